// 3D PNG preview: orthographic view (scene_3d.hpp), elements as shaded spheres and
// sheets as shaded surfaces (sheet_surface.hpp) drawn with a z-buffer, the domain box as
// thin grey edges hidden where elements are in front, supersampled (supersample.hpp); the
// legend strip below.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "render/class_colors.hpp"
#include "render/grid.hpp"
#include "render/hires_buffer.hpp"
#include "render/legend.hpp"
#include "render/palette.hpp"
#include "render/raster.hpp"
#include "render/render_internal.hpp"
#include "render/scene_3d.hpp"
#include "render/sheet_surface.hpp"
#include "render/style.hpp"
#include "render/supersample.hpp"

namespace tessera::render {
namespace {

void draw_sphere(HiResBuffer& buf, const View3D& view, const Frame3D& frame, double ss, const Sphere& s, Rgb color) {
    const double cx = frame.px(view, s.center) * ss, cy = frame.py(view, s.center) * ss;
    const double r = std::max(0.75, s.radius * frame.scale * ss);  // pixels
    const double depth = view.depth(s.center);
    const double depth_range = std::max(frame.near - frame.far, 1e-300);
    const Rgb base = s.marker ? darker(color, 0.6f) : color;
    const int x0 = std::max(0, static_cast<int>(std::floor(cx - r))), x1 = std::min(buf.width - 1, static_cast<int>(std::ceil(cx + r)));
    const int y0 = std::max(0, static_cast<int>(std::floor(cy - r))), y1 = std::min(buf.height - 1, static_cast<int>(std::ceil(cy + r)));
    for (int y = y0; y <= y1; ++y) {
        const double ny = (cy - (y + 0.5)) / r;  // view up
        for (int x = x0; x <= x1; ++x) {
            const double nx = (x + 0.5 - cx) / r;
            const double q = nx * nx + ny * ny;
            if (q > 1.0) continue;
            const double nz = std::sqrt(1.0 - q);
            const double z = depth + nz * s.radius;  // the sphere's front surface
            const size_t i = static_cast<size_t>(y) * buf.width + x;
            if (z <= buf.depth[i]) continue;
            buf.depth[i] = static_cast<float>(z);
            buf.color[i] = shade_sphere(base, {nx, ny, nz}, (frame.near - z) / depth_range);
        }
    }
}

}  // namespace

std::string render_png_3d(const Exemplar& data, const RenderOptions& options) {
    const Style style = make_style(data, options);
    const View3D view = View3D::standard();
    const std::vector<Sphere> spheres = collect_spheres(data, style, options.show_samples, true);
    const Frame3D frame = make_frame_3d(data, spheres, view, options);
    const std::vector<Rgb> colors = class_colors(data);
    const Legend legend = make_legend(data, colors, frame.width, options);
    check_picture_size(frame.width, frame.height + static_cast<int>(legend.height));
    const int ss = supersampling(frame.width, frame.height, sizeof(Rgb) + sizeof(float));
    HiResBuffer buf(frame.width * ss, frame.height * ss);
    for (const auto& s : spheres) draw_sphere(buf, view, frame, ss, s, colors[s.type]);
    draw_sheets(buf, data, view, frame, ss, colors);
    if (options.show_domain)
        for (const auto& [a, b] : box_edges(data.domain.bounds()))
            draw_hidden_edge(buf.color, buf.depth, buf.width, view, frame, ss, a, b);
    for (const auto& [a, b] : grid_lines(data.domain.bounds(), options.grid, 3))
        draw_hidden_edge(buf.color, buf.depth, buf.width, view, frame, ss, a, b);
    Canvas canvas = box_filter(buf.color, buf.width, ss);
    draw_legend_png(canvas, legend);
    return canvas.encode_png();
}

}  // namespace tessera::render
