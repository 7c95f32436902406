// Tests of class colours and the legend: colour names and "#rrggbb" parsed, a class named
// after a colour drawn in it, a type's color field used by every picture (2D and 3D, PNG,
// SVG, element meshes), the palette kept clear of chosen colours, and the legend strip
// below the picture (names and swatches, hiding nothing, omitted for one unnamed class).
#include <gtest/gtest.h>

#include <string>

#include "render/class_colors.hpp"
#include "render/legend.hpp"
#include "render/render_test_util.hpp"
#include "render/style.hpp"
#include "tessera/error.hpp"
#include "tessera/geometry.hpp"
#include "tessera/render.hpp"

using namespace tessera;

namespace {

Exemplar classes_of(const std::vector<std::string>& names, int dimension = 2) {
    Exemplar ex;
    ex.dimension = dimension;
    ex.domain = dimension == 2 ? Domain::box({0, 0, 0}, {10, 10, 0}, 2) : Domain::box({0, 0, 0}, {10, 10, 10}, 3);
    for (size_t t = 0; t < names.size(); ++t) {
        const int type = ex.type_index(names[t]);
        ex.add_element(type, {Vec3{1.5 + 2.0 * static_cast<double>(t % 4), 2.0 + 2.0 * static_cast<double>(t / 4),
                                   dimension == 3 ? 5.0 : 0.0}},
                       0.8);
    }
    return ex;
}

render::Rgb rgb(int r, int g, int b) { return {r / 255.0f, g / 255.0f, b / 255.0f}; }

render::Rgb centre_colour(const test::Image& img, const Exemplar& ex, int element, int width) {
    const auto f = render::make_frame_2d(ex, render::make_style(ex, {}), RenderOptions{.width = width});
    const auto& e = ex.elements[element];
    return img.at(static_cast<int>(f.px(e.position.x)), static_cast<int>(f.py(e.position.y)));
}

}  // namespace

TEST(Colors, ParsesHexAndColourNames) {
    EXPECT_EQ(parse_color("#e0b030"), (Color{0xe0, 0xb0, 0x30}));
    EXPECT_EQ(parse_color("#E0B030"), (Color{0xe0, 0xb0, 0x30}));
    EXPECT_EQ(parse_color("#abc"), (Color{0xaa, 0xbb, 0xcc}));
    EXPECT_EQ(parse_color("cyan"), (Color{0, 255, 255}));
    EXPECT_EQ(parse_color("Dark-Green"), (Color{0, 100, 0}));
    EXPECT_EQ(parse_color("light blue"), (Color{173, 216, 230}));
    EXPECT_EQ(parse_color("LIGHT_BLUE"), (Color{173, 216, 230}));
    EXPECT_EQ(parse_color("gray"), (Color{128, 128, 128}));  // CSS, not X11's 190
    EXPECT_EQ(parse_color("grey"), (Color{128, 128, 128}));
    EXPECT_EQ(parse_color("orange"), (Color{255, 165, 0}));
    EXPECT_EQ(parse_color("navy blue"), (Color{0, 0, 128}));  // X11 only
    for (const char* bad : {"", "#12345", "#gggggg", "#1234567", "blurple", "red1", "banana", "e0b030"})
        EXPECT_FALSE(parse_color(bad)) << bad;
}

TEST(Colors, ColorFieldThenColourNameThenPalette) {
    Exemplar ex = classes_of({"cyan", "banana", "stone", "Light Blue"});
    ex.types[1].color = "#f0d040";
    const std::vector<Color> colors = type_colors(ex);
    EXPECT_EQ(colors[0], (Color{0, 255, 255}));
    EXPECT_EQ(colors[1], (Color{0xf0, 0xd0, 0x40}));
    EXPECT_EQ(colors[3], (Color{173, 216, 230}));
    // "stone" takes the palette: not its blue, which looks like the chosen cyan and light blue.
    EXPECT_FALSE(render::looks_alike(render::to_rgb(colors[2]), render::to_rgb(*parse_color("cyan"))));
    EXPECT_FALSE(render::looks_alike(render::to_rgb(colors[2]), render::to_rgb(*parse_color("lightblue"))));
    // Without chosen colours, classes keep the palette in order.
    const std::vector<Color> plain = type_colors(classes_of({"a", "b", "c"}));
    for (int t = 0; t < 3; ++t) EXPECT_EQ(render::to_rgb(plain[t]).r, render::class_color(t).r);
    // A color the parser does not read is an input error naming the type.
    ex.types[2].color = "blurple";
    try {
        type_colors(ex);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::input);
        EXPECT_NE(std::string(e.what()).find("stone"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("blurple"), std::string::npos) << e.what();
    }
}

TEST(Colors, EveryPictureDrawsTheTypesColours) {
    Exemplar ex = classes_of({"cyan", "banana"});
    ex.types[1].color = "#f0d040";
    const RenderOptions options{.width = 400};
    const auto img = test::decode_png(render_png(ex, options));
    EXPECT_LE(test::color_distance(centre_colour(img, ex, 0, 400), rgb(0, 255, 255)), 1);
    EXPECT_LE(test::color_distance(centre_colour(img, ex, 1, 400), rgb(0xf0, 0xd0, 0x40)), 1);
    const std::string svg = render_svg(ex, options);
    EXPECT_NE(svg.find("fill=\"#00ffff\""), std::string::npos);
    EXPECT_NE(svg.find("fill=\"#f0d040\""), std::string::npos);
    // 3D spheres (shaded, so compared by hue) and their SVG gradients.
    Exemplar ex3 = classes_of({"cyan", "banana"}, 3);
    ex3.types[1].color = "#f0d040";
    EXPECT_NE(render_svg(ex3, options).find("radialGradient"), std::string::npos);
    const Scene scene = build_scene(ex3);
    for (const std::string& png : {render_png(ex3, options), render_scene_png(ex3, scene, options)}) {
        const auto pic = test::decode_png(png);
        int yellowish = 0, cyanish = 0;
        for (int y = 0; y < pic.height; ++y)
            for (int x = 0; x < pic.width; ++x) {
                const render::Rgb c = pic.at(x, y);
                yellowish += c.r > 0.5f && c.g > 0.4f && c.b < 0.35f;
                cyanish += c.r < 0.3f && c.g > 0.5f && c.b > 0.5f;
            }
        EXPECT_GT(yellowish, 100);
        EXPECT_GT(cyanish, 100);
    }
}

TEST(Legend, StripBelowHidesNothingAndShowsEveryClass) {
    const Exemplar ex = classes_of({"stone", "pebble", "sand"});
    const auto with = test::decode_png(render_png(ex, {.width = 800}));
    const auto without = test::decode_png(render_png(ex, {.width = 800, .show_legend = false}));
    ASSERT_EQ(with.width, 800);
    ASSERT_GT(with.height, without.height + 30);  // one row of 14-pixel text with padding
    // The picture above the strip is the picture without a legend, pixel for pixel.
    EXPECT_TRUE(std::equal(without.rgb.begin(), without.rgb.end(), with.rgb.begin()));
    // In the strip: a swatch of every class colour and dark text.
    const std::vector<Color> colors = type_colors(ex);
    std::vector<int> swatch(colors.size(), 0);
    int ink = 0;
    for (int y = without.height; y < with.height; ++y)
        for (int x = 0; x < with.width; ++x) {
            const render::Rgb c = with.at(x, y);
            for (size_t t = 0; t < colors.size(); ++t) swatch[t] += test::color_distance(c, render::to_rgb(colors[t])) <= 2;
            ink += c.r < 0.3f && c.g < 0.3f && c.b < 0.3f;
        }
    for (size_t t = 0; t < colors.size(); ++t) EXPECT_GT(swatch[t], 50) << ex.types[t].name;
    EXPECT_GT(ink, 200);
}

TEST(Legend, OmittedForOneUnnamedClassShownForOneNamedClass) {
    const Exemplar unnamed = classes_of({"default"});
    EXPECT_EQ(render_png(unnamed, {.width = 300}), render_png(unnamed, {.width = 300, .show_legend = false}));
    EXPECT_EQ(render_svg(unnamed, {.width = 300}).find("<text"), std::string::npos);
    const Exemplar from_python = classes_of({"0"});
    EXPECT_EQ(render_png(from_python, {.width = 300}), render_png(from_python, {.width = 300, .show_legend = false}));
    const Exemplar named = classes_of({"plum"});
    EXPECT_NE(render_svg(named, {.width = 300}).find(">plum</text>"), std::string::npos);
}

TEST(Legend, SvgNamesAreEscapedAndTheStripIsInThePicture) {
    const Exemplar ex = classes_of({"a<b & c", "rock"});
    const std::string svg = render_svg(ex, {.width = 500});
    EXPECT_NE(svg.find(">a&lt;b &amp; c</text>"), std::string::npos) << svg;
    EXPECT_NE(svg.find(">rock</text>"), std::string::npos);
    const std::string svg3 = render_svg(classes_of({"a", "b"}, 3), {.width = 500});
    EXPECT_NE(svg3.find(">b</text>"), std::string::npos);
}

TEST(Legend, ManyClassesWrapIntoAFewRowsAndLongNamesAreShortened) {
    std::vector<std::string> names;
    for (int t = 0; t < 60; ++t) names.push_back("species_" + std::to_string(t));
    names[3] = std::string(300, 'x');
    const Exemplar ex = classes_of(names);
    const std::vector<render::Rgb> colors = render::class_colors(ex);
    const render::Legend legend = render::make_legend(ex, colors, 800, {});
    ASSERT_FALSE(legend.entries.empty());
    double rows = 0;
    for (const auto& e : legend.entries) {
        EXPECT_GE(e.x - legend.swatch_radius, 0.0);
        EXPECT_LE(e.label.size(), 120u);
        rows = std::max(rows, e.y);
    }
    EXPECT_EQ(legend.entries[3].label.substr(legend.entries[3].label.size() - 3), "...");
    EXPECT_FALSE(legend.entries.back().swatch);
    EXPECT_NE(legend.entries.back().label.find(" more"), std::string::npos);
    EXPECT_LE(legend.height, 2 * 6 * 2.0 + render::legend_max_rows * 15 * 2.0 + 1);
    // Too narrow a picture gets none.
    EXPECT_EQ(render::make_legend(ex, colors, 60, {}).height, 0.0);
}
