// `tessera analyze --decompose` and `tessera recombine`: the two animations written and added
// back to the input, every output format of recombine, and errors that are one line, name the
// flag or the file and leave no file behind.
#include <gtest/gtest.h>

#include "analysis/motion_fixtures.hpp"
#include "cli/cli_fixture.hpp"
#include "tessera/animation_io.hpp"

namespace tessera_cli_test {
namespace {

class MotionCli : public CliFixture {
protected:
    std::string swirl() const { return example("dynamic/swirl_particles_2d.json"); }
    // Decomposes the swirl into coarse.json and detail.json.
    void decompose() const {
        const Result r = run("analyze " + q(swirl()) + " --decompose -o " + q(path("coarse.json")) +
                             " --detail " + q(path("detail.json")) + " --temporal-radius 3 --threads 2");
        ASSERT_EQ(r.code, 0) << r.err;
        EXPECT_NE(r.err.find("split into coarse motion and details"), std::string::npos) << r.err;
    }
};

TEST_F(MotionCli, DecomposeWritesCoarseAndDetailThatRecombineToTheInput) {
    decompose();
    const tessera::Animation input = tessera::load_animation(swirl());
    const tessera::Animation coarse = tessera::load_animation(path("coarse.json"));
    const tessera::Animation detail = tessera::load_animation(path("detail.json"));
    EXPECT_EQ(coarse.times, input.times);
    EXPECT_EQ(detail.frame_count(), input.frame_count());
    const Result r = run("recombine " + q(path("coarse.json")) + " " + q(path("detail.json")) + " -o " +
                         q(path("back.json")));
    ASSERT_EQ(r.code, 0) << r.err;
    const tessera::Animation back = tessera::load_animation(path("back.json"));
    EXPECT_LT(motion_test::max_difference(back.positions, input.positions), 1e-9);
    EXPECT_GT(motion_test::max_norm(detail.positions), 0.01);
}

TEST_F(MotionCli, RecombineWritesEveryAnimationFormat) {
    decompose();
    for (const char* name : {"out.json", "out.csv", "out.usda", "out.png"}) {
        const Result r = run("recombine " + q(path("coarse.json")) + " " + q(path("detail.json")) + " -o " +
                             q(path(name)) + " -q");
        ASSERT_EQ(r.code, 0) << name << ": " << r.err;
        EXPECT_TRUE(r.err.empty()) << r.err;
    }
    EXPECT_EQ(tessera::load_animation(path("out.csv")).frame_count(), 32);
    EXPECT_NE(read_text(path("out.usda")).find("positions.timeSamples"), std::string::npos);
    const std::string png = read_text(path("out.png"));
    EXPECT_TRUE(is_png(path("out.png")));
    EXPECT_NE(png.find("acTL"), std::string::npos);  // animated
}

TEST_F(MotionCli, TheFlagsOfTheOtherModeAreRefusedNamingThem) {
    const std::string head = "analyze " + q(swirl()) + " ";
    const std::string outputs = " -o " + q(path("c.json")) + " --detail " + q(path("d.json"));
    const std::pair<std::string, std::string> cases[] = {
        {"--decompose" + outputs + " --sigma 0.3", "--sigma cannot be used with --decompose"},
        {"--decompose" + outputs + " --plot " + q(path("p.png")), "--plot cannot be used with --decompose"},
        {"--decompose" + outputs + " --standard-pcf", "--standard-pcf cannot be used with --decompose"},
        {"--decompose" + outputs + " --r-max 2", "--r-max cannot be used with --decompose"},
        {"-o " + q(path("m.json")) + " --spatial-radius 2", "--spatial-radius needs --decompose"},
        {"-o " + q(path("m.json")) + " --detail " + q(path("d.json")), "--detail needs --decompose"},
        {"--decompose -o " + q(path("c.json")), "--decompose needs -o COARSE and --detail DETAIL"},
        {"--decompose" + outputs + " --topology-radius -1", "--topology-radius must be an integer from 0"},
        {"--decompose -o " + q(path("c.svg")) + " --detail " + q(path("d.json")), "-o"},
        {"--decompose -o " + q(path("c.json")) + " --detail " + q(path("c.json")), "must be different files"},
    };
    for (const auto& [args, message] : cases) {
        const Result r = run(head + args);
        EXPECT_EQ(r.code, 2) << args;
        EXPECT_EQ(r.err.rfind("tessera: error: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
        EXPECT_EQ(line_count(r.err), 1) << r.err;
        EXPECT_TRUE(work_files().empty()) << args;
    }
}

TEST_F(MotionCli, ADetailThatDoesNotFitIsAnErrorNamingTheFilesAndWritesNothing) {
    // Threads as the coarse animation, the swirl's particles as the details.
    tessera::save_animation(motion_test::animation_of(
                                "hair", tessera::ElementTopology::thread, 0, 2, 5, 3,
                                [](int e, int k, int f) {
                                    return tessera::Vec3{0.5 * k, 2.0 * e + 0.1 * f, 0};
                                },
                                tessera::Domain::box({-1, -1, 0}, {5, 5, 0}, 2)),
                            path("hair.json"));
    const Result r =
        run("recombine " + q(path("hair.json")) + " " + q(swirl()) + " -o " + q(path("out.json")));
    EXPECT_EQ(r.code, 3) << r.err;
    EXPECT_EQ(r.err,
              "tessera: error: " + swirl() +
                  ": the detail animation has no thread elements for the coarse animation's thread elements "
                  "(type 'hair') (coarse: " +
                  path("hair.json") + ")\n");
    const Result missing =
        run("recombine " + q(path("hair.json")) + " " + q(path("none.json")) + " -o " + q(path("out.json")));
    EXPECT_EQ(missing.code, 5) << missing.err;
    EXPECT_NE(missing.err.find("none.json"), std::string::npos) << missing.err;
    const Result extension =
        run("recombine " + q(path("hair.json")) + " " + q(path("hair.json")) + " -o " + q(path("out.svg")));
    EXPECT_EQ(extension.code, 2) << extension.err;
    EXPECT_EQ(work_files(), std::set<std::string>{"hair.json"});
}

}  // namespace
}  // namespace tessera_cli_test
