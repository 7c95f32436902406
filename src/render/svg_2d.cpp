// 2D SVG preview: the same picture as the 2D PNG (render_2d.cpp) as vectors.
// The viewBox is in data units with y flipped (a scale(1,-1) group), so the
// coordinates in the file are the data's own. Runs of elements of one class
// share a <g> carrying the colours, which keeps large outputs compact while
// keeping the PNG's element drawing order. The legend strip below the domain is
// drawn in pixel units (legend.hpp).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "render/class_colors.hpp"
#include "render/glyphs.hpp"
#include "render/legend.hpp"
#include "render/palette.hpp"
#include "render/render_internal.hpp"
#include "render/style.hpp"
#include "render/svg_writer.hpp"

namespace tessera::render {
namespace {

constexpr double min_radius_px = 0.75;  // as in render_2d.cpp

void write_disk(std::ostream& out, const SvgNumbers& num, double px_size, const Element& e, const Style& style,
                Rgb color) {
    const double r = std::max(min_radius_px * px_size, style.radius_of(e));
    const double r_px = r / px_size;
    const double x = e.position.x, y = e.position.y;
    if (r_px >= 3.0) {
        // The rim is a stroke centred on the circle: shrink by half its width so
        // the outer edge stays at r, as in the PNG.
        const double rim = std::clamp(0.08 * r_px, 0.8, 2.0) * px_size;
        out << "<circle cx=\"" << num(x) << "\" cy=\"" << num(y) << "\" r=\"" << num(r - 0.5 * rim)
            << "\" stroke-width=\"" << num(rim) << "\"/>\n";
    } else {
        out << "<circle cx=\"" << num(x) << "\" cy=\"" << num(y) << "\" r=\"" << num(r) << "\" stroke=\"none\"/>\n";
    }
    if (has_rotation(e.orientation) && r_px >= 2.0) {
        const Vec3 axis = e.orientation.rotate({1.0, 0.0, 0.0});
        const double len = std::hypot(axis.x, axis.y);
        if (len < 1e-6) return;
        const double tx = x + 0.85 * r * axis.x / len, ty = y + 0.85 * r * axis.y / len;
        out << "<line x1=\"" << num(x) << "\" y1=\"" << num(y) << "\" x2=\"" << num(tx) << "\" y2=\"" << num(ty)
            << "\" stroke=\"" << to_hex(darker(color, 0.45f)) << "\" stroke-width=\""
            << num(2.0 * std::clamp(0.1 * r_px, 0.6, 3.0) * px_size) << "\" stroke-linecap=\"round\"/>\n";
    }
}

// A glyph (glyphs.hpp) turned to the element's x axis, in data units: disks as circles,
// segments as round-capped lines of the fill colour, as the PNG draws them.
void write_glyph(std::ostream& out, const SvgNumbers& num, double px_size, const Element& e, const Style& style,
                 Rgb color) {
    const double r = std::max(min_radius_px * px_size, style.radius_of(e));
    const Vec3 axis = e.orientation.rotate({1.0, 0.0, 0.0});
    const double len = std::hypot(axis.x, axis.y);
    const double ux = len > 1e-6 ? axis.x / len : 1.0, uy = len > 1e-6 ? axis.y / len : 0.0;
    const auto x = [&](double a, double b) { return e.position.x + r * (a * ux - b * uy); };
    const auto y = [&](double a, double b) { return e.position.y + r * (a * uy + b * ux); };
    for (const GlyphPart& g : fish_glyph()) {
        if (g.ax == g.bx && g.ay == g.by) {
            out << "<circle cx=\"" << num(x(g.ax, g.ay)) << "\" cy=\"" << num(y(g.ax, g.ay)) << "\" r=\""
                << num(g.radius * r) << "\" stroke=\"none\"/>\n";
        } else {
            out << "<line x1=\"" << num(x(g.ax, g.ay)) << "\" y1=\"" << num(y(g.ax, g.ay)) << "\" x2=\""
                << num(x(g.bx, g.by)) << "\" y2=\"" << num(y(g.bx, g.by)) << "\" stroke=\"" << to_hex(color)
                << "\" stroke-width=\"" << num(2.0 * g.radius * r) << "\" stroke-linecap=\"round\"/>\n";
        }
    }
}

void write_polyline(std::ostream& out, const SvgNumbers& num, double px_size, const Exemplar& data, const Element& e,
                    const Style& style, Rgb color, bool show_samples) {
    const double hw = std::max(0.6 * px_size, style.line_half_width);
    const Sample* s = &data.samples[e.first_sample];
    out << "<polyline fill=\"none\" stroke=\"" << to_hex(color) << "\" stroke-width=\"" << num(2.0 * hw)
        << "\" stroke-linecap=\"round\" stroke-linejoin=\"round\" points=\"";
    for (int k = 0; k < e.sample_count; ++k) out << (k ? " " : "") << num(s[k].p.x) << "," << num(s[k].p.y);
    out << "\"/>\n";
    if (!show_samples) return;
    const double dot = std::max(1.0 * px_size, 0.6 * hw);
    for (int k = 0; k < e.sample_count; ++k)
        out << "<circle cx=\"" << num(s[k].p.x) << "\" cy=\"" << num(s[k].p.y) << "\" r=\"" << num(dot)
            << "\" fill=\"" << to_hex(darker(color, 0.55f)) << "\" stroke=\"none\"/>\n";
}

}  // namespace

std::string render_svg_2d(const Exemplar& data, const RenderOptions& options) {
    const Style style = make_style(data, options);
    const Frame2D f = make_frame_2d(data, style, options);
    const double px_size = 1.0 / f.scale;  // data units per pixel
    const SvgNumbers num(px_size);
    const double vw = f.hi.x - f.lo.x, vh = f.hi.y - f.lo.y;
    const std::vector<Rgb> colors = class_colors(data);
    const Legend legend = make_legend(data, colors, f.width, options);
    check_picture_size(f.width, f.height + static_cast<int>(legend.height));
    std::ostringstream out;
    // viewBox in flipped coordinates: data y in [lo.y, hi.y] becomes [-hi.y, -lo.y]; the
    // legend strip adds its height (in data units) below.
    out << svg_header(f.width, f.height + static_cast<int>(legend.height),
                      num(f.lo.x) + " " + num(-f.hi.y) + " " + num(vw) + " " + num(vh + legend.height * px_size));
    out << "<rect x=\"" << num(f.lo.x) << "\" y=\"" << num(-f.hi.y) << "\" width=\"" << num(vw) << "\" height=\""
        << num(vh) << "\" fill=\"#ffffff\"/>\n";
    out << "<g transform=\"scale(1,-1)\">\n";
    if (options.show_domain && data.domain.kind() == Domain::Kind::polygon) {
        const DomainSource src = data.domain.source();
        std::vector<std::vector<Vec3>> rings = src.holes;
        rings.push_back(src.outer);
        for (const auto& ring : rings) {
            out << "<polygon fill=\"none\" stroke=\"" << to_hex(outline_grey) << "\" stroke-width=\""
                << num(1.5 * px_size) << "\" points=\"";
            for (const auto& p : ring) out << num(p.x) << "," << num(p.y) << " ";
            out << "\"/>\n";
        }
    } else if (options.show_domain) {
        const Box& b = data.domain.bounds();
        out << "<rect x=\"" << num(b.lo.x) << "\" y=\"" << num(b.lo.y) << "\" width=\"" << num(b.hi.x - b.lo.x)
            << "\" height=\"" << num(b.hi.y - b.lo.y) << "\" fill=\"none\" stroke=\"" << to_hex(outline_grey)
            << "\" stroke-width=\"" << num(1.5 * px_size) << "\"/>\n";
    }
    int open_type = -1;
    for (const auto& e : data.elements) {
        if (e.type != open_type) {
            if (open_type >= 0) out << "</g>\n";
            const Rgb color = colors[e.type];
            out << "<g class=\"" << "type-" << e.type << "\" fill=\"" << to_hex(color) << "\" stroke=\""
                << to_hex(darker(color, 0.72f)) << "\">\n";
            open_type = e.type;
        }
        if (e.sample_count <= 1 && data.types[e.type].glyph == ElementGlyph::fish)
            write_glyph(out, num, px_size, e, style, colors[e.type]);
        else if (e.sample_count <= 1)
            write_disk(out, num, px_size, e, style, colors[e.type]);
        else
            write_polyline(out, num, px_size, data, e, style, colors[e.type], options.show_samples);
    }
    if (open_type >= 0) out << "</g>\n";
    out << "</g>\n";
    if (legend.height > 0.0) {
        // A white band under the domain's picture, then the legend in pixel units.
        out << "<rect x=\"" << num(f.lo.x) << "\" y=\"" << num(-f.lo.y) << "\" width=\"" << num(vw) << "\" height=\""
            << num(legend.height * px_size) << "\" fill=\"#ffffff\"/>\n";
        out << "<g transform=\"translate(" << num(f.lo.x) << " " << num(-f.lo.y) << ") scale(" << px_size << ")\">\n";
        write_legend_svg(out, legend);
        out << "</g>\n";
    }
    out << "</svg>\n";
    return out.str();
}

}  // namespace tessera::render
