// Tests of the 2D PNG preview: a valid PNG of the requested width, class colours
// at element centres, white away from elements, y pointing up, orientation
// ticks, polylines for multi-sample elements, option errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "render/render_test_util.hpp"
#include "render/style.hpp"
#include "tessera/animation.hpp"
#include "tessera/animation_render.hpp"
#include "tessera/error.hpp"
#include "tessera/render.hpp"

using namespace tessera;

namespace {

// Two classes of disks with radius 1 in a 10 x 10 box.
Exemplar two_disks() {
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    const int a = ex.type_index("pebble"), b = ex.type_index("shell");
    ex.add_element(a, {Vec3{3, 3, 0}}, 1.0);
    ex.add_element(b, {Vec3{7, 7, 0}}, 1.0);
    ex.add_element(b, {Vec3{7, 2, 0}}, 1.0);
    return ex;
}

render::Frame2D frame_of(const Exemplar& ex, int width) {
    return render::make_frame_2d(ex, render::make_style(ex, {}), RenderOptions{.width = width});
}

}  // namespace

TEST(Render2d, PngDecodesToRequestedWidthAndAspect) {
    const Exemplar ex = two_disks();
    const std::string png = render_png(ex, {.width = 400, .show_legend = false});
    ASSERT_TRUE(test::has_png_signature(png));
    const auto img = test::decode_png(png);
    EXPECT_EQ(img.width, 400);
    EXPECT_NEAR(img.height, 400, 2);  // square domain

    Exemplar wide = ex;
    wide.domain = Domain::box({0, 0, 0}, {20, 10, 0}, 2);
    const auto wide_img = test::decode_png(render_png(wide, {.width = 400, .show_legend = false}));
    EXPECT_EQ(wide_img.width, 400);
    EXPECT_NEAR(wide_img.height, 400 * (10 + 1.2) / (20 + 1.2), 2);  // 3% margins of the longer side
}

TEST(Render2d, ClassColoursAtCentresWhiteElsewhere) {
    const Exemplar ex = two_disks();
    const auto img = test::decode_png(render_png(ex, {.width = 400}));
    const auto f = frame_of(ex, 400);
    for (const auto& e : ex.elements) {
        const int x = static_cast<int>(f.px(e.position.x)), y = static_cast<int>(f.py(e.position.y));
        EXPECT_LE(test::color_distance(img.at(x, y), render::class_color(e.type)), 1) << "element type " << e.type;
    }
    // Far from every element and from the outline.
    EXPECT_EQ(test::color_distance(img.at(static_cast<int>(f.px(5)), static_cast<int>(f.py(5))), render::white), 0);
    EXPECT_EQ(test::color_distance(img.at(static_cast<int>(f.px(2)), static_cast<int>(f.py(8))), render::white), 0);
    // y points up: the element at y = 3 is in the lower half of the picture.
    EXPECT_GT(f.py(3.0), img.height / 2);
    // The domain outline is grey, not white.
    const auto edge = img.at(static_cast<int>(f.px(5)), static_cast<int>(std::lround(f.py(0.0) - 0.5)));
    EXPECT_LT(edge.r, 0.9f);
}

TEST(Render2d, DiskSizeFollowsSpacingWhenNoRadius) {
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    const int t = ex.type_index("p");
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) ex.add_element(t, {Vec3{1.0 + 2 * i, 1.0 + 2 * j, 0}});
    // Spacing 2 -> radius 0.8: a point 0.6 from a centre is inside, 1.0 (midway) is not.
    const auto img = test::decode_png(render_png(ex, {.width = 500}));
    const auto f = frame_of(ex, 500);
    const auto blue = render::class_color(0);
    EXPECT_LE(test::color_distance(img.at(static_cast<int>(f.px(5.6)), static_cast<int>(f.py(5))), blue), 1);
    EXPECT_EQ(test::color_distance(img.at(static_cast<int>(f.px(6.0)), static_cast<int>(f.py(5))), render::white), 0);
}

TEST(Render2d, OrientationTickIsDarker) {
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    ex.add_element(ex.type_index("stone"), {Vec3{5, 5, 0}}, 2.0);
    ex.elements[0].orientation = Quat::from_angle_z(std::acos(-1.0) / 2.0);  // tick points +y
    const auto img = test::decode_png(render_png(ex, {.width = 400}));
    const auto f = frame_of(ex, 400);
    const auto fill = render::class_color(0);
    const auto above = img.at(static_cast<int>(f.px(5)), static_cast<int>(f.py(6)));
    const auto below = img.at(static_cast<int>(f.px(5)), static_cast<int>(f.py(4)));
    EXPECT_LE(test::color_distance(below, fill), 1);
    EXPECT_LT(above.r + above.g + above.b, 0.8f * (fill.r + fill.g + fill.b));
}

// Second moments of the non-white pixels: how far the ink spreads along x and along y.
std::pair<double, double> ink_spread(const test::Image& img, int rows) {
    double n = 0, sx = 0, sy = 0, sxx = 0, syy = 0;
    for (int y = 0; y < rows; ++y)
        for (int x = 0; x < img.width; ++x) {
            const auto c = img.at(x, y);
            if (c.r + c.g + c.b > 2.9f) continue;
            n += 1, sx += x, sy += y, sxx += double(x) * x, syy += double(y) * y;
        }
    return {sxx / n - (sx / n) * (sx / n), syy / n - (sy / n) * (sy / n)};
}

TEST(Render2d, AFishGlyphIsLongAlongItsHeadingInPngAndSvg) {
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    const int fish = ex.type_index("fish");
    ex.types[fish].glyph = ElementGlyph::fish;
    ex.add_element(fish, {Vec3{5, 5, 0}}, 2.0);
    const RenderOptions options{.width = 400, .show_domain = false, .show_legend = false};
    const auto along_x = ink_spread(test::decode_png(render_png(ex, options)), 400);
    EXPECT_GT(along_x.first, 3.0 * along_x.second);  // heading +x without a rotation
    ex.elements[0].orientation = Quat::from_angle_z(std::acos(-1.0) / 2.0);
    const auto along_y = ink_spread(test::decode_png(render_png(ex, options)), 400);
    EXPECT_GT(along_y.second, 3.0 * along_y.first);
    EXPECT_NEAR(along_y.second, along_x.first, 0.05 * along_x.first);  // the same fish, turned
    // The SVG draws it from the same parts, turned the same way: its tail lobes lie below
    // the centre (heading +y: the tail towards -y).
    const std::string svg = render_svg(ex, options);
    double low = 5, high = 5;  // the y range of the glyph's strokes, data units
    for (const char* key : {" y1=\"", " y2=\""})
        for (size_t at = svg.find(key); at != std::string::npos; at = svg.find(key, at + 1)) {
            const double y = std::stod(svg.substr(at + 5));
            low = std::min(low, y), high = std::max(high, y);
        }
    EXPECT_LT(low, 5.0 - 2.0) << "the tail, more than a radius behind the centre";
    EXPECT_LT(high, 5.0 + 2.0) << "the snout, within the radius ahead";
    EXPECT_GT(high, 5.0 + 1.0);
}

TEST(Render2d, AnAnimatedFishHeadsWhereItMoves) {
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    const int fish = ex.type_index("fish");
    ex.types[fish].glyph = ElementGlyph::fish;
    ex.add_element(fish, {Vec3{5, 4, 0}}, 2.0);
    Animation a = animation_from_exemplar(ex);
    a.add_frame(1.0, {Vec3{5, 5, 0}});
    a.add_frame(2.0, {Vec3{5, 6, 0}});  // swimming +y; its own orientation says +x
    AnimationRenderOptions options;
    options.picture = RenderOptions{.width = 400, .show_domain = false, .show_legend = false};
    options.trail = 1;  // the frame alone
    const auto spread = ink_spread(test::decode_png(render_trails_png(a, 1, options)), 400);
    EXPECT_GT(spread.second, 3.0 * spread.first);
}

TEST(Render2d, MultiSampleElementsArePolylines) {
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    const int t = ex.type_index("stick");
    ex.add_element(t, {Vec3{1, 2, 0}, Vec3{5, 2, 0}, Vec3{5, 8, 0}});
    ex.add_element(t, {Vec3{8, 1, 0}, Vec3{8, 9, 0}, Vec3{9, 9, 0}});
    const auto img = test::decode_png(render_png(ex, {.width = 400}));
    const auto f = frame_of(ex, 400);
    const auto color = render::class_color(0);
    // Midpoints of segments carry the class colour; a point off the sticks is white.
    EXPECT_LE(test::color_distance(img.at(static_cast<int>(f.px(3)), static_cast<int>(f.py(2))), color), 1);
    EXPECT_LE(test::color_distance(img.at(static_cast<int>(f.px(5)), static_cast<int>(f.py(5))), color), 1);
    EXPECT_EQ(test::color_distance(img.at(static_cast<int>(f.px(3)), static_cast<int>(f.py(6))), render::white), 0);
    // Sample dots are darker than the line; without show_samples they are gone.
    const auto dot = img.at(static_cast<int>(f.px(5)), static_cast<int>(f.py(2)));
    EXPECT_LT(dot.r + dot.g + dot.b, 0.8f * (color.r + color.g + color.b));
    const auto plain = test::decode_png(render_png(ex, {.width = 400, .show_samples = false}));
    EXPECT_LE(test::color_distance(plain.at(static_cast<int>(f.px(5)), static_cast<int>(f.py(2))), color), 1);
}

TEST(Render2d, SingleElementAndOptionErrors) {
    Exemplar one;
    one.domain = Domain::box({0, 0, 0}, {4, 2, 0}, 2);
    one.add_element(one.type_index("a"), {Vec3{2, 1, 0}});
    const auto img = test::decode_png(render_png(one, {.width = 200, .show_legend = false}));
    ASSERT_EQ(img.width, 200);
    EXPECT_LE(test::color_distance(img.at(100, img.height / 2), render::class_color(0)), 1);
    try {
        render_png(one, {.width = 4});
        FAIL() << "expected Error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::option);
    }
    EXPECT_THROW(render_svg(one, {.width = 100000}), Error);
}

TEST(Render2d, AGridDrawsFaintTileBordersBehindTheElements) {
    // A world's tile borders at multiples of 5: grey on the line x = 5 away from elements,
    // white beside it and where no grid is asked for, the element's colour on top of a line.
    Exemplar ex = two_disks();
    ex.add_element(0, {Vec3{5, 5, 0}}, 1.0);
    const auto f = frame_of(ex, 400);
    const auto plain = test::decode_png(render_png(ex, {.width = 400, .show_legend = false}));
    RenderOptions options{.width = 400, .show_legend = false};
    options.grid = 5.0;
    const auto img = test::decode_png(render_png(ex, options));
    const int line_x = static_cast<int>(std::lround(f.px(5))), free_y = static_cast<int>(f.py(8.5));
    EXPECT_EQ(test::color_distance(plain.at(line_x, free_y), render::white), 0);
    EXPECT_GT(test::color_distance(img.at(line_x, free_y), render::white), 10);
    EXPECT_LT(test::color_distance(img.at(line_x, free_y), render::white), 120);  // faint
    EXPECT_EQ(test::color_distance(img.at(line_x + 6, free_y), render::white), 0);
    EXPECT_LE(test::color_distance(img.at(line_x, static_cast<int>(f.py(5))), render::class_color(0)), 1);
    options.grid = -1.0;
    EXPECT_THROW(render_png(ex, options), Error);
}
