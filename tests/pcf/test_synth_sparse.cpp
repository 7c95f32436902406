// Classes with one or a few elements (PcfSparseClass): analysed and synthesized by the
// fallback, with its density, its distances to the other classes, and a note.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "pcf/synth_test_data.hpp"
#include "tessera/error.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera {
namespace {

// A forest of 120 pines (hard-core 6) in a 100 x 100 box and `rare` aspens, each 4 to 5
// from a pine and at least 12 from every other aspen.
Exemplar forest(int rare) {
    Exemplar ex = test::poisson_disk(120, 100.0, 6.0, 11);
    ex.types[0].name = "pine";
    const int aspen = ex.type_index("aspen");
    const Vec3 spots[] = {{30, 40, 0}, {70, 60, 0}, {50, 15, 0}};
    for (int k = 0; k < rare; ++k) {
        // The pine nearest a spot, and a point 4.5 from it away from the others.
        const Element* near = &ex.elements[0];
        for (const Element& e : ex.elements)
            if (norm(e.position - spots[k]) < norm(near->position - spots[k])) near = &e;
        for (int a = 0; a < 64; ++a) {
            const double t = 2.0 * 3.14159265358979 * a / 64;
            const Vec3 p = near->position + Vec3{4.5 * std::cos(t), 4.5 * std::sin(t), 0};
            double closest = 1e9;
            for (const Element& e : ex.elements) closest = std::min(closest, norm(e.position - p));
            if (closest >= 4.0) {
                ex.add_element(aspen, {p}, 0.0);
                break;
            }
        }
    }
    return ex;
}

double closest_between(const Exemplar& out, int a, int b) {
    double d = 1e18;
    for (const Element& e : out.elements)
        for (const Element& f : out.elements)
            if (&e != &f && e.type == a && f.type == b) d = std::min(d, norm(e.position - f.position));
    return d;
}

void expect_fallback(int rare) {
    const Exemplar ex = forest(rare);
    ASSERT_EQ(static_cast<int>(ex.elements.size()), 120 + rare) << "the test forest";
    const PcfModel model = analyze_distribution(ex);
    ASSERT_EQ(model.sparse.size(), 1u);
    EXPECT_EQ(model.sparse[0].cls, 1);
    EXPECT_GT(model.sparse[0].tether[0], 0.0);  // aspens depend on pines (the default chain)
    EXPECT_EQ(pcf_model_to_json(pcf_model_from_json(pcf_model_to_json(model), "model")), pcf_model_to_json(model));

    PcfSynthOptions o;
    o.threads = 2;
    const Domain domain = ex.domain.scaled(2.0);  // 4x the area
    const Arrangement out = synthesize_pcf(ex, domain, o);
    int aspens = 0;
    for (const Element& e : out.elements) aspens += e.type == 1;
    EXPECT_EQ(aspens, 4 * rare);
    // Its own spacing, and no closer to a pine than the exemplar's aspens are.
    if (4 * rare > 1) {
        EXPECT_GE(closest_between(out, 1, 1), model.sparse[0].spacing * (1 - 1e-9));
    }
    EXPECT_GE(closest_between(out, 1, 0), 0.99 * closest_between(ex, 1, 0));
    // Each aspen has a pine within the tether (plus the crowding repair's pushes).
    for (const Element& e : out.elements) {
        if (e.type != 1) continue;
        double nearest = 1e18;
        for (const Element& f : out.elements)
            if (f.type == 0) nearest = std::min(nearest, norm(f.position - e.position));
        EXPECT_LE(nearest / model.r_max, model.sparse[0].tether[0] + 0.1);
    }
    const bool noted = std::any_of(out.stats.notes.begin(), out.stats.notes.end(), [](const std::string& n) {
        return n.find("class 'aspen'") != std::string::npos && n.find("too few for PCFs") != std::string::npos;
    });
    EXPECT_TRUE(noted);
}

TEST(PcfSparse, OneElementClassIsPlacedByTheFallback) { expect_fallback(1); }
TEST(PcfSparse, ThreeElementClassIsPlacedByTheFallback) { expect_fallback(3); }

TEST(PcfSparse, ClassWithoutElementsIsAnError) {
    Exemplar ex = forest(0);
    ex.type_index("aspen");
    try {
        analyze_distribution(ex);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("'aspen' has no elements"), std::string::npos) << e.what();
    }
}

TEST(PcfSparse, SameBytesForAnyThreadCount) {
    const Exemplar ex = forest(1);
    PcfSynthOptions one, two;
    one.threads = 1;
    two.threads = 2;
    const Domain domain = ex.domain.scaled(2.0);
    const Arrangement a = synthesize_pcf(ex, domain, one), b = synthesize_pcf(ex, domain, two);
    ASSERT_EQ(a.elements.size(), b.elements.size());
    for (size_t k = 0; k < a.elements.size(); ++k) EXPECT_EQ(a.elements[k].position, b.elements[k].position);
}

}  // namespace
}  // namespace tessera
