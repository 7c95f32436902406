// Supersampling, hidden domain edges and the box filter (supersample.hpp).
#include "render/supersample.hpp"

#include <algorithm>
#include <cmath>

namespace tessera::render {

int supersampling(int width, int height, int bytes_per_sample) {
    return 4.0 * width * height * bytes_per_sample <= 1024.0 * 1024 * 1024 ? 2 : 1;
}

void draw_hidden_edge(std::vector<Rgb>& color, const std::vector<float>& depth, int width, const View3D& view,
                      const Frame3D& frame, int ss, const Vec3& a, const Vec3& b) {
    const int height = width > 0 ? static_cast<int>(color.size() / width) : 0;
    const double ax = frame.px(view, a) * ss, ay = frame.py(view, a) * ss;
    const double bx = frame.px(view, b) * ss, by = frame.py(view, b) * ss;
    const double da = view.depth(a), db = view.depth(b);
    const double hw = 0.7 * ss;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min(ax, bx) - hw - 1)));
    const int x1 = std::min(width - 1, static_cast<int>(std::ceil(std::max(ax, bx) + hw + 1)));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min(ay, by) - hw - 1)));
    const int y1 = std::min(height - 1, static_cast<int>(std::ceil(std::max(ay, by) + hw + 1)));
    const double ux = bx - ax, uy = by - ay, len2 = ux * ux + uy * uy;
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const double px = x + 0.5 - ax, py = y + 0.5 - ay;
            const double t = len2 > 0.0 ? std::clamp((px * ux + py * uy) / len2, 0.0, 1.0) : 0.0;
            const double d = std::hypot(px - t * ux, py - t * uy);
            const float c = static_cast<float>(std::clamp(hw - d + 0.5, 0.0, 1.0));
            const size_t i = static_cast<size_t>(y) * width + x;
            if (c <= 0.0f || da + t * (db - da) < depth[i]) continue;
            Rgb& p = color[i];
            p = {p.r + (outline_grey.r - p.r) * c, p.g + (outline_grey.g - p.g) * c,
                 p.b + (outline_grey.b - p.b) * c};
        }
}

Canvas box_filter(const std::vector<Rgb>& color, int width, int ss) {
    const int out_width = width / ss, out_height = static_cast<int>(color.size() / width) / ss;
    Canvas canvas(out_width, out_height, white);
    const float weight = 1.0f / static_cast<float>(ss * ss);
    for (int y = 0; y < out_height; ++y)
        for (int x = 0; x < out_width; ++x) {
            Rgb sum{0, 0, 0};
            for (int j = 0; j < ss; ++j)
                for (int i = 0; i < ss; ++i) {
                    const Rgb& c = color[static_cast<size_t>(y * ss + j) * width + (x * ss + i)];
                    sum.r += c.r, sum.g += c.g, sum.b += c.b;
                }
            canvas.set_pixel(x, y, {sum.r * weight, sum.g * weight, sum.b * weight});
        }
    return canvas;
}

}  // namespace tessera::render
