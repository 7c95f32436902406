// 3D SVG preview: the projection of the 3D PNG (scene_3d.hpp) as vectors, in
// pixel coordinates. Spheres are circles painted back to front (the painter's
// algorithm stands in for the z-buffer) and filled with a radial gradient per
// class that imitates the PNG's shading; depth fog is quantised into a few
// gradient levels. Box edges behind the box centre go under the spheres, the
// others over them. The legend strip goes below (legend.hpp).
#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <sstream>
#include <tuple>
#include <utility>

#include "render/class_colors.hpp"
#include "render/legend.hpp"
#include "render/palette.hpp"
#include "render/render_internal.hpp"
#include "render/scene_3d.hpp"
#include "render/style.hpp"
#include "render/svg_writer.hpp"

namespace tessera::render {
namespace {

constexpr int fog_levels = 5;

std::string gradient_id(int type, bool marker, int level) {
    return "s" + std::to_string(type) + (marker ? "m" : "") + "f" + std::to_string(level);
}

void write_gradient(std::ostream& out, int type, Rgb color, bool marker, int level) {
    const Rgb base = marker ? darker(color, 0.6f) : color;
    const double farness = (level + 0.5) / fog_levels;
    const Vec3 light = Vec3{-0.4, 0.7, 0.6} / norm(Vec3{-0.4, 0.7, 0.6});
    const Vec3 lit = light;                                        // brightest point
    const Vec3 side = Vec3{0.0, 0.0, 1.0};                         // disc centre
    const Vec3 rim = Vec3{-light.x, -light.y, 0.0} / std::hypot(light.x, light.y);  // silhouette, away from the light
    // Focus of the gradient at the projected brightest point (SVG y points down).
    out << "<radialGradient id=\"" << gradient_id(type, marker, level) << "\" cx=\"0.5\" cy=\"0.5\" r=\"0.5\" fx=\""
        << 0.5 + 0.5 * light.x << "\" fy=\"" << 0.5 - 0.5 * light.y << "\">"
        << "<stop offset=\"0\" stop-color=\"" << to_hex(shade_sphere(base, lit, farness)) << "\"/>"
        << "<stop offset=\"0.45\" stop-color=\"" << to_hex(shade_sphere(base, side, farness)) << "\"/>"
        << "<stop offset=\"1\" stop-color=\"" << to_hex(shade_sphere(base, rim, farness)) << "\"/>"
        << "</radialGradient>\n";
}

}  // namespace

std::string render_svg_3d(const Exemplar& data, const RenderOptions& options) {
    const Style style = make_style(data, options);
    const View3D view = View3D::standard();
    const std::vector<Sphere> spheres = collect_spheres(data, style, options.show_samples);
    const Frame3D frame = make_frame_3d(data, spheres, view, options);
    const SvgNumbers num(1.0);
    const std::vector<Rgb> colors = class_colors(data);
    const Legend legend = make_legend(data, colors, frame.width, options);
    check_picture_size(frame.width, frame.height + static_cast<int>(legend.height));
    const int height = frame.height + static_cast<int>(legend.height);
    const double depth_range = std::max(frame.near - frame.far, 1e-300);
    auto fog_level = [&](const Sphere& s) {
        const double farness = (frame.near - (view.depth(s.center) + s.radius)) / depth_range;
        return std::clamp(static_cast<int>(farness * fog_levels), 0, fog_levels - 1);
    };

    // Painter's order: far to near; ties keep element order (stable sort).
    std::vector<int> order(spheres.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        return view.depth(spheres[a].center) < view.depth(spheres[b].center);
    });

    std::ostringstream out;
    out << svg_header(frame.width, height, "0 0 " + std::to_string(frame.width) + " " + std::to_string(height));
    std::set<std::tuple<int, bool, int>> used;
    for (const auto& s : spheres) used.insert({s.type, s.marker, fog_level(s)});
    out << "<defs>\n";
    for (const auto& [type, marker, level] : used) write_gradient(out, type, colors[type], marker, level);
    out << "</defs>\n";
    out << "<rect x=\"0\" y=\"0\" width=\"" << frame.width << "\" height=\"" << height << "\" fill=\"#ffffff\"/>\n";

    const Box& box = data.domain.bounds();
    const double centre_depth = view.depth(box.center());
    auto write_edges = [&](bool front) {
        if (!options.show_domain) return;
        out << "<g stroke=\"" << to_hex(outline_grey) << "\" stroke-width=\"1.4\" stroke-linecap=\"round\">\n";
        for (const auto& [a, b] : box_edges(box)) {
            if ((view.depth((a + b) * 0.5) > centre_depth) != front) continue;
            out << "<line x1=\"" << num(frame.px(view, a)) << "\" y1=\"" << num(frame.py(view, a)) << "\" x2=\""
                << num(frame.px(view, b)) << "\" y2=\"" << num(frame.py(view, b)) << "\"/>\n";
        }
        out << "</g>\n";
    };
    write_edges(false);
    for (const int i : order) {
        const Sphere& s = spheres[i];
        const double r = std::max(0.75, s.radius * frame.scale);
        out << "<circle cx=\"" << num(frame.px(view, s.center)) << "\" cy=\"" << num(frame.py(view, s.center))
            << "\" r=\"" << num(r) << "\" fill=\"url(#" << gradient_id(s.type, s.marker, fog_level(s)) << ")\"/>\n";
    }
    write_edges(true);
    if (legend.height > 0.0) {
        out << "<g transform=\"translate(0 " << frame.height << ")\">\n";
        write_legend_svg(out, legend);
        out << "</g>\n";
    }
    out << "</svg>\n";
    return out.str();
}

}  // namespace tessera::render
