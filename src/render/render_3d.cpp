// 3D PNG preview: orthographic view (scene_3d.hpp), elements as shaded spheres
// drawn with a z-buffer, the domain box as thin grey edges hidden where spheres
// are in front. Rendered at 2x supersampling and box-filtered down, which
// anti-aliases sphere silhouettes without the coverage bookkeeping a z-buffer
// would otherwise need.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "render/palette.hpp"
#include "render/raster.hpp"
#include "render/render_internal.hpp"
#include "render/scene_3d.hpp"
#include "render/style.hpp"

namespace tessera::render {
namespace {

struct HiResBuffer {
    int width = 0, height = 0;
    std::vector<Rgb> color;
    std::vector<float> depth;  // larger = nearer; -inf = empty

    HiResBuffer(int w, int h)
        : width(w), height(h), color(static_cast<size_t>(w) * h, white),
          depth(static_cast<size_t>(w) * h, -std::numeric_limits<float>::infinity()) {}
};

void draw_sphere(HiResBuffer& buf, const View3D& view, const Frame3D& frame, double ss, const Sphere& s) {
    const double cx = frame.px(view, s.center) * ss, cy = frame.py(view, s.center) * ss;
    const double r = std::max(0.75, s.radius * frame.scale * ss);  // pixels
    const double depth = view.depth(s.center);
    const double depth_range = std::max(frame.near - frame.far, 1e-300);
    const Rgb base = s.marker ? darker(class_color(s.type), 0.6f) : class_color(s.type);
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

// A thin edge, depth-tested against the spheres, with coverage anti-aliasing.
void draw_edge(HiResBuffer& buf, const View3D& view, const Frame3D& frame, double ss, const Vec3& a, const Vec3& b) {
    const double ax = frame.px(view, a) * ss, ay = frame.py(view, a) * ss;
    const double bx = frame.px(view, b) * ss, by = frame.py(view, b) * ss;
    const double da = view.depth(a), db = view.depth(b);
    const double hw = 0.7 * ss;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min(ax, bx) - hw - 1)));
    const int x1 = std::min(buf.width - 1, static_cast<int>(std::ceil(std::max(ax, bx) + hw + 1)));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min(ay, by) - hw - 1)));
    const int y1 = std::min(buf.height - 1, static_cast<int>(std::ceil(std::max(ay, by) + hw + 1)));
    const double ux = bx - ax, uy = by - ay, len2 = ux * ux + uy * uy;
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const double px = x + 0.5 - ax, py = y + 0.5 - ay;
            const double t = len2 > 0.0 ? std::clamp((px * ux + py * uy) / len2, 0.0, 1.0) : 0.0;
            const double d = std::hypot(px - t * ux, py - t * uy);
            const float c = static_cast<float>(std::clamp(hw - d + 0.5, 0.0, 1.0));
            const size_t i = static_cast<size_t>(y) * buf.width + x;
            if (c <= 0.0f || da + t * (db - da) < buf.depth[i]) continue;
            Rgb& p = buf.color[i];
            p = {p.r + (outline_grey.r - p.r) * c, p.g + (outline_grey.g - p.g) * c, p.b + (outline_grey.b - p.b) * c};
        }
}

}  // namespace

std::string render_png_3d(const Exemplar& data, const RenderOptions& options) {
    const Style style = make_style(data);
    const View3D view = View3D::standard();
    const std::vector<Sphere> spheres = collect_spheres(data, style, options.show_samples);
    const Frame3D frame = make_frame_3d(data, spheres, view, options);
    // 2x2 supersampling unless the picture is already large (bounded memory).
    const int ss = static_cast<double>(frame.width) * frame.height <= 16.0 * 1024 * 1024 ? 2 : 1;
    HiResBuffer buf(frame.width * ss, frame.height * ss);
    for (const auto& s : spheres) draw_sphere(buf, view, frame, ss, s);
    if (options.show_domain)
        for (const auto& [a, b] : box_edges(data.domain.bounds())) draw_edge(buf, view, frame, ss, a, b);

    Canvas canvas(frame.width, frame.height, white);
    const float weight = 1.0f / static_cast<float>(ss * ss);
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x) {
            Rgb sum{0, 0, 0};
            for (int j = 0; j < ss; ++j)
                for (int i = 0; i < ss; ++i) {
                    const Rgb& c = buf.color[static_cast<size_t>(y * ss + j) * buf.width + (x * ss + i)];
                    sum.r += c.r, sum.g += c.g, sum.b += c.b;
                }
            canvas.set_pixel(x, y, {sum.r * weight, sum.g * weight, sum.b * weight});
        }
    return canvas.encode_png();
}

}  // namespace tessera::render
