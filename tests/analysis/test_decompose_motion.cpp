// decompose_motion (Dynamic Element Textures, section 5, Figures 6-7): the split into coarse
// and detail motion gives the input back, keeps rigid and uniform motions whole in the coarse
// animation up to the first and last frames and the threads' ends (the symmetric shrink of
// the windows), separates a thread's fine wiggle from its slow sway, does not depend on the
// thread count, and refuses bad options naming them.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/low_pass.hpp"
#include "analysis/motion_fixtures.hpp"
#include "tessera/animation_io.hpp"
#include "tessera/error.hpp"
#include "tessera/motion_analysis.hpp"

namespace motion_test {
namespace {

using tessera::ElementTopology;

Animation swirl() {
    return tessera::load_animation(std::string(TESSERA_SOURCE_DIR) +
                                   "/examples/dynamic/swirl_particles_2d.json");
}

// Threads along x, `samples` samples 0.25 apart, moved by `motion`.
Animation threads(int count, int samples, int frames, const Motion& motion) {
    return animation_of("hair", ElementTopology::thread, 0, count, samples, frames, motion,
                        tessera::Domain::box({-2, -4, 0}, {14, 12, 0}, 2));
}

// Particles, threads and a sheet in one animation, each moving its own way.
Animation mixed() {
    Animation dots = animation_of(
        "dot", ElementTopology::none, 0, 30, 1, 9,
        [](int e, int, int f) {
            return Vec3{0.5 + (e * 7 % 30) * 0.33, 0.4 + (e * 11 % 30) * 0.25, 0} +
                   Vec3{0.1 * std::sin(0.7 * f + e), 0.05 * f, 0};
        },
        tessera::Domain::box({-2, -4, 0}, {14, 12, 0}, 2));
    Animation hair = threads(3, 9, 9, [](int e, int k, int f) {
        return Vec3{0.25 * k, 2.0 * e + 0.3 * std::sin(0.5 * f + k), 0};
    });
    Animation cloth = animation_of(
        "cloth", ElementTopology::sheet, 4, 1, 12, 9,
        [](int, int k, int f) {
            return Vec3{5 + k % 4 + 0.05 * f, 6 + k / 4 + 0.1 * std::cos(f + k), 0};
        },
        tessera::Domain::box({-2, -4, 0}, {14, 12, 0}, 2));
    return merged(merged(dots, hair), cloth);
}

TEST(DecomposeMotion, CoarsePlusDetailIsTheInput) {
    for (const Animation& input : {swirl(), mixed()}) {
        const tessera::MotionSplit split = tessera::decompose_motion(input);
        ASSERT_EQ(split.coarse.times, input.times);
        ASSERT_EQ(split.detail.times, input.times);
        ASSERT_EQ(split.coarse.sample_count(), input.sample_count());
        ASSERT_EQ(split.detail.structure.elements.size(), input.structure.elements.size());
        const Animation back = tessera::recombine_motion(split.coarse, split.detail);
        EXPECT_LT(max_difference(back.positions, input.positions), 1e-9);
        // Something was filtered: the details are not all zero.
        EXPECT_GT(max_norm(split.detail.positions), 1e-3);
    }
}

TEST(DecomposeMotion, ARigidlyTranslatingLatticeIsAllCoarseUpToTheBoundaryAndTheEnds) {
    // Edge particles lie half a spacing from the box: without the symmetric shrink of the
    // disk they would average neighbours on one side only, and without the temporal shrink
    // the first and last frames would average frames on one side only.
    const Animation input = translating_lattice(10, 8, 9, {0.011, 0.007, 0});
    tessera::LowPassOptions options;
    options.spatial_radius = 2.3;
    const tessera::MotionSplit split = tessera::decompose_motion(input, options);
    EXPECT_LT(max_norm(split.detail.positions), 1e-9);
    EXPECT_LT(max_difference(split.coarse.positions, input.positions), 1e-9);
}

TEST(DecomposeMotion, AStraightThreadAndAFlatSheetTranslatingAreAllCoarseToTheirEnds) {
    const Animation hair = threads(2, 15, 7, [](int e, int k, int f) {
        return Vec3{0.25 * k + 0.03 * f, 1.5 * e + 0.1 * k - 0.02 * f, 0};
    });
    const Animation cloth = animation_of(
        "cloth", ElementTopology::sheet, 5, 1, 20, 7,
        [](int, int k, int f) {
            return Vec3{k % 5 + 0.2 * (k / 5) + 0.04 * f, 0.7 * (k / 5) + 0.01 * f, 0};
        },
        tessera::Domain::box({-2, -4, 0}, {14, 12, 0}, 2));
    for (const Animation& input : {hair, cloth}) {
        const tessera::MotionSplit split = tessera::decompose_motion(input);
        EXPECT_LT(max_norm(split.detail.positions), 1e-9);
    }
}

TEST(DecomposeMotion, AThreadsFineWiggleIsDetailAndItsSlowSwayCoarse) {
    // 41 samples 0.25 apart; the slow sway bends the thread (quadratic along it) with a period
    // of 48 frames and drifts it along x; the wiggle alternates +-0.05 from sample to sample.
    const int n = 41, frames = 24;
    const double a = 0.05;
    auto slow = [&](int k, int f) {
        const double u = static_cast<double>(k) / (n - 1);
        return Vec3{0.25 * k + 0.02 * f, 0.6 * u * u * std::sin(2 * std::numbers::pi * f / 48.0), 0};
    };
    const Animation input = threads(1, n, frames, [&](int, int k, int f) {
        return slow(k, f) + Vec3{0, k % 2 ? -a : a, 0};
    });
    const tessera::MotionSplit split = tessera::decompose_motion(input);
    // Interior samples (a whole window along the thread): the wiggle measured in the details
    // and what of the slow motion the coarse animation misses.
    double wiggle = 0.0, missed = 0.0, leaked = 0.0;
    int count = 0;
    for (int f = 0; f < frames; ++f)
        for (int k = 3; k < n - 3; ++k) {
            const double sign = k % 2 ? -1.0 : 1.0;
            wiggle += sign * split.detail.at(f, k).y;
            missed = std::max(missed, tessera::norm(split.coarse.at(f, k) - slow(k, f)));
            leaked = std::max(leaked, std::abs(split.detail.at(f, k).x));
            ++count;
        }
    wiggle /= count;
    // Measured: a wiggle of 0.0507 in the details (the kernel lets 1.3% of an alternating
    // wiggle through to the coarse animation, with the opposite sign, so the details hold a
    // little more than it), a slow motion missed by at most 0.0038 (0.6% of the sway's 0.6:
    // the temporal kernel rounds the sine's peak and the one along the thread its bend), no
    // x motion in the details (2.7e-15).
    EXPECT_NEAR(wiggle, a, 0.002);
    EXPECT_LT(missed, 0.006);
    EXPECT_LT(leaked, 1e-9);
    // The coarse animation keeps the sway: its tip (whose window has shrunk to itself, so it
    // keeps its wiggle too) moves by the sway's amplitude, 0.595 of 0.6 measured.
    EXPECT_NEAR(split.coarse.at(12, n - 1).y - split.coarse.at(0, n - 1).y, slow(n - 1, 12).y, 0.01);
}

TEST(DecomposeMotion, AParticleCrossingTheDiskEdgeMovesTheAverageContinuously) {
    // A centre with four neighbours at distance 1 and a fifth that crosses the disk's edge
    // (radius 2) between the two frames by 2e-6: the centre's coarse position may move by
    // about that much, not jump (a Gaussian cut at the edge moved it by 0.077).
    const Vec3 centre{5, 5, 0};
    const Animation input = animation_of(
        "dot", ElementTopology::none, 0, 6, 1, 2,
        [&](int e, int, int f) {
            const Vec3 ring[] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
            if (e == 0) return centre;
            if (e <= 4) return centre + ring[e - 1];
            return centre + Vec3{0.6, 2.0 - 1e-6 + 2e-6 * f, 0};
        },
        tessera::Domain::box({0, 0, 0}, {10, 10, 0}, 2));
    tessera::LowPassOptions options;
    options.spatial_radius = std::hypot(0.6, 2.0);  // the fifth neighbour at the edge, mid-way
    options.temporal_radius = 0;
    const tessera::MotionSplit split = tessera::decompose_motion(input, options);
    EXPECT_LT(tessera::norm(split.coarse.at(1, 0) - split.coarse.at(0, 0)), 1e-5);
}

TEST(DecomposeMotion, TheAutomaticRadiusIsTwiceTheMeanNearestNeighbourDistance) {
    const Animation lattice = translating_lattice(6, 5, 2, {0.1, 0, 0});
    EXPECT_NEAR(tessera::analysis::automatic_particle_radius(
                    lattice, tessera::analysis::element_layouts(lattice.structure)),
                2.0, 1e-12);
}

TEST(DecomposeMotion, TheResultIsTheSameBitsForAnyThreadCount) {
    for (const Animation& input : {swirl(), mixed()}) {
        tessera::LowPassOptions options;
        options.threads = 1;
        const tessera::MotionSplit one = tessera::decompose_motion(input, options);
        for (int threads : {2, 3, 0}) {
            options.threads = threads;
            const tessera::MotionSplit many = tessera::decompose_motion(input, options);
            EXPECT_TRUE(many.coarse.positions == one.coarse.positions) << threads;
            EXPECT_TRUE(many.detail.positions == one.detail.positions) << threads;
        }
    }
}

std::string option_error(const tessera::LowPassOptions& options) {
    try {
        tessera::decompose_motion(swirl(), options);
    } catch (const tessera::Error& e) {
        EXPECT_EQ(e.kind(), tessera::ErrorKind::option);
        return e.what();
    }
    return "no error";
}

TEST(DecomposeMotion, BadOptionsAreErrorsNamingTheOption) {
    tessera::LowPassOptions o;
    o.spatial_radius = -1;
    EXPECT_EQ(option_error(o), "spatial_radius must be a number >= 0, got -1");
    o = {};
    o.temporal_radius = -1;
    EXPECT_EQ(option_error(o).rfind("temporal_radius must be an integer from 0", 0), 0u) << option_error(o);
    o = {};
    o.topology_radius = -2;
    EXPECT_EQ(option_error(o).rfind("topology_radius must be an integer from 0", 0), 0u) << option_error(o);
    o = {};
    o.threads = -1;
    EXPECT_EQ(option_error(o), "threads must be an integer >= 0, got -1");
}

}  // namespace
}  // namespace motion_test
