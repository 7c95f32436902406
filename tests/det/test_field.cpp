// Synthesis in a local orientation field (Eq. 7) and the field's frames.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tessera/tessera.hpp"

using namespace tessera;

namespace {

Exemplar example(const std::string& name) { return load(std::string(TESSERA_SOURCE_DIR) + "/examples/" + name); }

// Angle in degrees between the x axis of an element's orientation and the field there,
// as undirected lines (a stick has no head).
double angle_to_field(const Element& e, const OrientationField& field) {
    const Vec3 axis = e.orientation.rotate({1, 0, 0});
    const Vec3 d = field.direction(e.position);
    const double c = std::abs(dot(axis, d)) / (norm(axis) * norm(d));
    return std::acos(std::min(1.0, c)) * 180.0 / M_PI;
}

}  // namespace

TEST(DetField, SticksFollowAVortex) {
    const Exemplar ex = example("sticks_2d.json");
    DetOptions o;
    o.field = OrientationField::vortex({15, 15, 0});
    const Arrangement out = synthesize_det(ex, Domain::box({0, 0, 0}, {30, 30, 0}, 2), o);
    // A stick's direction (first to last sample) against a reference direction, in degrees.
    auto stick_angle = [](const Exemplar& d, const Element& e, const Vec3& reference) {
        const Vec3 s = d.samples[e.first_sample + e.sample_count - 1].p - d.samples[e.first_sample].p;
        return std::acos(std::min(1.0, std::abs(dot(s, reference)) / (norm(s) * norm(reference)))) * 180.0 / M_PI;
    };
    // The exemplar's sticks deviate from its +x axis by some angle on average; in the
    // output they must deviate from the field by about as much, not more.
    double exemplar_spread = 0.0;
    for (const auto& e : ex.elements) exemplar_spread += stick_angle(ex, e, {1, 0, 0});
    exemplar_spread /= ex.elements.size();
    double along = 0.0;
    int counted = 0;
    for (const auto& e : out.elements) {
        if (norm(e.position - Vec3{15, 15, 0}) < 2.0) continue;  // the field turns fast at its centre
        along += stick_angle(out, e, o.field.direction(e.position));
        ++counted;
    }
    ASSERT_GT(counted, 300);
    EXPECT_LT(along / counted, exemplar_spread + 4.0) << "exemplar spread " << exemplar_spread;
    EXPECT_LT(along / counted, 15.0);
}

TEST(DetField, AConstantFieldTurnsThePattern) {
    const Exemplar ex = example("sticks_2d.json");
    DetOptions o;
    o.field = OrientationField::constant({0, 1, 0});
    const Arrangement out = synthesize_det(ex, ex.domain.scaled(2.0), o);
    // Mostly horizontal sticks become mostly vertical.
    double vertical = 0.0;
    for (const auto& e : out.elements) {
        const Vec3 s = out.samples[e.first_sample + 4].p - out.samples[e.first_sample].p;
        vertical += std::abs(s.y) / norm(s);
    }
    EXPECT_GT(vertical / out.elements.size(), 0.9);
}

// The criterion: element orientations within 10 degrees of a vortex field on average.
TEST(DetField, SingleSampleOrientationsFollowTheField) {
    Exemplar ex = example("poisson_disk_2d.json");
    for (auto& e : ex.elements) e.orientation = Quat::from_angle_z(0.0);
    DetOptions o;
    o.field = OrientationField::vortex({15, 15, 0});
    o.iterations = 3;
    const Arrangement out = synthesize_det(ex, ex.domain.scaled(3.0), o);
    double sum = 0.0;
    for (const auto& e : out.elements) sum += angle_to_field(e, o.field);
    EXPECT_LT(sum / out.elements.size(), 5.0);
}

TEST(OrientationFieldTest, FramesAndParsing) {
    const Quat q = frame_from_direction({0, 0, 1}, 3);  // x onto +z: still a proper rotation
    EXPECT_NEAR(norm(q.rotate({1, 0, 0}) - Vec3{0, 0, 1}), 0.0, 1e-12);
    const Quat r = frame_from_direction({1, 1, 0}, 3);
    EXPECT_NEAR(norm(r.rotate({0, 0, 1}) - Vec3{0, 0, 1}), 0.0, 1e-12) << "least twist keeps z up";
    const OrientationField v = OrientationField::parse("vortex:1,2", 2, "--field");
    EXPECT_NEAR(norm(v.direction({2, 2, 0}) - Vec3{0, 1, 0}), 0.0, 1e-12);
    EXPECT_EQ(v.direction({1, 2, 0}), Vec3{});  // degenerate at the centre
    EXPECT_EQ(v.frame({1, 2, 0}, 2), Quat{});
    EXPECT_THROW(OrientationField::parse("constant:0,0", 2, "--field"), Error);
    EXPECT_THROW(OrientationField::parse("spiral:0,0", 2, "--field"), Error);
    EXPECT_THROW(OrientationField::parse("vortex:1", 2, "--field"), Error);
    try {
        OrientationField::parse("vortex:a,b", 2, "--field");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("--field"), std::string::npos);
    }
}

TEST(OrientationFieldTest, PolylineAndTrefoilFollowTheirCurve) {
    const OrientationField f = OrientationField::parse("polyline:0,0,10,0,10,10", 2, "--field");
    EXPECT_NEAR(norm(f.direction({3, 1, 0}) - Vec3{1, 0, 0}), 0.0, 1e-12);
    EXPECT_NEAR(norm(f.direction({11, 7, 0}) - Vec3{0, 1, 0}), 0.0, 1e-12);
    EXPECT_THROW(OrientationField::parse("polyline:0,0,0,0", 2, "--field"), Error);
    EXPECT_THROW(OrientationField::parse("polyline:0,0,1", 2, "--field"), Error);
    // On the trefoil, the direction is the curve's tangent (derivative of the parametrisation).
    const OrientationField knot = OrientationField::trefoil({0, 0, 0}, 1.0, 3600);
    const double t = 0.7;
    const Vec3 p{std::sin(t) + 2 * std::sin(2 * t), std::cos(t) - 2 * std::cos(2 * t), -std::sin(3 * t)};
    Vec3 d{std::cos(t) + 4 * std::cos(2 * t), -std::sin(t) + 4 * std::sin(2 * t), -3 * std::cos(3 * t)};
    d = d / norm(d);
    EXPECT_GT(std::abs(dot(knot.direction(p), d)), 0.999);
    EXPECT_THROW(OrientationField::parse("trefoil:0,0,0", 3, "--field"), Error);
}
