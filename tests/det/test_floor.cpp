// Constrained selection at the floor (section 5): floor elements keep their elevation.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "core/rng.hpp"
#include "det/floor.hpp"
#include "tessera/tessera.hpp"

using namespace tessera;

namespace {

// A 2D stack: rows of disks resting on the floor y = 0, jittered, in a 12 x 5 box.
Exemplar disk_stack() {
    Exemplar ex;
    ex.dimension = 2;
    ex.domain = Domain::box({0, 0, 0}, {12, 5, 0}, 2);
    const int t = ex.type_index("plum");
    const core::KeyedRng rng(31, core::Purpose::test);
    std::uint64_t c = 0;
    for (int row = 0; row < 5; ++row)
        for (int i = 0; i < 12; ++i) {
            const double x = 0.5 + i + 0.5 * (row % 2) + 0.08 * (rng.uniform(c++) - 0.5);
            const double y = 0.5 + row * 0.87 + (row == 0 ? 0.0 : 0.08 * (rng.uniform(c++) - 0.5));
            if (x < 12.0) ex.add_element(t, {{x, y, 0}}, 0.5);
        }
    return ex;
}

}  // namespace

TEST(DetFloor, FloorElementsKeepTheirElevation) {
    // The exemplar's floor row has its centres at one height (no jitter): the initialization
    // copies it at that height, and the iterations keep every floor element where it was.
    const Exemplar ex = disk_stack();
    const Domain out_domain = Domain::box({0, 0, 0}, {36, 5, 0}, 2);
    DetOptions o;
    o.floor_distance = 0.6;  // the bottom row (centres at 0.5) rests on the floor
    const det::Gravity down = det::resolve_gravity({0, -1, 0}, 2);
    DetSession session(ex, o);
    session.initialize(out_domain);
    const Arrangement start = session.arrangement();
    const auto floor = det::floor_elements(start, out_domain, down, o.floor_distance);
    std::map<std::uint64_t, double> level;  // element id -> height, ids are kept by the session
    for (size_t e = 0; e < start.elements.size(); ++e) {
        if (!floor[e]) continue;
        level[start.elements[e].id] = start.elements[e].position.y;
        EXPECT_NEAR(start.elements[e].position.y, 0.5, 1e-9) << "copied off the floor's height";
    }
    session.iterate(8);
    session.finish();
    int floor_count = 0;
    for (const Element& e : session.arrangement().elements) {
        const auto it = level.find(e.id);
        if (it == level.end()) continue;
        ++floor_count;
        EXPECT_NEAR(e.position.y, it->second, 1e-9) << "element " << e.id;
    }
    EXPECT_GT(floor_count, 25);  // the 36-wide floor row, or most of it
    // Without the constraint the bottom row is free to move.
    o.floor_distance = 0.0;
    o.iterations = 8;
    const Arrangement free_run = synthesize_det(ex, out_domain, o);
    double moved = 0.0;
    for (const Element& e : free_run.elements)
        if (e.position.y < 0.8) moved = std::max(moved, std::abs(e.position.y - 0.5));
    EXPECT_GT(moved, 1e-6);
}

TEST(DetFloor, GravityMustFollowAnAxis) {
    EXPECT_THROW(det::resolve_gravity({1, -1, 0}, 2), Error);
    EXPECT_THROW(det::resolve_gravity({0, 0, -1}, 2), Error);
    const det::Gravity g = det::resolve_gravity({0, 0, -9.8}, 3);
    EXPECT_EQ(g.axis, 2);
    EXPECT_EQ(g.sign, -1.0);
}

// Constrained selection at a chosen wall (DetOptions::boundary_sides): a hedge of elements
// along the exemplar's left wall (x = 0.3), a gap, then a jittered grid. With the -x side
// chosen, the output's left wall is lined with hedge elements along its whole height, and
// the interior keeps the gap; without it, interior elements end up against the wall too.
namespace {
Exemplar hedge_exemplar() {
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    ex.type_index("dot");
    const core::KeyedRng rng(5, core::Purpose::test);
    for (int k = 0; k < 10; ++k) ex.add_element(0, {{0.3, 0.5 + k, 0}}, 0.2);
    for (int i = 0; i < 9; ++i)
        for (int k = 0; k < 10; ++k) {
            const std::uint64_t c = 2 * static_cast<std::uint64_t>(i * 10 + k);
            ex.add_element(0, {{1.5 + i + 0.1 * (rng.uniform(c) - 0.5), 0.5 + k + 0.1 * (rng.uniform(c + 1) - 0.5), 0}}, 0.2);
        }
    return ex;
}
}  // namespace

TEST(DetBoundary, AChosenWallIsLinedWithTheExemplarsWallElements) {
    const Exemplar ex = hedge_exemplar();
    const Domain out_domain = Domain::box({0, 0, 0}, {20, 20, 0}, 2);
    DetOptions o;
    o.iterations = 5;
    o.boundary_sides = {{0, -1}};
    o.boundary_distance = 0.5;
    const Arrangement out = synthesize_det(ex, out_domain, o);
    int on_wall = 0, too_close = 0;
    for (const auto& e : out.elements) {
        if (e.position.x < 0.6) {
            ++on_wall;
            EXPECT_NEAR(e.position.x, 0.3, 0.15);
        } else if (e.position.x < 1.1 && e.position.y > 0.5 && e.position.y < 19.5) {
            ++too_close;  // inside the exemplar's gap next to the hedge
        }
    }
    EXPECT_NEAR(on_wall, 20, 2);
    EXPECT_LE(too_close, 1);
    // Bad sides are option errors.
    o.boundary_sides = {{2, -1}};
    EXPECT_THROW(synthesize_det(ex, out_domain, o), Error);
}
