// Tests of render_to_file: the format follows the extension (any case), and an
// unknown extension is an option error naming the path.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include <unistd.h>

#include "render/render_test_util.hpp"
#include "tessera/error.hpp"
#include "tessera/render.hpp"

using namespace tessera;

namespace {

std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST(RenderFile, WritesByExtension) {
    const auto dir = std::filesystem::temp_directory_path() / ("tessera_render_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    Exemplar ex;
    ex.add_element(ex.type_index("a"), {Vec3{0.5, 0.5, 0}});
    ex.add_element(ex.type_index("a"), {Vec3{0.2, 0.7, 0}});
    render_to_file(ex, (dir / "p.png").string(), {.width = 64});
    render_to_file(ex, (dir / "p.SVG").string(), {.width = 64});
    EXPECT_TRUE(test::has_png_signature(slurp(dir / "p.png")));
    EXPECT_EQ(test::decode_png(slurp(dir / "p.png")).width, 64);
    EXPECT_NE(slurp(dir / "p.SVG").find("</svg>"), std::string::npos);
    const std::string bad = (dir / "p.jpg").string();
    try {
        render_to_file(ex, bad);
        FAIL() << "expected Error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::option);
        EXPECT_NE(std::string(e.what()).find(bad), std::string::npos);
    }
    EXPECT_FALSE(std::filesystem::exists(bad));
    std::filesystem::remove_all(dir);
}
