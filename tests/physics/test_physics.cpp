// The interleaved physics solver (section 5 of Discrete Element Textures, Figure 15):
// interpenetration and floating measures, and the Bullet steps that reduce them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/rng.hpp"
#include "tessera/error.hpp"
#include "tessera/physics.hpp"

using namespace tessera;

namespace {

// `count` spheres of radius 0.5 at random in [0, w] x [0, w] x [0, h], inside a box
// domain [0, w] x [0, w] x [0, top]: a dense pile in which many spheres overlap.
Arrangement pile(int count, double w, double h, double top, std::uint64_t seed = 7) {
    const core::KeyedRng rng(seed, core::Purpose::test);
    Arrangement a;
    a.dimension = 3;
    a.domain = Domain::box({0, 0, 0}, {w, w, top}, 3);
    a.type_index("ball");
    for (int i = 0; i < count; ++i) {
        const std::uint64_t c = 3 * static_cast<std::uint64_t>(i);
        const Vec3 p{0.5 + (w - 1) * rng.uniform(c), 0.5 + (w - 1) * rng.uniform(c + 1),
                     0.5 + (h - 1) * rng.uniform(c + 2)};
        a.add_element(0, {p}, 0.5);
    }
    return a;
}

}  // namespace

TEST(PhysicsMeasure, CountsAConstructedOverlapWithItsDepth) {
    Arrangement a;
    a.dimension = 3;
    a.domain = Domain::box({0, 0, 0}, {10, 10, 10}, 3);
    a.type_index("ball");
    a.add_element(0, {{5, 5, 0.5}}, 0.5);     // on the floor
    a.add_element(0, {{5.7, 5, 0.5}}, 0.5);   // overlaps the first by 0.3
    a.add_element(0, {{2, 2, 5}}, 0.5);       // in the air: floating
    a.add_element(0, {{8, 8, 1.05}}, 0.25);   // on nothing either (gap 0.8)
    a.add_element(0, {{5.35, 5, 1.35}}, 0.5); // rests on the first two (gaps < 0)
    const PhysicsReport r = measure_physics(a, a.domain, {});
    // Pairs: (0,1) depth 0.3; (0,4) and (1,4) at distance sqrt(0.35^2 + 0.85^2) = 0.919 -> depth 0.081.
    EXPECT_EQ(r.interpenetrating_pairs, 3);
    EXPECT_NEAR(r.max_depth, 0.3, 1e-12);
    EXPECT_EQ(r.floating, 2);
    EXPECT_EQ(r.lost, 0);
    EXPECT_EQ(r.elements, 5);
    // A looser tolerance (20% of the smaller radius) ignores the shallow pairs.
    EXPECT_EQ(measure_physics(a, a.domain, {}, 0.2).interpenetrating_pairs, 1);
}

TEST(PhysicsMeasure, CapsuleChainsOverlapAlongTheirAxes) {
    Arrangement a;
    a.dimension = 3;
    a.domain = Domain::box({0, 0, 0}, {10, 10, 10}, 3);
    a.type_index("stick");
    a.add_element(0, {{2, 5, 0.2}, {5, 5, 0.2}, {8, 5, 0.2}}, 0.2);  // lying on the floor along x
    a.add_element(0, {{5, 2, 0.5}, {5, 5, 0.5}, {5, 8, 0.5}}, 0.2);  // crossing it along y, 0.3 above
    const PhysicsReport r = measure_physics(a, a.domain, {});
    EXPECT_EQ(r.interpenetrating_pairs, 1);
    EXPECT_NEAR(r.max_depth, 0.1, 1e-12);
    EXPECT_EQ(r.floating, 0);  // the upper stick rests on the lower one
}

TEST(PhysicsStep, DensePileHalvesInterpenetrationAndLosesNothing) {
    Arrangement a = pile(300, 7, 6, 12);
    const PhysicsReport before = measure_physics(a, a.domain, {});
    PhysicsOptions o;
    o.substeps = 5;
    const PhysicsReport after = step_physics(a, a.domain, o);
    RecordProperty("pairs_before", before.interpenetrating_pairs);
    RecordProperty("pairs_after", after.interpenetrating_pairs);
    std::printf("dense pile: pairs %d -> %d, max depth %.3f -> %.3f, floating %d -> %d\n",
                before.interpenetrating_pairs, after.interpenetrating_pairs, before.max_depth, after.max_depth,
                before.floating, after.floating);
    EXPECT_GT(before.interpenetrating_pairs, 100);
    EXPECT_LE(2 * after.interpenetrating_pairs, before.interpenetrating_pairs);
    EXPECT_LT(after.max_depth, before.max_depth);
    EXPECT_EQ(after.lost, 0);
    ASSERT_EQ(a.elements.size(), 300u);
    ASSERT_EQ(a.samples.size(), 300u);
    for (const Element& e : a.elements) {
        EXPECT_TRUE(a.domain.inside(e.position)) << e.position.x << " " << e.position.y << " " << e.position.z;
        EXPECT_EQ(e.position, a.samples[e.first_sample].p);
    }
}

TEST(PhysicsStep, SpheresInTheAirFallAndLand) {
    Arrangement a;
    a.dimension = 3;
    a.domain = Domain::box({0, 0, 0}, {10, 10, 10}, 3);
    a.type_index("ball");
    for (int i = 0; i < 4; ++i) a.add_element(0, {{2.0 + 2 * i, 5, 2.0 + i}}, 0.5);
    const PhysicsReport before = measure_physics(a, a.domain, {});
    EXPECT_EQ(before.floating, 4);
    PhysicsOptions o;
    o.substeps = 5;
    Arrangement b = a;
    step_physics(b, b.domain, o);
    for (std::size_t i = 0; i < a.elements.size(); ++i)
        EXPECT_LT(b.elements[i].position.z, a.elements[i].position.z);
    o.substeps = 120;  // 2 s: the highest falls 3.5 in about 0.85 s
    const PhysicsReport after = step_physics(b, b.domain, o);
    EXPECT_EQ(after.floating, 0);
    for (const Element& e : b.elements) EXPECT_NEAR(e.position.z, 0.5, 0.05);
}

TEST(PhysicsStep, TwoDimensionalDataStayInThePlane) {
    Arrangement a;
    a.dimension = 2;
    a.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    a.type_index("ball");
    a.type_index("stick");
    const core::KeyedRng rng(11, core::Purpose::test);
    for (int i = 0; i < 40; ++i) {
        const Vec3 p{1 + 8 * rng.uniform(2 * i), 1 + 4 * rng.uniform(2 * i + 1), 0};
        if (i % 2) a.add_element(0, {p}, 0.5);
        else a.add_element(1, {p, p + Vec3{0.6, 0.3, 0}, p + Vec3{1.2, 0.6, 0}}, 0.2);
    }
    a.update_positions();
    PhysicsOptions o;
    o.substeps = 30;
    const Arrangement start = a;
    step_physics(a, a.domain, o);
    double moved = 0;
    for (std::size_t i = 0; i < a.samples.size(); ++i) {
        EXPECT_EQ(a.samples[i].p.z, 0.0);
        moved += norm(a.samples[i].p - start.samples[i].p);
    }
    EXPECT_GT(moved, 1.0);
    for (const Element& e : a.elements) {
        EXPECT_EQ(e.position.z, 0.0);
        EXPECT_EQ(e.orientation.x, 0.0);
        EXPECT_EQ(e.orientation.y, 0.0);
        EXPECT_NEAR(e.orientation.w * e.orientation.w + e.orientation.z * e.orientation.z, 1.0, 1e-12);
    }
    // Rigid motion: distances between a stick's samples are kept.
    for (const Element& e : a.elements) {
        if (e.sample_count < 3) continue;
        const Vec3 p0 = a.samples[e.first_sample].p, p2 = a.samples[e.first_sample + 2].p;
        EXPECT_NEAR(norm(p2 - p0), norm(Vec3{1.2, 0.6, 0}), 1e-9);
    }
}

TEST(PhysicsStep, IsDeterministic) {
    Arrangement a = pile(120, 5, 3, 8, 21), b = a;
    PhysicsOptions o;
    o.substeps = 10;
    const PhysicsReport ra = step_physics(a, a.domain, o);
    const PhysicsReport rb = step_physics(b, b.domain, o);
    EXPECT_EQ(ra.interpenetrating_pairs, rb.interpenetrating_pairs);
    for (std::size_t i = 0; i < a.samples.size(); ++i) EXPECT_EQ(a.samples[i].p, b.samples[i].p);
    for (std::size_t i = 0; i < a.elements.size(); ++i) EXPECT_EQ(a.elements[i].orientation, b.elements[i].orientation);
}

TEST(PhysicsStep, LockedElementsDoNotMoveAndZeroStepsChangeNothing) {
    Arrangement a = pile(60, 4, 3, 8, 5);
    a.elements[0].locked = true;
    const Arrangement start = a;
    PhysicsOptions o;
    o.substeps = 0;
    step_physics(a, a.domain, o);
    for (std::size_t i = 0; i < a.samples.size(); ++i) EXPECT_EQ(a.samples[i].p, start.samples[i].p);
    o.substeps = 10;
    step_physics(a, a.domain, o);
    EXPECT_EQ(a.samples[0].p, start.samples[0].p);
}

TEST(PhysicsStep, RejectsBadOptions) {
    Arrangement a = pile(5, 4, 3, 8);
    PhysicsOptions o;
    o.time_step = 0;
    EXPECT_THROW(step_physics(a, a.domain, o), Error);
    o = {};
    o.substeps = -1;
    EXPECT_THROW(step_physics(a, a.domain, o), Error);
    o = {};
    o.units_per_metre = 0;
    EXPECT_THROW(step_physics(a, a.domain, o), Error);
    EXPECT_THROW(measure_physics(a, a.domain, {}, -1), Error);
}

TEST(PhysicsStep, MeshDomainsCollideWithTheirSurface) {
    // A closed cube [0, 4]^3 read from an OBJ file: its triangles are the static collider.
    const auto path = std::filesystem::temp_directory_path() / "tessera_physics_cube.obj";
    {
        std::ofstream f(path);
        f << "v 0 0 0\nv 4 0 0\nv 4 4 0\nv 0 4 0\nv 0 0 4\nv 4 0 4\nv 4 4 4\nv 0 4 4\n"
             "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\n"
             "f 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";
    }
    const Domain cube = Domain::mesh(path.string(), 32);
    Arrangement a = pile(40, 4, 3, 4, 9);
    a.domain = cube;
    PhysicsOptions o;
    o.substeps = 60;
    const PhysicsReport r = step_physics(a, cube, o);
    EXPECT_EQ(r.lost, 0);
    for (const Element& e : a.elements) {
        EXPECT_GT(e.position.z, 0.4);
        EXPECT_TRUE(cube.inside(e.position));
    }
    // Without the file, the bounding box is the collider: nothing is lost either.
    std::filesystem::remove(path);
    const PhysicsReport again = step_physics(a, cube, o);
    EXPECT_EQ(again.lost, 0);
    for (const Element& e : a.elements) EXPECT_TRUE(cube.inside(e.position));
}

TEST(PhysicsStep, PolygonEdgesAreWallsSoNothingFallsIntoAHole) {
    // A 10 x 10 square with a square hole [4, 6] x [2, 4]; a disk dropped above the hole
    // comes to rest on the hole's upper edge (y = 4), not on the bounding box's floor.
    const Domain domain = Domain::polygon({{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}},
                                          {{{4, 2, 0}, {4, 4, 0}, {6, 4, 0}, {6, 2, 0}}});
    Arrangement a;
    a.dimension = 2;
    a.domain = domain;
    a.type_index("disk");
    a.add_element(0, {{5, 5, 0}}, 0.4);
    a.add_element(0, {{8, 5, 0}}, 0.4);  // beside the hole: falls to the floor
    PhysicsOptions o;
    o.substeps = 120;
    const PhysicsReport r = step_physics(a, domain, o);
    EXPECT_NEAR(a.samples[0].p.y, 4.4, 0.05);
    EXPECT_NEAR(a.samples[1].p.y, 0.4, 0.05);
    EXPECT_EQ(r.lost, 0);
    EXPECT_EQ(r.floating, 0);
}
