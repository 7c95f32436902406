// The physics sub-step of frame-by-frame synthesis (src/dynamic/collision_step.hpp, the
// paper's Figure 5): particles closer than the exemplar's closest pair are pushed apart,
// particles already apart are left exactly where they are, pairs across the wrap seam
// collide too, in the demo's channel the particles carried past the obstacle collide less
// often than without it, and all-frame sequencing with the step has no colliding pair.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "dynamic/collision_step.hpp"
#include "dynamic/obstacle_demo.hpp"
#include "tessera/animation_io.hpp"
#include "tessera/dynamic.hpp"
#include "tessera/error.hpp"
#include "tessera/io.hpp"

namespace {

using tessera::Domain;
using tessera::Vec3;
using tessera::dynamic::CollisionStep;

// Four particles on a 1 x 1 square, at rest: its closest pair is 1 apart.
tessera::Animation square_exemplar() {
    tessera::Exemplar e;
    e.dimension = 2;
    e.types.emplace_back().name = "dot";
    for (int i = 0; i < 4; ++i) {
        e.elements.push_back({});
        e.elements.back().first_sample = i;
        e.elements.back().position = {double(i % 2), double(i / 2), 0};
        e.samples.push_back({e.elements.back().position, i, 0, 0.0});
    }
    e.domain = Domain::box({0, 0, 0}, {1, 1, 0}, 2);
    tessera::Animation a = tessera::animation_from_exemplar(e);
    const std::vector<Vec3> first = a.positions;
    a.add_frame(1.0, first);
    return a;
}

TEST(CollisionStep, TheRadiusIsHalfTheExemplarsClosestPair) {
    const Domain domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    EXPECT_DOUBLE_EQ(CollisionStep(square_exemplar(), domain, false).radius(), 0.5);
}

TEST(CollisionStep, PushesApartCollidingParticlesAndLeavesTheOthers) {
    const Domain domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    CollisionStep step(square_exemplar(), domain, false);
    std::vector<Vec3> p{{4.8, 5.0, 0}, {5.2, 5.0, 0}, {1.0, 1.0, 0}, {8.0, 8.0, 0}};
    const std::vector<Vec3> before = p;
    EXPECT_EQ(step.apply(p), 2);
    EXPECT_GT(tessera::norm(p[1] - p[0]), 0.7) << "0.4 apart before, collision distance 1";
    EXPECT_LT(std::abs(p[0].y - 5.0), 1e-6);  // pushed along the line joining them
    EXPECT_EQ(p[2], before[2]);                 // apart: not touched at all
    EXPECT_EQ(p[3], before[3]);
}

TEST(CollisionStep, WithWrapAPairAcrossTheSeamCollides) {
    const Domain domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    CollisionStep step(square_exemplar(), domain, true);
    std::vector<Vec3> p{{0.1, 5.0, 0}, {9.8, 5.0, 0}};  // 0.3 apart through the seam
    EXPECT_GE(step.apply(p), 1);
    const double apart = 10.0 - (p[1].x - p[0].x);
    EXPECT_GT(apart, 0.95) << "collision distance 1";
    EXPECT_LT(apart, 1.1) << "pushed apart once, not from both sides";
    EXPECT_NEAR(p[0].y, 5.0, 1e-6);
}

// Pairs closer than `distance` in frame f.
int close_pairs(const tessera::Animation& a, int f, double distance) {
    int pairs = 0;
    for (int i = 0; i < a.sample_count(); ++i)
        for (int j = i + 1; j < a.sample_count(); ++j)
            if (tessera::norm(a.at(f, i) - a.at(f, j)) < distance) ++pairs;
    return pairs;
}

// Figure 5: the swirl particles carried past the round obstacle, with and without the step.
TEST(CollisionStep, FewerCollisionsPastAnObstacleWithThePhysicsSubStep) {
    auto [exemplar, domain, options] = dynamic_test::obstacle_demo(32);
    const double collision = 2.0 * tessera::dynamic::exemplar_collision_radius(exemplar, CollisionStep::closest_quantile);
    const auto collisions = [&](bool physics) {
        options.physics = physics;
        const tessera::AnimatedArrangement out = tessera::synthesize_dynamic(exemplar, domain, options);
        int pairs = 0;
        for (int f = 1; f < out.frame_count(); ++f) {
            pairs += close_pairs(out, f, 0.99 * collision);  // touching is no collision
            for (int s = 0; s < out.sample_count(); ++s) EXPECT_TRUE(domain.inside(out.at(f, s)));
        }
        return pairs;
    };
    const int pure = collisions(false), hybrid = collisions(true);
    std::printf("past the obstacle, frames 1-31: %d colliding pairs without the physics sub-step, %d with it\n", pure,
                hybrid);
    EXPECT_LT(hybrid, 0.7 * pure) << pure << " colliding pairs without the step, " << hybrid << " with it";
}

// Mean |acceleration| over the frames, through the wrap (`period` the box's size).
double mean_acceleration(const tessera::Animation& a, const Vec3& period) {
    const auto step = [&](int f, int s) {
        Vec3 d = a.at(f + 1, s) - a.at(f, s);
        d.x -= period.x * std::round(d.x / period.x), d.y -= period.y * std::round(d.y / period.y);
        return d;
    };
    double sum = 0.0;
    int n = 0;
    for (int f = 0; f + 2 < a.frame_count(); ++f)
        for (int s = 0; s < a.sample_count(); ++s, ++n) sum += tessera::norm(step(f + 1, s) - step(f, s));
    return n > 0 ? sum / n : 0.0;
}

// All frames together: the step follows each round's assignment on every frame; the seams
// between copied trajectories crowd without it, and the next round smooths what it moved.
TEST(CollisionStep, AllFramesSequencingWithTheStepHasNoCollidingPairInAnyFrame) {
    const std::string root = std::string(TESSERA_SOURCE_DIR) + "/examples/dynamic/";
    const tessera::Animation exemplar = tessera::load_animation(root + "swirl_particles_2d.json");
    const Domain domain = Domain::box({0, 0, 0}, {20, 10, 0}, 2);
    const double collision = 2.0 * tessera::dynamic::exemplar_collision_radius(exemplar, CollisionStep::closest_quantile);
    tessera::DynamicOptions options;
    options.sequencing = tessera::Sequencing::all;
    options.frames = 16;
    options.iterations = 3;
    options.wrap = true;
    options.threads = 2;
    const auto run = [&](bool physics) {
        options.physics = physics;
        return tessera::synthesize_dynamic(exemplar, domain, options);
    };
    const tessera::AnimatedArrangement pure = run(false), hybrid = run(true);
    int pure_pairs = 0, hybrid_pairs = 0;
    for (int f = 0; f < hybrid.frame_count(); ++f) {
        pure_pairs += close_pairs(pure, f, 0.99 * collision);
        hybrid_pairs += close_pairs(hybrid, f, 0.99 * collision);
        for (int s = 0; s < hybrid.sample_count(); ++s) EXPECT_TRUE(domain.inside(hybrid.at(f, s)));
    }
    EXPECT_GT(pure_pairs, 0);
    EXPECT_EQ(hybrid_pairs, 0) << pure_pairs << " colliding pairs without the step";
    // The motion stays as smooth.
    const Vec3 period{20, 10, 0};
    EXPECT_LT(mean_acceleration(hybrid, period), 1.1 * mean_acceleration(pure, period));
    options.threads = 1;
    EXPECT_TRUE(run(true).positions == hybrid.positions);
}

}  // namespace
