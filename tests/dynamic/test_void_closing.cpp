// The void closing of frame-by-frame synthesis (src/dynamic/void_closing.hpp): a void wider
// than any the exemplar holds is closed from its rim, the exemplar's own voids are kept, and
// past an obstacle in a flow no void opens wider than the exemplar's over a long run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "dynamic/dynamic_fixtures.hpp"
#include "dynamic/obstacle_demo.hpp"
#include "dynamic/void_closing.hpp"
#include "tessera/animation_io.hpp"
#include "tessera/dynamic.hpp"
#include "tessera/io.hpp"

namespace {

using tessera::Domain;
using tessera::Vec3;
using tessera::dynamic::Periodic;
using tessera::dynamic::VoidClosing;

// The largest disk inside `domain` that holds none of `points`, by brute force over a lattice
// of probes `step` apart (written apart from the step's own grid search, to check it).
double largest_empty_radius(const std::vector<Vec3>& points, const Domain& domain, double step,
                            const Periodic& periodic = {}) {
    const tessera::Box& b = domain.bounds();
    double largest = 0.0;
    for (double y = b.lo.y + step / 2; y < b.hi.y; y += step)
        for (double x = b.lo.x + step / 2; x < b.hi.x; x += step) {
            const Vec3 p{x, y, 0};
            if (!domain.inside(p)) continue;
            // A box that wraps has no walls; the channel's walls are its obstacle's.
            using namespace dynamic_test;
            double empty = periodic.on ? std::hypot(x - hole_x, y - hole_y) - hole_r : domain.distance_to_boundary(p);
            if (empty <= largest) continue;
            for (const Vec3& q : points) {
                Vec3 d = q - p;
                if (periodic.on)
                    for (int k = 0; k < 2; ++k) d[k] -= periodic.extent[k] * std::round(d[k] / periodic.extent[k]);
                empty = std::min(empty, std::hypot(d.x, d.y));
                if (empty <= largest) break;
            }
            largest = std::max(largest, empty);
        }
    return largest;
}

// A hexagonal lattice of spacing 1 filling `domain`, less the points within `hole` of `centre`.
std::vector<Vec3> lattice_with_hole(const Domain& domain, const Vec3& centre, double hole) {
    std::vector<Vec3> out;
    const tessera::Box& b = domain.bounds();
    for (int j = 0; j * std::sqrt(3.0) / 2 < b.hi.y; ++j)
        for (int i = 0; i < b.hi.x; ++i) {
            const Vec3 p{0.25 + i + 0.5 * (j % 2), 0.25 + j * std::sqrt(3.0) / 2, 0};
            if (domain.inside(p) && std::hypot(p.x - centre.x, p.y - centre.y) > hole) out.push_back(p);
        }
    return out;
}

TEST(VoidClosing, AVoidWiderThanTheExemplarsIsClosedFromItsRim) {
    const tessera::Animation exemplar = dynamic_test::drifting_lattice(10, 10, 8, {}, 0.05);
    const Domain domain = Domain::box({0, 0, 0}, {24, 20, 0}, 2);
    const Vec3 centre{12, 10, 0};
    std::vector<Vec3> points = lattice_with_hole(domain, centre, 2.2);
    const std::vector<Vec3> before = points;
    VoidClosing voids(exemplar, domain, 1.0, {});
    EXPECT_GT(voids.exemplar_void(), 0.5);
    EXPECT_LT(voids.exemplar_void(), 0.8);  // a lattice's voids: a little over half a spacing
    const double hole_before = largest_empty_radius(points, domain, 0.05);
    EXPECT_GT(hole_before, 2.2);
    voids.apply(points);
    for (size_t s = 0; s < points.size(); ++s) EXPECT_LE(norm(points[s] - before[s]), 0.1 + 1e-12) << "sample " << s;
    for (int frame = 1; frame < 40; ++frame) voids.apply(points);
    const double hole_after = largest_empty_radius(points, domain, 0.05);
    // 2.29 -> 0.81 (the exemplar's widest 0.59): the rest of it would be a vacancy that the
    // lattice cannot close without crowding its ring, and the step leaves it.
    EXPECT_LT(hole_after, 1.5 * voids.exemplar_void()) << "from " << hole_before;
    // The samples far from the void stay where they were. (The rim crowds as it closes in,
    // which the assignment evens out in synthesis: the last test.)
    for (size_t s = 0; s < points.size(); ++s) {
        EXPECT_TRUE(domain.inside(points[s]));
        if (std::hypot(before[s].x - centre.x, before[s].y - centre.y) > 8.0) {
            EXPECT_EQ(points[s], before[s]) << "sample " << s;
        }
    }
}

TEST(VoidClosing, TheExemplarsOwnVoidsAreKept) {
    // Clumps of dots with wide gaps between them: voids the output should have too.
    tessera::Animation exemplar = dynamic_test::drifting_lattice(12, 12, 4, {}, 0.05);
    for (Vec3& p : exemplar.positions) p = Vec3{std::floor(p.x / 4) * 4 + 0.5 * std::fmod(p.x, 4.0), p.y, 0};
    const tessera::Box window = exemplar.structure.domain.bounds();
    // The window up to the last clump and the last row: bands wider than the exemplar's voids
    // along its sides would be voids by the rule of the walls.
    exemplar.structure.domain = Domain::box(window.lo, {10.5, window.hi.y - 0.87, 0}, 2);
    VoidClosing voids(exemplar, exemplar.structure.domain, 1.0, {});
    EXPECT_GT(voids.exemplar_void(), 0.9);
    for (int f = 0; f < exemplar.frame_count(); ++f) {
        std::vector<Vec3> frame(&exemplar.at(f, 0), &exemplar.at(f, 0) + exemplar.sample_count());
        EXPECT_EQ(voids.apply(frame), 0) << "frame " << f;
    }
}

// The demo's particles past the obstacle: the streamlines part at its front and a gap ran
// down the middle of its wake and round through the wrap; over 72 frames the largest empty
// circle grew from the exemplar's 0.92 to 1.6 (seed 1; 1.4-1.8 for seeds 1 to 3). With the
// step it stays under 1.08.
TEST(VoidClosing, NoVoidPastAnObstacleGrowsWiderThanTheExemplars) {
    auto [exemplar, domain, options] = dynamic_test::obstacle_demo(72);
    const Periodic periodic{true, domain.bounds().lo, domain.bounds().size()};
    const double exemplar_void = VoidClosing(exemplar, domain, 0.83, periodic).exemplar_void();
    // The widest void over frames 48-71, and the closest pair.
    const auto measure = [&](const tessera::AnimatedArrangement& out, double& closest) {
        double w = 0.0;
        closest = 1e9;
        for (int f = 48; f < out.frame_count(); f += 6) {
            const std::vector<Vec3> frame(&out.at(f, 0), &out.at(f, 0) + out.sample_count());
            w = std::max(w, largest_empty_radius(frame, domain, 0.1, periodic));
            for (size_t s = 0; s < frame.size(); ++s)
                for (size_t o = 0; o < s; ++o) closest = std::min(closest, norm(frame[s] - frame[o]));
        }
        return w;
    };
    double closest = 0.0;
    // Voids up to the exemplar's are left, and the step moves a rim only so fast: a little over.
    EXPECT_LT(measure(tessera::synthesize_dynamic(exemplar, domain, options), closest), 1.25 * exemplar_void);
    EXPECT_GT(closest, 0.5);  // the exemplar's closest pair: 0.65; 0.60 here, 0.61 without the step
    options.keep_voids = true;
    EXPECT_GT(measure(tessera::synthesize_dynamic(exemplar, domain, options), closest), 1.35 * exemplar_void);
}

}  // namespace
