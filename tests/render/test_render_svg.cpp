// Tests of the SVG previews: one <circle> per single-sample element, a document
// that starts and ends as SVG, balanced groups, y flipped through the viewBox.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tessera/render.hpp"

using namespace tessera;

namespace {

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
    return n;
}

std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    return s;
}

}  // namespace

TEST(RenderSvg, OneCirclePerElementAndWellFormed) {
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {10, 5, 0}, 2);
    const int a = ex.type_index("a"), b = ex.type_index("b<&>");
    for (int i = 0; i < 9; ++i) ex.add_element(i % 3 ? a : b, {Vec3{1.0 + i, 1.0 + 0.3 * i, 0}});
    ex.elements[4].radius = 0.7;
    ex.elements[2].orientation = Quat::from_angle_z(1.0);
    const std::string svg = render_svg(ex, {.width = 500, .show_legend = false});
    EXPECT_TRUE(svg.rfind("<?xml", 0) == 0 || svg.rfind("<svg", 0) == 0);
    EXPECT_TRUE(trimmed(svg).ends_with("</svg>"));
    EXPECT_EQ(count(svg, "<circle"), 9u);
    EXPECT_EQ(count(svg, "<g"), count(svg, "</g>"));
    EXPECT_EQ(count(svg, "<svg"), 1u);
    EXPECT_NE(svg.find("width=\"500\""), std::string::npos);
    EXPECT_NE(svg.find("scale(1,-1)"), std::string::npos);
    // Class names reach the markup in the legend, escaped.
    const std::string with_legend = render_svg(ex, {.width = 500});
    EXPECT_EQ(with_legend.find("b<&>"), std::string::npos);
    EXPECT_NE(with_legend.find(">b&lt;&amp;&gt;</text>"), std::string::npos);
    EXPECT_EQ(count(with_legend, "<g"), count(with_legend, "</g>"));
    EXPECT_NE(svg.find("<line"), std::string::npos);  // the orientation tick
}

TEST(RenderSvg, PolylinesForMultiSampleElements) {
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    const int t = ex.type_index("stick");
    ex.add_element(t, {Vec3{1, 1, 0}, Vec3{2, 2, 0}, Vec3{3, 1, 0}});
    ex.add_element(ex.type_index("pebble"), {Vec3{5, 5, 0}});
    const std::string with_dots = render_svg(ex, {.show_legend = false});
    EXPECT_EQ(count(with_dots, "<polyline"), 1u);
    EXPECT_EQ(count(with_dots, "<circle"), 1u + 3u);  // the pebble + 3 sample dots
    EXPECT_EQ(count(render_svg(ex, {.show_samples = false, .show_legend = false}), "<circle"), 1u);
    EXPECT_EQ(count(render_svg(ex, {.show_domain = false, .show_legend = false}), "<rect"), 1u);  // background only
}

TEST(RenderSvg, ThreeDimensionalCirclesBackToFront) {
    Exemplar ex;
    ex.dimension = 3;
    ex.domain = Domain::box({0, 0, 0}, {4, 4, 4}, 3);
    const int t = ex.type_index("ball");
    for (int i = 0; i < 4; ++i) ex.add_element(t, {Vec3{0.5 + i, 0.5 + i, 0.5 + i}});
    const std::string svg = render_svg(ex, {.show_legend = false});
    EXPECT_TRUE(trimmed(svg).ends_with("</svg>"));
    EXPECT_EQ(count(svg, "<circle"), 4u);
    EXPECT_EQ(count(svg, "<line"), 12u);
    EXPECT_NE(svg.find("<radialGradient"), std::string::npos);
    // Painted far to near: the fog level in each circle's gradient id ("...f<level>)")
    // never increases along the file.
    int previous = 99;
    for (size_t at = svg.find("url(#"); at != std::string::npos; at = svg.find("url(#", at + 1)) {
        const size_t close = svg.find(')', at);
        const int level = svg[close - 1] - '0';
        EXPECT_LE(level, previous);
        previous = level;
    }
}
