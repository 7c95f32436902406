// The flow round the domain's obstacles (src/dynamic/obstacle_flow.hpp): uniform without
// holes, tangent to a hole's wall, faster beside it, divergence-free round it, and in
// synthesis the wake behind an obstacle filled again, frame by frame and all frames together.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "dynamic/obstacle_demo.hpp"
#include "dynamic/obstacle_flow.hpp"
#include "tessera/animation_io.hpp"
#include "tessera/dynamic.hpp"
#include "tessera/io.hpp"

namespace {

using tessera::Domain;
using tessera::Vec3;
using tessera::dynamic::ObstacleFlow;

using dynamic_test::hole_r;
using dynamic_test::hole_x;
using dynamic_test::hole_y;

// The 30 x 15 channel with a round obstacle of radius 2.5 the demo uses.
Domain channel() {
    std::vector<Vec3> outer{{0, 0, 0}, {30, 0, 0}, {30, 14.6, 0}, {0, 14.6, 0}}, hole;
    for (int k = 0; k < 48; ++k) {
        const double a = 2 * std::numbers::pi * k / 48;
        hole.push_back({hole_x + hole_r * std::cos(a), hole_y + hole_r * std::sin(a), 0});
    }
    return Domain::polygon(outer, {hole});
}

TEST(ObstacleFlow, AFlowWithoutObstaclesIsUniform) {
    const ObstacleFlow flow(Domain::polygon({{0, 0, 0}, {8, 0, 0}, {4, 6, 0}}), 1);
    EXPECT_TRUE(flow.uniform());
    const Vec3 step{0.3, -0.1, 0};
    const Vec3 d = flow.displacement({4, 2, 0}, step);
    EXPECT_EQ(d.x, step.x);
    EXPECT_EQ(d.y, step.y);
}

TEST(ObstacleFlow, TheFlowRunsAlongTheObstacleAndFasterBesideIt) {
    const ObstacleFlow flow(channel(), 2);
    ASSERT_FALSE(flow.uniform());
    const Vec3 step{0.1, 0, 0};
    // Just outside the wall, all round: the flow is tangent to it (the normal part small).
    for (int k = 0; k < 16; ++k) {
        const double a = 2 * std::numbers::pi * (k + 0.5) / 16;
        const Vec3 n{std::cos(a), std::sin(a), 0};
        const Vec3 p = Vec3{hole_x, hole_y, 0} + n * (hole_r + 0.35);
        const Vec3 d = flow.displacement(p, step);
        EXPECT_LT(std::abs(tessera::dot(d, n)), 0.35 * step.x) << "angle " << a;
    }
    // Beside it (above and below) the flow speeds up; far upstream it is the far flow.
    EXPECT_GT(flow.displacement({hole_x, hole_y + hole_r + 0.4, 0}, step).x, 1.3 * step.x);
    EXPECT_GT(flow.displacement({hole_x, hole_y - hole_r - 0.4, 0}, step).x, 1.3 * step.x);
    const Vec3 far = flow.displacement({1.0, 2.0, 0}, step);
    EXPECT_NEAR(far.x, step.x, 0.1 * step.x);
    EXPECT_NEAR(far.y, 0.0, 0.1 * step.x);
}

// The flow is divergence-free: what enters a box round the obstacle leaves it (particles are
// neither made nor lost on the way round). Through the channel's outer boundary the flow may
// enter and leave (phi = U.x there), so sections of the channel need not carry equal flux.
TEST(ObstacleFlow, WhatFlowsIntoABoxRoundTheObstacleFlowsOut) {
    const ObstacleFlow flow(channel(), 2);
    const Vec3 step{0.1, 0, 0};
    const double x0 = hole_x - 5, x1 = hole_x + 5, y0 = hole_y - 5, y1 = hole_y + 5;
    const int n = 400;
    double inflow = 0.0, net = 0.0;  // outward flux through the box's four sides
    for (int i = 0; i < n; ++i) {
        const double y = y0 + (y1 - y0) * (i + 0.5) / n, x = x0 + (x1 - x0) * (i + 0.5) / n;
        const double dy = (y1 - y0) / n, dx = (x1 - x0) / n;
        const double left = -flow.displacement({x0, y, 0}, step).x * dy;
        const double right = flow.displacement({x1, y, 0}, step).x * dy;
        const double bottom = -flow.displacement({x, y0, 0}, step).y * dx;
        const double top = flow.displacement({x, y1, 0}, step).y * dx;
        for (double side : {left, right, bottom, top}) {
            net += side;
            if (side < 0) inflow -= side;
        }
    }
    EXPECT_GT(inflow, 0.9 * (y1 - y0) * step.x);
    EXPECT_NEAR(net, 0.0, 0.03 * inflow) << "inflow " << inflow;
}

// The demo's run: swirl particles carried past the obstacle. Particles that only slid along
// the wall left an empty wake behind it; the flow round the obstacle closes it.
TEST(ObstacleFlow, ParticlesCarriedPastAnObstacleFillItsWake) {
    const auto [exemplar, domain, options] = dynamic_test::obstacle_demo(48);
    const tessera::AnimatedArrangement out = tessera::synthesize_dynamic(exemplar, domain, options);
    const int last = out.frame_count() - 1;
    // Density in the wake (a hole-sized box just behind the obstacle) against the whole domain's.
    int wake = 0;
    for (int s = 0; s < out.sample_count(); ++s) {
        const Vec3 p = out.at(last, s);
        ASSERT_TRUE(domain.inside(p)) << "sample " << s;
        if (p.x > hole_x + hole_r && p.x < hole_x + 3 * hole_r && std::abs(p.y - hole_y) < hole_r) ++wake;
    }
    const double wake_area = 2 * hole_r * 2 * hole_r;
    const double density = out.sample_count() / domain.measure();
    EXPECT_GT(wake / wake_area, 0.6 * density) << wake << " samples in the wake";
}

// Sequencing all: each particle's trail is compared less its drift along its own path, the
// flow's displacement round the obstacle (AllFrames::carry). With the drift taken uniform the
// particles were only kept out of the obstacle: they piled up on its front (7 within 0.35 of
// its rim at frame 0, 11 at frame 31) and its wake emptied (0.78 of the domain's density).
TEST(ObstacleFlow, AllFramesSequencingAlsoFlowsRoundTheObstacle) {
    auto [exemplar, domain, options] = dynamic_test::obstacle_demo(32);
    options.sequencing = tessera::Sequencing::all;
    options.iterations = 3;
    const tessera::AnimatedArrangement out = tessera::synthesize_dynamic(exemplar, domain, options);
    const double density = out.sample_count() / domain.measure(), wake_area = 4 * hole_r * hole_r;
    const auto rim_count = [&](int f) {
        int n = 0;
        for (int s = 0; s < out.sample_count(); ++s)
            n += std::abs(std::hypot(out.at(f, s).x - hole_x, out.at(f, s).y - hole_y) - hole_r) < 0.35;
        return n;
    };
    double wake = 0.0, rim = 0.0;
    const int from = out.frame_count() / 2;
    for (int f = from; f < out.frame_count(); ++f) {
        for (int s = 0; s < out.sample_count(); ++s) {
            const Vec3 p = out.at(f, s);
            ASSERT_TRUE(domain.inside(p)) << "sample " << s << " frame " << f;
            wake += p.x > hole_x + hole_r && p.x < hole_x + 3 * hole_r && std::abs(p.y - hole_y) < hole_r;
        }
        rim += rim_count(f);
    }
    const int frames = out.frame_count() - from;
    EXPECT_GT(wake / frames / wake_area, 0.85 * density) << "mean wake count " << wake / frames;
    EXPECT_LE(rim / frames, 1.25 * rim_count(0)) << "mean count on the rim " << rim / frames;
}

}  // namespace
