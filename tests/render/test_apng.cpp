// Animated PNGs: every chunk's CRC is right, the frame count and sequence numbers are what
// the APNG specification asks, and a viewer without APNG support still decodes frame 0.
#include <gtest/gtest.h>

#include <stb_image.h>

#include <cstdint>
#include <string>
#include <vector>

#include "dynamic/dynamic_fixtures.hpp"
#include "render/apng.hpp"
#include "tessera/animation_render.hpp"
#include "tessera/error.hpp"

namespace {

struct Chunk {
    std::string type, data;
    bool crc_ok = false;
};

std::uint32_t u32(const std::string& s, size_t at) {
    return (std::uint32_t(std::uint8_t(s[at])) << 24) | (std::uint32_t(std::uint8_t(s[at + 1])) << 16) |
           (std::uint32_t(std::uint8_t(s[at + 2])) << 8) | std::uint32_t(std::uint8_t(s[at + 3]));
}

std::vector<Chunk> chunks(const std::string& png) {
    std::vector<Chunk> out;
    for (size_t at = 8; at + 12 <= png.size();) {
        const std::uint32_t n = u32(png, at);
        Chunk c{png.substr(at + 4, 4), png.substr(at + 8, n)};
        const std::string body = png.substr(at + 4, 4 + n);
        c.crc_ok = tessera::render::crc32(reinterpret_cast<const unsigned char*>(body.data()), body.size()) ==
                   u32(png, at + 8 + n);
        out.push_back(c);
        at += 12 + n;
    }
    return out;
}

TEST(Apng, FramesChunksAndSequenceFollowTheSpecification) {
    const tessera::Animation a = dynamic_test::drifting_lattice(5, 5, 6, {0.1, 0, 0}, 0.05);
    tessera::AnimationRenderOptions options;
    options.picture.width = 120;
    options.trail = 3;
    const std::string png = tessera::render_animation_png(a, options);
    const std::vector<Chunk> cs = chunks(png);
    ASSERT_GE(cs.size(), 4u);
    EXPECT_EQ(cs[0].type, "IHDR");
    EXPECT_EQ(cs[1].type, "acTL");
    EXPECT_EQ(u32(cs[1].data, 0), 6u);  // frames
    EXPECT_EQ(cs.back().type, "IEND");
    std::uint32_t sequence = 0;
    int controls = 0;
    for (const Chunk& c : cs) {
        EXPECT_TRUE(c.crc_ok) << c.type;
        if (c.type == "fcTL" || c.type == "fdAT") {
            EXPECT_EQ(u32(c.data, 0), sequence++) << c.type;
        }
        controls += c.type == "fcTL";
    }
    EXPECT_EQ(controls, 6);
    // A plain PNG decoder sees frame 0.
    int w = 0, h = 0, n = 0;
    unsigned char* pixels = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(png.data()),
                                                  static_cast<int>(png.size()), &w, &h, &n, 3);
    ASSERT_NE(pixels, nullptr);
    EXPECT_EQ(w, 120);
    stbi_image_free(pixels);
}

TEST(Apng, ThreeDimensionalFramesShareOneView) {
    // Elements moving toward the viewer change the picture's framing unless the frames
    // share one view; the APNG then needs every frame at the same size.
    tessera::Animation a = dynamic_test::drifting_lattice(4, 4, 4, {0, 0, 0}, 0.0);
    a.structure.dimension = 3;
    a.structure.domain = tessera::Domain::box({-0.5, -0.5, -0.5}, {4.5, 4, 0.5}, 3);
    for (int f = 0; f < a.frame_count(); ++f)
        for (int s = 0; s < a.sample_count(); ++s) a.at(f, s).z = 0.4 * f;
    tessera::AnimationRenderOptions options;
    options.picture.width = 100;
    const std::vector<Chunk> cs = chunks(tessera::render_animation_png(a, options));
    ASSERT_GE(cs.size(), 2u);
    EXPECT_EQ(u32(cs[1].data, 0), 4u);
}

TEST(Apng, TrailsShowTheMotionBehindEachParticle) {
    const tessera::Animation a = dynamic_test::drifting_lattice(5, 5, 6, {0.1, 0, 0}, 0.05);
    tessera::AnimationRenderOptions plain;
    plain.picture.width = 120;
    plain.trail = 1;  // no path: the frame alone
    tessera::AnimationRenderOptions with = plain;
    with.trail = 0;  // the whole path
    EXPECT_NE(tessera::render_trails_png(a, -1, with), tessera::render_trails_png(a, -1, plain));
    EXPECT_THROW(tessera::render_trails_png(a, 6, with), tessera::Error);
    with.trail = -1;
    EXPECT_THROW(tessera::render_animation_png(a, with), tessera::Error);
}

}  // namespace
