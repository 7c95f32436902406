// Tests of the 3D PNG preview: valid, of the requested width, not blank, with
// a shaded (not flat) sphere in the class colour's hue.
#include <gtest/gtest.h>

#include "render/render_test_util.hpp"
#include "tessera/render.hpp"

using namespace tessera;

TEST(Render3d, SpheresAreDrawnAndShaded) {
    Exemplar ex;
    ex.dimension = 3;
    ex.domain = Domain::box({0, 0, 0}, {10, 10, 10}, 3);
    const int a = ex.type_index("a"), b = ex.type_index("b");
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) ex.add_element((i + j + k) % 2 ? a : b, {Vec3{2.0 + 3 * i, 2.0 + 3 * j, 2.0 + 3 * k}});
    ex.add_element(a, {Vec3{1, 1, 1}, Vec3{1, 9, 1}, Vec3{9, 9, 1}});  // a chain
    const std::string png = render_png(ex, {.width = 320});
    ASSERT_TRUE(test::has_png_signature(png));
    const auto img = test::decode_png(png);
    ASSERT_EQ(img.width, 320);
    ASSERT_GT(img.height, 100);
    int coloured = 0, white = 0;
    float darkest = 3.0f, brightest = 0.0f;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const auto c = img.at(x, y);
            const float sum = c.r + c.g + c.b;
            if (sum > 2.99f) ++white;
            // Saturated pixels: sphere surface, not the grey outline.
            if (std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b}) > 0.15f) {
                ++coloured;
                darkest = std::min(darkest, sum), brightest = std::max(brightest, sum);
            }
        }
    const int total = img.width * img.height;
    EXPECT_GT(coloured, total / 50);
    EXPECT_GT(white, total / 4);      // background around the scene
    EXPECT_GT(brightest - darkest, 0.5f);  // Lambert shading varies over the spheres
}

TEST(Render3d, EmptyBoxStillShowsTheDomain) {
    Exemplar ex;
    ex.dimension = 3;
    ex.domain = Domain::box({0, 0, 0}, {1, 2, 3}, 3);
    const auto img = test::decode_png(render_png(ex, {.width = 100}));
    ASSERT_EQ(img.width, 100);
    int grey = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) grey += img.at(x, y).r < 0.9f;
    EXPECT_GT(grey, 50);
}
