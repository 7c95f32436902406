// `tessera synth STILL --method dynamic`: a static exemplar gets its motion from graph
// synthesis (--graph-frames, automatic for one frame) and is then synthesized frame by frame;
// --graph-frames 0 keeps the old refusal, a bad value names the flag. `tessera animate` does
// the graph synthesis alone.
#include <gtest/gtest.h>

#include "cli/cli_fixture.hpp"
#include "tessera/animation_io.hpp"

namespace tessera_cli_test {
namespace {

class GraphMotionCli : public CliFixture {
protected:
    std::string still() const { return example("poisson_disk_2d.json"); }
};

TEST_F(GraphMotionCli, MethodDynamicOnAStillEnrichesItAndWritesMovingFrames) {
    const Result r = run("synth '" + still() + "' --method dynamic -o '" + path("out.json") +
                         "' --frames 6 --scale 1.5 --threads 2");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("x 1 frames"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("motion by graph synthesis: 24 frames"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("synth: note: graph synthesis gave the still 24 frames"), std::string::npos) << r.err;
    const tessera::Animation out = tessera::load_animation(path("out.json"));
    ASSERT_EQ(out.frame_count(), 6);
    EXPECT_GT(out.structure.elements.size(), 200u);  // 110 in the still, 2.25x the area
    double moved = 0.0;
    for (int s = 0; s < out.sample_count(); ++s) moved += tessera::norm(out.at(5, s) - out.at(0, s));
    EXPECT_GT(moved / out.sample_count(), 0.02);
    // --graph-frames sets the enriched length.
    const Result longer = run("synth '" + still() + "' --method dynamic -o '" + path("longer.json") +
                              "' --frames 3 --graph-frames 12");
    ASSERT_EQ(longer.code, 0) << longer.err;
    EXPECT_NE(longer.err.find("motion by graph synthesis: 12 frames"), std::string::npos) << longer.err;
}

TEST_F(GraphMotionCli, WithoutMethodDynamicAStillStaysStatic) {
    const Result r = run("synth '" + still() + "' -o '" + path("out.json") + "' --iterations 1 -q");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_FALSE(tessera::has_frames(path("out.json")));
}

TEST_F(GraphMotionCli, BadGraphFramesNameTheFlagAndWriteNothing) {
    Result r = run("synth '" + still() + "' --method dynamic -o '" + path("out.json") + "' --graph-frames 1");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err.rfind("tessera: error: --graph-frames must be -1 (automatic), 0 (off) or an integer >= 2, got 1", 0),
              0u)
        << r.err;
    r = run("synth '" + still() + "' --method dynamic -o '" + path("out.json") + "' --graph-frames -2");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--graph-frames must be"), std::string::npos) << r.err;
    // Off: a still has no window of 3 frames, as before graph synthesis.
    r = run("synth '" + still() + "' --method dynamic -o '" + path("out.json") + "' --graph-frames 0");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err.rfind("tessera: error: --temporal-size must be at most the exemplar's frame count (1), got 3", 0), 0u)
        << r.err;
    EXPECT_TRUE(work_files().empty());
}

// `tessera animate`: graph synthesis alone, for particles and for threads.
TEST_F(GraphMotionCli, AnimateWritesTheStillWithMotion) {
    Result r = run("animate '" + example("noodles_2d.json") + "' -o '" + path("noodles.json") + "' --frames 8");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("animate: 70 elements x 8 frames"), std::string::npos) << r.err;
    const tessera::Animation out = tessera::load_animation(path("noodles.json"));
    ASSERT_EQ(out.frame_count(), 8);
    double moved = 0.0;
    for (int s = 0; s < out.sample_count(); ++s) moved += tessera::norm(out.at(7, s) - out.at(0, s));
    EXPECT_GT(moved / out.sample_count(), 0.02);
    // A clip is continued: its 32 frames first.
    r = run("animate '" + example("dynamic/swirl_particles_2d.json") + "' -o '" + path("swirl.json") + "' --frames 36 -q");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(tessera::load_animation(path("swirl.json")).frame_count(), 36);
    r = run("animate '" + still() + "' -o '" + path("dots.png") + "' --frames 4 -q");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;
}

TEST_F(GraphMotionCli, AnimateNamesABadFlagAndWritesNothing) {
    Result r = run("animate '" + still() + "' -o '" + path("out.json") + "' --frames 1");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err.rfind("tessera: error: --frames", 0), 0u) << r.err;
    r = run("animate '" + still() + "' -o '" + path("out.txt") + "'");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("-o"), std::string::npos) << r.err;
    EXPECT_TRUE(work_files().empty());
}

}  // namespace
}  // namespace tessera_cli_test
