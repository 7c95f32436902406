// Frame-by-frame dynamic synthesis: the motion and arrangement of an exemplar with a known
// steady motion are kept frame by frame; causality; determinism; smoothness; bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/rng.hpp"
#include "dynamic/dynamic_fixtures.hpp"
#include "dynamic/motion_checks.hpp"
#include "tessera/dynamic.hpp"
#include "tessera/error.hpp"
#include "tessera/metrics.hpp"

namespace {

using namespace tessera;
using dynamic_test::closest_pair;
using dynamic_test::drifting_lattice;
using dynamic_test::motion_stats;
using dynamic_test::MotionStats;

// Mean |p(f+1) - 2 p(f) + p(f-1)|: the temporal jitter a viewer sees.
double mean_acceleration(const Animation& a) {
    double sum = 0.0;
    int n = 0;
    for (int f = 1; f + 1 < a.frame_count(); ++f)
        for (int s = 0; s < a.sample_count(); ++s, ++n) sum += norm(a.at(f + 1, s) - a.at(f, s) * 2.0 + a.at(f - 1, s));
    return sum / n;
}

const Domain output_box = Domain::box({0, 0, 0}, {20, 17, 0}, 2);

TEST(Dynamic, SteadyMotionKeepsVelocityAndArrangementFrameByFrame) {
    const Animation ex = drifting_lattice(12, 12, 24, {0.05, 0.02, 0}, 0.06);
    DynamicOptions o;
    o.frames = 16;
    o.threads = 2;
    const AnimatedArrangement out = synthesize_dynamic(ex, output_box, o);
    ASSERT_EQ(out.frame_count(), 16);
    const MotionStats in = motion_stats(ex, 0, ex.frame_count());
    const MotionStats got = motion_stats(out, 1, out.frame_count());
    EXPECT_NEAR(got.mean.x, in.mean.x, 0.1 * norm(in.mean));
    EXPECT_NEAR(got.mean.y, in.mean.y, 0.1 * norm(in.mean));
    EXPECT_NEAR(got.speed_sd, in.speed_sd, 0.35 * in.speed_sd);
    dynamic_test::expect_lattice_kept(ex, out, {4, 9, 15}, output_box);
}

TEST(Dynamic, ThreeDimensionalParticlesKeepTheirMotionAndSpacing) {
    // A jittered cubic lattice (spacing 1) drifting at (0.05, 0, 0.02) per frame.
    const Exemplar ex = dynamic_test::jittered_cubic_lattice(5, 0.1);
    Animation a = animation_from_exemplar(ex);
    a.times = {};
    a.positions = {};
    for (int f = 0; f < 8; ++f) {
        std::vector<Vec3> p;
        for (const Sample& s : ex.samples) p.push_back(s.p + Vec3{0.05, 0, 0.02} * f);
        a.add_frame(0.1 * f, p);
    }
    DynamicOptions o;
    o.frames = 6;
    const Domain box = Domain::box({-0.5, -0.5, -0.5}, {7.5, 7.5, 7.5}, 3);
    const AnimatedArrangement out = synthesize_dynamic(a, box, o);
    const MotionStats got = motion_stats(out, 1, out.frame_count());
    EXPECT_NEAR(got.mean.x, 0.05, 0.005);
    EXPECT_NEAR(got.mean.z, 0.02, 0.005);
    for (int f : {1, 5}) EXPECT_GT(closest_pair(out.frame(f)), 0.6 * closest_pair(ex)) << "frame " << f;
}

TEST(Dynamic, CausalNeighbourhoodsNeverReadFutureFrames) {
    // Frames 0..5 of a 6-frame run and of a 10-frame run are the same bits: nothing in frame
    // f depends on what comes after it.
    const Animation ex = drifting_lattice(10, 10, 12, {0.04, 0, 0}, 0.05);
    DynamicOptions o;
    o.threads = 1;
    o.frames = 6;
    const AnimatedArrangement short_run = synthesize_dynamic(ex, output_box, o);
    o.frames = 10;
    const AnimatedArrangement long_run = synthesize_dynamic(ex, output_box, o);
    ASSERT_EQ(long_run.frame_count(), 10);
    ASSERT_TRUE(std::equal(short_run.positions.begin(), short_run.positions.end(), long_run.positions.begin()));
}

TEST(Dynamic, SameBitsForEveryThreadCount) {
    const Animation ex = drifting_lattice(10, 10, 12, {0.04, 0.01, 0}, 0.05);
    for (NeighbourhoodShape shape : {NeighbourhoodShape::compact, NeighbourhoodShape::full}) {
        DynamicOptions o;
        o.frames = 6;
        o.shape = shape;
        o.threads = 1;
        const AnimatedArrangement one = synthesize_dynamic(ex, output_box, o);
        o.threads = 2;
        const AnimatedArrangement two = synthesize_dynamic(ex, output_box, o);
        o.threads = 3;
        const AnimatedArrangement three = synthesize_dynamic(ex, output_box, o);
        EXPECT_TRUE(one.positions == two.positions);
        EXPECT_TRUE(one.positions == three.positions);
    }
}

TEST(Dynamic, SmoothSynthesisJittersLessThanTheBasicAlgorithm) {
    // A small exemplar samples the space of neighbourhoods sparsely: the basic algorithm
    // jumps between matches, the blend of two matches with a falloff moves smoothly.
    const Animation ex = drifting_lattice(7, 7, 16, {0.03, 0.03, 0}, 0.08);
    DynamicOptions basic;
    basic.frames = 14;
    basic.matches = 1;
    DynamicOptions smooth = basic;
    smooth.matches = 2;
    smooth.sigma_p = 1.0;
    const double jitter_basic = mean_acceleration(synthesize_dynamic(ex, output_box, basic));
    const double jitter_smooth = mean_acceleration(synthesize_dynamic(ex, output_box, smooth));
    EXPECT_LT(jitter_smooth, jitter_basic);
}

TEST(Dynamic, FlowWithWrapKeepsTheDomainFilledWithoutOverlaps) {
    const Animation ex = drifting_lattice(10, 10, 12, {0, 0, 0}, 0.05);
    DynamicOptions o;
    o.frames = 30;
    o.flow = {2.0, 0, 0};  // 0.2 per frame: the whole box is crossed in 100 frames
    o.wrap = true;
    const AnimatedArrangement out = synthesize_dynamic(ex, output_box, o);
    const double closest_in = closest_pair(ex.frame(2));
    for (int f : {5, 15, 29}) {
        const Exemplar frame = out.frame(f);
        int left_half = 0;
        for (const Sample& s : frame.samples) {
            EXPECT_TRUE(output_box.inside(s.p));
            left_half += s.p.x < 10.0;
        }
        EXPECT_NEAR(left_half, 0.5 * frame.samples.size(), 0.1 * frame.samples.size()) << "frame " << f;
        // Elements that re-enter across the border meet the others without landing on them:
        // neighbourhoods see through the periodic border.
        EXPECT_GT(closest_pair(frame), 0.6 * closest_in) << "frame " << f;
    }
}

TEST(Dynamic, ATurningFlowTurnsTheWholeMotion) {
    const Animation ex = drifting_lattice(10, 10, 12, {0, 0, 0}, 0.05);
    DynamicOptions o;
    o.frames = 24;
    o.flow = {2.0, 0, 0};
    o.flow_turn = 90.0;  // degrees per unit of time; frames are 0.1 apart
    o.wrap = true;
    const AnimatedArrangement out = synthesize_dynamic(ex, output_box, o);
    const Vec3 size = output_box.bounds().size();
    for (int f : {3, 12, 23}) {
        Vec3 mean;
        for (int s = 0; s < out.sample_count(); ++s) {
            Vec3 d = out.at(f, s) - out.at(f - 1, s);
            for (int k = 0; k < 2; ++k) d[k] -= size[k] * std::round(d[k] / size[k]);  // across the wrap
            mean += d / out.sample_count();
        }
        const double expected = 90.0 * (f - 0.5) * 0.1;
        double angle = std::atan2(mean.y, mean.x) * 180.0 / std::numbers::pi;
        angle -= 360.0 * std::round((angle - expected) / 360.0);
        EXPECT_NEAR(angle, expected, 12.0) << "frame " << f;
        EXPECT_NEAR(norm(mean), 0.2, 0.05) << "frame " << f;
    }
}

TEST(Dynamic, RejectsBadInput) {
    Animation ex = drifting_lattice(6, 6, 4, {0.05, 0, 0}, 0.0);
    DynamicOptions o;
    o.temporal_size = 5;  // more than the exemplar's 4 frames
    EXPECT_THROW(synthesize_dynamic(ex, output_box, o), Error);
    o.temporal_size = 3;
    o.matches = 0;
    try {
        synthesize_dynamic(ex, output_box, o);
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::option);
        EXPECT_NE(std::string(e.what()).find("matches"), std::string::npos) << e.what();
    }
    EXPECT_THROW(synthesize_dynamic(ex, Domain::box({0, 0, 0}, {5, 5, 5}, 3), DynamicOptions{}), Error);
    Animation bad = ex;
    bad.times[2] = bad.times[1];  // time stamps must strictly increase
    EXPECT_THROW(synthesize_dynamic(bad, output_box, DynamicOptions{}), Error);
}

}  // namespace
