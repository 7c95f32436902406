// `tessera synth` and `tessera render` with an animated exemplar: the dynamic method chosen
// from the frames, the animation written as JSON with frames or as an animated PNG, and
// errors that name the flag and leave no file behind.
#include <gtest/gtest.h>

#include "cli/cli_fixture.hpp"
#include "dynamic/dynamic_fixtures.hpp"
#include "geometry/usda_text.hpp"
#include "tessera/animation_io.hpp"

namespace tessera_cli_test {
namespace {

class DynamicCli : public CliFixture {
protected:
    std::string lattice() const { return example("dynamic/drifting_lattice_2d.json"); }
};

TEST_F(DynamicCli, AnimatedInputChoosesTheDynamicMethodAndWritesFrames) {
    const Result r = run("synth '" + lattice() + "' -o '" + path("out.json") + "' --frames 4 --scale 1.5 --threads 2");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("method dynamic"), std::string::npos) << r.err;
    const tessera::Animation out = tessera::load_animation(path("out.json"));
    EXPECT_EQ(out.frame_count(), 4);
    EXPECT_GT(out.structure.elements.size(), 200u);  // 144 in the exemplar, 2.25x the area
}

TEST_F(DynamicCli, PngOutputAndPreviewAreAnimatedPngs) {
    const Result r = run("synth '" + lattice() + "' -o '" + path("out.png") + "' --frames 3 --preview '" +
                         path("preview.png") + "' -q");
    ASSERT_EQ(r.code, 0) << r.err;
    for (const char* name : {"out.png", "preview.png"}) {
        const std::string png = read_text(path(name));
        EXPECT_EQ(png.rfind("\x89PNG", 0), 0u) << name;
        EXPECT_NE(png.find("acTL"), std::string::npos) << name;
        EXPECT_NE(png.find("fdAT"), std::string::npos) << name;
    }
    const Result still = run("render '" + lattice() + "' -o '" + path("still.png") + "' --frame -1 --trail 0 -q");
    ASSERT_EQ(still.code, 0) << still.err;
    EXPECT_EQ(read_text(path("still.png")).find("acTL"), std::string::npos);
}

TEST_F(DynamicCli, UsdOutputAnimatesTheInstancerWithOneTimeSamplePerFrame) {
    const Result r = run("synth '" + lattice() + "' -o '" + path("out.usda") + "' --frames 5 --scale 1.2 -q");
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string usda = read_text(path("out.usda"));
    EXPECT_NE(usda.find("startTimeCode = 0"), std::string::npos);
    EXPECT_NE(usda.find("endTimeCode = 4"), std::string::npos);
    EXPECT_NE(usda.find("timeCodesPerSecond = 10"), std::string::npos);  // frames 0.1 apart
    const size_t samples = usda.find("point3f[] positions.timeSamples = {");
    ASSERT_NE(samples, std::string::npos);
    for (int f = 0; f < 5; ++f) EXPECT_NE(usda.find("\n            " + std::to_string(f) + ": [(", samples), std::string::npos) << f;
    EXPECT_EQ(usda.find("\n            5: [(", samples), std::string::npos);
    EXPECT_NE(usda.find("quath[] orientations.timeSamples"), std::string::npos);
    // Frame 0's positions are the JSON output's frame 0 (same run, same seed).
    ASSERT_EQ(run("synth '" + lattice() + "' -o '" + path("out.json") + "' --frames 5 --scale 1.2 -q").code, 0);
    const tessera::Animation a = tessera::load_animation(path("out.json"));
    EXPECT_NE(usda.find("0: [(" + tessera::geometry::usda::real(a.at(0, 0).x)), std::string::npos);
}

TEST_F(DynamicCli, ATemporalWindowLongerThanTheExemplarNamesTheFlag) {
    tessera::save_animation(dynamic_test::drifting_lattice(4, 4, 3, {0.1, 0, 0}, 0.0), path("short.json"));
    const Result r = run("synth '" + path("short.json") + "' -o '" + path("out.json") + "' --temporal-size 5");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err.rfind("tessera: error: --temporal-size must be at most the exemplar's frame count (3), got 5", 0), 0u)
        << r.err;
    EXPECT_EQ(work_files(), std::set<std::string>{"short.json"});
}

TEST_F(DynamicCli, BadOptionsNameTheFlagAndWriteNothing) {
    Result r = run("synth '" + lattice() + "' -o '" + path("out.svg") + "'");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("-o"), std::string::npos) << r.err;
    r = run("synth '" + lattice() + "' -o '" + path("out.json") + "' --temporal-size 40");
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("--temporal-size must be"), std::string::npos) << r.err;
    r = run("synth '" + lattice() + "' -o '" + path("out.json") + "' --flow 1,x");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--flow must be a vector"), std::string::npos) << r.err;
    r = run("render '" + lattice() + "' -o '" + path("x.png") + "' --frame 99");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--frame"), std::string::npos) << r.err;
    EXPECT_TRUE(work_files().empty());
}

}  // namespace
}  // namespace tessera_cli_test
