// End-to-end tests of `tessera render`: every error names the option or file really at
// fault (and not another one), and the legend and colours reach the written pictures.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <stb_image.h>

#include "cli/cli_fixture.hpp"

using namespace tessera_cli_test;

namespace {

struct RenderErrorCase {
    std::string name;
    std::string file, content;           // an input to create in the work directory, if any
    std::string args;                    // after "render"; {work} and {ex} as in test_cli.cpp
    int code;
    std::vector<std::string> say;        // substrings of the one-line message
    std::vector<std::string> not_say;    // options that are not at fault
};

void PrintTo(const RenderErrorCase& c, std::ostream* os) { *os << c.name; }

std::string expand(std::string text, const std::string& work) {
    for (const auto& [key, value] : {std::pair<std::string, std::string>{"{work}", work}, {"{ex}", examples}})
        for (size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + value.size()))
            text.replace(at, key.size(), value);
    return text;
}

class CliRenderErrors : public CliFixture, public ::testing::WithParamInterface<RenderErrorCase> {};

TEST_P(CliRenderErrors, NameTheOptionAtFaultAndWriteNothing) {
    const RenderErrorCase& c = GetParam();
    if (!c.file.empty()) write(c.file, c.content);
    const std::set<std::string> before = work_files();
    const Result r = run("render " + expand(c.args, (root_ / "work").string()));
    EXPECT_EQ(r.code, c.code) << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    for (const auto& s : c.say) EXPECT_NE(r.err.find(s), std::string::npos) << "'" << s << "' not in: " << r.err;
    for (const auto& s : c.not_say) EXPECT_EQ(r.err.find(s), std::string::npos) << "'" << s << "' in: " << r.err;
    EXPECT_EQ(work_files(), before);
}

const std::string dots = "'{ex}poisson_disk_2d.json' ";
// A column of 100 points spaced 1 apart in a domain 100 times taller than wide: with the
// frame's margins (3% of the taller side), a 1200 pixel wide picture would be about 18,000
// pixels tall.
std::string tall_column() {
    std::string elements;
    for (int k = 0; k < 100; ++k)
        elements += std::string(k ? ", " : "") + "{\"position\": [0.5, " + std::to_string(k + 0.5) + "]}";
    return R"({"format": "tessera", "version": 1, "dimension": 2, "domain": {"type": "box", "min": [0, 0], "max": [1, 100]},
        "elements": [)" + elements + "]}";
}
const std::string tall = tall_column();

// clang-format off
const RenderErrorCase render_error_cases[] = {
    {"meshes_on_with_svg", "", "", dots + "-o '{work}/p.svg' --meshes on", 2, {"--meshes on", "p.svg", ".png"}, {"--width"}},
    {"meshes_on_with_svg_and_width", "", "", dots + "-o '{work}/p.svg' --meshes on --width 300", 2, {"--meshes"}, {"--width"}},
    {"unknown_meshes", "", "", dots + "-o '{work}/p.png' --meshes maybe", 2, {"--meshes", "maybe"}, {"--width"}},
    {"width_zero", "", "", dots + "-o '{work}/p.png' --width 0", 2, {"--width", "16 and 16384", "got 0"}, {"--meshes"}},
    {"width_too_large", "", "", dots + "-o '{work}/p.png' --width 1e5", 2, {"--width", "got 100000"}, {}},
    {"width_not_integral", "", "", dots + "-o '{work}/p.png' --width 1e-1", 2, {"--width", "not an integer"}, {}},
    {"picture_too_tall", "tall.json", tall, "'{work}/tall.json' -o '{work}/p.png' --width 1200", 2, {"--width", "pixels tall"}, {"--meshes"}},
    {"svg_too_tall", "tall.json", tall, "'{work}/tall.json' -o '{work}/p.svg' --width 1200", 2, {"--width", "pixels tall"}, {}},
    {"too_many_pixels", "", "", dots + "-o '{work}/p.png' --width 12000", 2, {"--width", "too large"}, {}},
    {"bad_extension", "", "", dots + "-o '{work}/p.jpg'", 2, {"-o", "p.jpg", ".jpg"}, {"--width", "--meshes"}},
    {"missing_output", "", "", dots, 2, {"--output"}, {"--width"}},
    {"missing_input", "", "", "'{work}/none.json' -o '{work}/p.png'", 5, {"none.json"}, {"--width"}},
    {"bad_input_domain", "", "", dots + "-o '{work}/p.png' --input-domain 0,0,0,1", 2, {"--input-domain"}, {"--width"}},
    {"bad_color_in_file", "c.json",
     R"({"format": "tessera", "version": 1, "dimension": 2, "domain": {"type": "box", "min": [0, 0], "max": [4, 4]},
         "types": [{"name": "dot", "color": "blurple"}], "elements": [{"type": "dot", "position": [1, 1]}]})",
     "'{work}/c.json' -o '{work}/p.png'", 3, {"c.json", "types[0].color", "blurple"}, {"--width"}},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Cli, CliRenderErrors, ::testing::ValuesIn(render_error_cases),
                         [](const ::testing::TestParamInfo<RenderErrorCase>& info) { return info.param.name; });

struct Png {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
};

Png read_png(const std::string& path) {
    Png png;
    int channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &png.width, &png.height, &channels, 3);
    if (data) png.rgb.assign(data, data + static_cast<size_t>(png.width) * png.height * 3);
    stbi_image_free(data);
    return png;
}

class CliRenderLegend : public CliFixture {};

TEST_F(CliRenderLegend, TwoClassesGetALegendStripThatNoLegendRemoves) {
    const std::string input = q(example("two_class_2d.json"));
    ASSERT_EQ(run("render " + input + " -o " + q(path("with.png")) + " -q").code, 0);
    ASSERT_EQ(run("render " + input + " -o " + q(path("without.png")) + " --no-legend -q").code, 0);
    const Png with = read_png(path("with.png")), without = read_png(path("without.png"));
    ASSERT_EQ(with.width, 800);
    EXPECT_EQ(without.width, 800);
    // A strip of one row: about 3 text heights (14 px each at 800 px) below the domain.
    EXPECT_GT(with.height - without.height, 30);
    EXPECT_LT(with.height - without.height, 60);
    ASSERT_EQ(run("render " + input + " -o " + q(path("with.svg")) + " -q").code, 0);
    const std::string svg = read_text(path("with.svg"));
    EXPECT_NE(svg.find(">stone</text>"), std::string::npos);
    EXPECT_NE(svg.find(">pebble</text>"), std::string::npos);
}

}  // namespace
