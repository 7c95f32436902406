// 2D PNG preview: white background, grey domain outline, single-sample elements
// as anti-aliased disks with a slightly darker rim (so touching disks stay
// distinct) and an orientation tick, or as the glyph of their type (a fish along their
// heading), multi-sample elements as thick polylines
// through their samples with dots at the samples. Drawn in element order, in the
// colours of type_colors, with the legend strip below.
#include <algorithm>
#include <cmath>

#include "render/class_colors.hpp"
#include "render/glyphs.hpp"
#include "render/grid.hpp"
#include "render/legend.hpp"
#include "render/palette.hpp"
#include "render/raster.hpp"
#include "render/render_internal.hpp"
#include "render/style.hpp"

namespace tessera::render {
namespace {

constexpr double min_radius_px = 0.75;  // smallest disk drawn, so dense outputs stay visible

void draw_disk_element(Canvas& canvas, const Frame2D& f, const Style& style, const Element& e, Rgb color) {
    const double cx = f.px(e.position.x), cy = f.py(e.position.y);
    const double r = std::max(min_radius_px, style.radius_of(e) * f.scale);
    if (r >= 3.0) {
        const double rim = std::clamp(0.08 * r, 0.8, 2.0);
        canvas.add_disk(cx, cy, r);
        canvas.composite(darker(color, 0.72f));
        canvas.add_disk(cx, cy, r - rim);
    } else {
        canvas.add_disk(cx, cy, r);
    }
    canvas.composite(color);
    if (has_rotation(e.orientation) && r >= 2.0) {
        const Vec3 axis = e.orientation.rotate({1.0, 0.0, 0.0});  // the element's reference x axis
        const double len = std::hypot(axis.x, axis.y);
        if (len < 1e-6) return;  // rotated out of the plane: no direction to show
        const double ux = axis.x / len, uy = -axis.y / len;   // picture y points down
        canvas.add_capsule(cx, cy, cx + 0.85 * r * ux, cy + 0.85 * r * uy, std::clamp(0.1 * r, 0.6, 3.0));
        canvas.composite(darker(color, 0.45f));
    }
}

// A glyph (glyphs.hpp) turned to the element's x axis (+x when it has no rotation).
void draw_glyph_element(Canvas& canvas, const Frame2D& f, const Style& style, const Element& e, Rgb color) {
    const double r = std::max(min_radius_px, style.radius_of(e) * f.scale);
    const Vec3 axis = e.orientation.rotate({1.0, 0.0, 0.0});
    const double len = std::hypot(axis.x, axis.y);
    const double ux = len > 1e-6 ? axis.x / len : 1.0, uy = len > 1e-6 ? -axis.y / len : 0.0;  // picture y down
    const double cx = f.px(e.position.x), cy = f.py(e.position.y);
    // Element frame (a along the heading, b across, y up) to pixels.
    const auto px = [&](double a, double b) { return cx + r * (a * ux + b * uy); };
    const auto py = [&](double a, double b) { return cy + r * (a * uy - b * ux); };
    for (const GlyphPart& g : fish_glyph()) {
        if (g.ax == g.bx && g.ay == g.by) canvas.add_disk(px(g.ax, g.ay), py(g.ax, g.ay), g.radius * r);
        else canvas.add_capsule(px(g.ax, g.ay), py(g.ax, g.ay), px(g.bx, g.by), py(g.bx, g.by), g.radius * r);
    }
    canvas.composite(color);
}

void draw_polyline_element(Canvas& canvas, const Frame2D& f, const Style& style, const Exemplar& data,
                           const Element& e, Rgb color, bool show_samples) {
    const double hw = std::max(0.6, style.line_half_width * f.scale);
    const Sample* s = &data.samples[e.first_sample];
    for (int k = 0; k + 1 < e.sample_count; ++k)
        canvas.add_capsule(f.px(s[k].p.x), f.py(s[k].p.y), f.px(s[k + 1].p.x), f.py(s[k + 1].p.y), hw);
    canvas.composite(color);
    if (!show_samples) return;
    const double dot = std::max(1.0, 0.6 * hw);
    for (int k = 0; k < e.sample_count; ++k) canvas.add_disk(f.px(s[k].p.x), f.py(s[k].p.y), dot);
    canvas.composite(darker(color, 0.55f));
}

}  // namespace

void draw_domain_outline(Canvas& canvas, const Frame2D& f, const Domain& domain) {
    const double hw = 0.75;
    if (domain.kind() == Domain::Kind::polygon) {  // outer ring and holes
        const DomainSource src = domain.source();
        std::vector<std::vector<Vec3>> rings = src.holes;
        rings.push_back(src.outer);
        for (const auto& ring : rings)
            for (size_t k = 0; k < ring.size(); ++k) {
                const Vec3& a = ring[k];
                const Vec3& b = ring[(k + 1) % ring.size()];
                canvas.add_capsule(f.px(a.x), f.py(a.y), f.px(b.x), f.py(b.y), hw);
            }
        canvas.composite(outline_grey);
        return;
    }
    const Box& b = domain.bounds();
    const double x0 = f.px(b.lo.x), x1 = f.px(b.hi.x), y0 = f.py(b.lo.y), y1 = f.py(b.hi.y);
    canvas.add_capsule(x0, y0, x1, y0, hw);
    canvas.add_capsule(x1, y0, x1, y1, hw);
    canvas.add_capsule(x1, y1, x0, y1, hw);
    canvas.add_capsule(x0, y1, x0, y0, hw);
    canvas.composite(outline_grey);
}

std::string render_png_2d(const Exemplar& data, const RenderOptions& options) {
    const Style style = make_style(data, options);
    const Frame2D frame = make_frame_2d(data, style, options);
    const std::vector<Rgb> colors = class_colors(data);
    const Legend legend = make_legend(data, colors, frame.width, options);
    check_picture_size(frame.width, frame.height + static_cast<int>(legend.height));
    Canvas canvas(frame.width, frame.height, white);
    if (options.grid > 0.0) {
        for (const auto& [a, b] : grid_lines(data.domain.bounds(), options.grid, 2))
            canvas.add_capsule(frame.px(a.x), frame.py(a.y), frame.px(b.x), frame.py(b.y), 0.8);
        canvas.composite(grid_line);
    }
    if (options.show_domain) draw_domain_outline(canvas, frame, data.domain);
    for (const auto& e : data.elements) {
        if (e.sample_count <= 1 && data.types[e.type].glyph == ElementGlyph::fish)
            draw_glyph_element(canvas, frame, style, e, colors[e.type]);
        else if (e.sample_count <= 1)
            draw_disk_element(canvas, frame, style, e, colors[e.type]);
        else
            draw_polyline_element(canvas, frame, style, data, e, colors[e.type], options.show_samples);
    }
    draw_legend_png(canvas, legend);
    return canvas.encode_png();
}

}  // namespace tessera::render
