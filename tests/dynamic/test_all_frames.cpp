// All-frame synthesis of particles (sequencing all): every frame keeps the exemplar's motion
// and arrangement, neighbourhoods see the frames after a sample's as well as before, the
// optimisation lowers the energy of the patch copy, the domain holds in every frame, the
// output may outlast the exemplar, same bits for every thread count, bad options refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "dynamic/all_frames.hpp"
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

const Domain output_box = Domain::box({0, 0, 0}, {20, 17, 0}, 2);

DynamicOptions all_frames(int frames) {
    DynamicOptions o;
    o.sequencing = Sequencing::all;
    o.frames = frames;
    o.iterations = 3;
    o.threads = 2;
    return o;
}

TEST(AllFrames, SteadyMotionKeepsVelocityAndArrangementInEveryFrame) {
    const Animation ex = drifting_lattice(12, 12, 24, {0.05, 0.02, 0}, 0.06);
    const AnimatedArrangement out = synthesize_dynamic(ex, output_box, all_frames(16));
    ASSERT_EQ(out.frame_count(), 16);
    ASSERT_EQ(out.positions.size(), size_t(16) * out.sample_count());
    std::set<std::uint64_t> ids;  // every element its own id, as frames of a file need them
    for (const Element& e : out.structure.elements) ids.insert(e.id);
    EXPECT_EQ(ids.size(), out.structure.elements.size());
    const MotionStats in = motion_stats(ex, 0, ex.frame_count());
    const MotionStats got = motion_stats(out, 1, out.frame_count());
    // The same elements in every frame: no element ever steps half a spacing (onto a
    // neighbour's place) between two frames.
    EXPECT_LT(got.largest_step, 0.5);
    EXPECT_NEAR(got.mean.x, in.mean.x, 0.1 * norm(in.mean));
    EXPECT_NEAR(got.mean.y, in.mean.y, 0.1 * norm(in.mean));
    EXPECT_NEAR(got.speed_sd, in.speed_sd, 0.35 * in.speed_sd);
    dynamic_test::expect_lattice_kept(ex, out, {0, 4, 9, 15}, output_box);
}

TEST(AllFrames, OutputLongerThanTheExemplarContinuesTheMotion) {
    // 10 exemplar frames, 30 output frames: trajectories are chained past the exemplar's end.
    const Animation ex = drifting_lattice(10, 10, 10, {0.04, 0.0, 0}, 0.05);
    DynamicOptions o = all_frames(30);
    o.flow = {1.0, 0, 0};  // 0.1 per frame on top of the exemplar's 0.04
    o.wrap = true;
    const AnimatedArrangement out = synthesize_dynamic(ex, output_box, o);
    ASSERT_EQ(out.frame_count(), 30);
    const Vec3 size = output_box.bounds().size();
    for (int from : {1, 12, 22}) {
        Vec3 mean;
        int n = 0;
        for (int f = from; f < from + 7; ++f)
            for (int s = 0; s < out.sample_count(); ++s, ++n) {
                Vec3 d = out.at(f, s) - out.at(f - 1, s);
                for (int k = 0; k < 2; ++k) d[k] -= size[k] * std::round(d[k] / size[k]);  // across the wrap
                mean += d;
            }
        mean = mean / n;
        EXPECT_NEAR(mean.x, 0.14, 0.02) << "frames from " << from;
        EXPECT_NEAR(mean.y, 0.0, 0.02) << "frames from " << from;
        EXPECT_GT(closest_pair(out.frame(from + 6)), 0.6 * closest_pair(ex.frame(2))) << "frame " << from + 6;
    }
}

TEST(AllFrames, NonCausalNeighbourhoodSeesTheNextFrame) {
    dynamic::StParams p;
    p.ahead = 1;
    p.temporal = 3;
    p.radius = 1.5;
    dynamic::AllFrames frames(3, {0, 0}, 1, p, {});
    const Vec3 a[3] = {{0, 0, 0}, {0.1, 0, 0}, {0.3, 0.1, 0}};
    for (int f = 0; f < 3; ++f) frames.at(f, 0) = a[f], frames.at(f, 1) = a[f] + Vec3{1, 0, 0};
    const Vec3 drift[3] = {{0, 0, 0}, {0.05, 0, 0}, {0.1, 0, 0}};  // the flow's share is not detail motion
    for (int f = 0; f < 3; ++f) frames.drift(f, 0) = drift[f], frames.drift(f, 1) = drift[f];
    frames.index_frames(1);
    dynamic::StNeighbourhood nb;
    frames.gather(0, 1, nb);
    bool saw_next = false, saw_previous = false;
    for (int k = 1; k < nb.groups; ++k)
        for (int e = nb.start[k]; e < nb.start[k + 1]; ++e) {
            const int dt = dynamic::time_offset(k, p);
            const Vec3 want = a[1 + dt] - a[1] - (drift[1 + dt] - drift[1]);
            EXPECT_LT(norm(nb.entries[e].offset - want), 1e-12) << "offset " << dt;
            saw_next |= dt == 1;
            saw_previous |= dt == -1;
        }
    EXPECT_TRUE(saw_next);
    EXPECT_TRUE(saw_previous);
    ASSERT_EQ(nb.start[1] - nb.start[0], 1);  // the other sample, at the same frame
    EXPECT_EQ(nb.entries[nb.start[0]].sample, 1);
    // At the last frame there is no frame after: that group is empty.
    frames.gather(0, 2, nb);
    for (int k = 1; k < nb.groups; ++k) {
        if (dynamic::time_offset(k, p) != 1) continue;
        EXPECT_EQ(nb.start[k + 1] - nb.start[k], 0);
    }
}

TEST(AllFrames, OptimisationLowersTheEnergyOfThePatchCopy) {
    const Animation ex = drifting_lattice(9, 9, 12, {0.03, 0.03, 0}, 0.08);
    const AnimatedArrangement out = synthesize_dynamic(ex, output_box, all_frames(12));
    ASSERT_GE(out.stats.energy.size(), 2u);
    EXPECT_LT(out.stats.energy.back(), 0.9 * out.stats.energy.front());
}

TEST(AllFrames, ElementsStayInAPolygonWithAHoleInEveryFrame) {
    std::vector<Vec3> outer{{0, 0, 0}, {20, 0, 0}, {20, 14, 0}, {0, 14, 0}}, hole;
    for (int i = 0; i < 24; ++i) {
        const double a = 2 * std::numbers::pi * i / 24;
        hole.push_back({8 + 3 * std::cos(a), 7 + 3 * std::sin(a), 0});
    }
    const Domain domain = Domain::polygon(outer, {hole});
    const Animation ex = drifting_lattice(10, 10, 12, {0.05, 0, 0}, 0.05);
    DynamicOptions o = all_frames(20);
    o.flow = {1.5, 0, 0};
    o.wrap = true;
    const AnimatedArrangement out = synthesize_dynamic(ex, domain, o);
    int outside = 0;
    for (const Vec3& p : out.positions) outside += !domain.inside(p);
    EXPECT_EQ(outside, 0);
    EXPECT_GT(out.sample_count(), 150);
}

TEST(AllFrames, SameBitsForEveryThreadCount) {
    const Animation ex = drifting_lattice(10, 10, 12, {0.04, 0.01, 0}, 0.05);
    DynamicOptions o = all_frames(8);
    o.threads = 1;
    const AnimatedArrangement one = synthesize_dynamic(ex, output_box, o);
    o.threads = 2;
    const AnimatedArrangement two = synthesize_dynamic(ex, output_box, o);
    EXPECT_TRUE(one.positions == two.positions);
    EXPECT_EQ(one.stats.energy, two.stats.energy);
}

TEST(AllFrames, RejectsOptionsItCannotHonour) {
    const Animation ex = drifting_lattice(6, 6, 4, {0.05, 0, 0}, 0.0);
    DynamicOptions o = all_frames(6);
    o.shape = NeighbourhoodShape::full;
    try {
        synthesize_dynamic(ex, output_box, o);
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::option);
        EXPECT_NE(std::string(e.what()).find("shape"), std::string::npos) << e.what();
    }
    o.shape = NeighbourhoodShape::compact;
    o.temporal_size = 6;  // 7 frames around each sample, the exemplar has 4
    try {
        synthesize_dynamic(ex, output_box, o);
        FAIL();
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::option);
        EXPECT_NE(std::string(e.what()).find("temporal_size"), std::string::npos) << e.what();
    }
}

}  // namespace
