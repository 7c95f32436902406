// Canvas: analytic anti-aliasing (coverage = clamp(distance inside the edge
// + 0.5, 0, 1), a one-pixel linear ramp across the edge) and PNG encoding.
#include "render/raster.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <stb_image_write.h>

#include "tessera/error.hpp"

namespace tessera::render {
namespace {

float edge_coverage(double inside_distance) {
    return static_cast<float>(std::clamp(inside_distance + 0.5, 0.0, 1.0));
}

}  // namespace

Canvas::Canvas(int width, int height, Rgb background)
    : width_(width), height_(height), coverage_(static_cast<size_t>(width) * height, 0.0f) {
    rgb_.resize(static_cast<size_t>(width) * height * 3);
    for (size_t i = 0; i < rgb_.size(); i += 3) rgb_[i] = background.r, rgb_[i + 1] = background.g, rgb_[i + 2] = background.b;
}

void Canvas::add_rows(int rows, Rgb background) {
    if (rows <= 0) return;
    const size_t old = rgb_.size();
    height_ += rows;
    rgb_.resize(static_cast<size_t>(width_) * height_ * 3);
    coverage_.resize(static_cast<size_t>(width_) * height_, 0.0f);
    for (size_t i = old; i < rgb_.size(); i += 3) rgb_[i] = background.r, rgb_[i + 1] = background.g, rgb_[i + 2] = background.b;
}

void Canvas::cover(int index, float coverage) {
    float& c = coverage_[index];
    if (c == 0.0f) touched_.push_back(index);
    c = std::max(c, coverage);
}

void Canvas::add_disk(double cx, double cy, double radius) {
    if (!(radius > 0.0)) return;
    const int x0 = std::max(0, static_cast<int>(std::floor(cx - radius - 1.0)));
    const int x1 = std::min(width_ - 1, static_cast<int>(std::ceil(cx + radius + 1.0)));
    const int y0 = std::max(0, static_cast<int>(std::floor(cy - radius - 1.0)));
    const int y1 = std::min(height_ - 1, static_cast<int>(std::ceil(cy + radius + 1.0)));
    // A disk smaller than a pixel would lose its centre coverage; scale coverage by
    // its area instead so tiny elements fade rather than vanish.
    const float small = radius < 0.5 ? static_cast<float>(4.0 * radius * radius) : 1.0f;
    const double r = std::max(radius, 0.5);
    for (int y = y0; y <= y1; ++y) {
        const double dy = y + 0.5 - cy;
        for (int x = x0; x <= x1; ++x) {
            const double dx = x + 0.5 - cx;
            const float c = edge_coverage(r - std::sqrt(dx * dx + dy * dy)) * small;
            if (c > 0.0f) cover(y * width_ + x, c);
        }
    }
}

void Canvas::add_capsule(double ax, double ay, double bx, double by, double half_width) {
    if (!(half_width > 0.0)) return;
    const double hw = std::max(half_width, 0.5);
    const float thin = half_width < 0.5 ? static_cast<float>(2.0 * half_width) : 1.0f;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min(ax, bx) - hw - 1.0)));
    const int x1 = std::min(width_ - 1, static_cast<int>(std::ceil(std::max(ax, bx) + hw + 1.0)));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min(ay, by) - hw - 1.0)));
    const int y1 = std::min(height_ - 1, static_cast<int>(std::ceil(std::max(ay, by) + hw + 1.0)));
    const double ux = bx - ax, uy = by - ay;
    const double len2 = ux * ux + uy * uy;
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            // Distance from the pixel centre to the segment: project, clamp, measure.
            const double px = x + 0.5 - ax, py = y + 0.5 - ay;
            const double t = len2 > 0.0 ? std::clamp((px * ux + py * uy) / len2, 0.0, 1.0) : 0.0;
            const double dx = px - t * ux, dy = py - t * uy;
            const float c = edge_coverage(hw - std::sqrt(dx * dx + dy * dy)) * thin;
            if (c > 0.0f) cover(y * width_ + x, c);
        }
}

void Canvas::composite(Rgb color, float opacity) {
    for (const int i : touched_) {
        const float a = coverage_[i] * opacity;
        float* p = &rgb_[static_cast<size_t>(i) * 3];
        p[0] += (color.r - p[0]) * a;
        p[1] += (color.g - p[1]) * a;
        p[2] += (color.b - p[2]) * a;
        coverage_[i] = 0.0f;
    }
    touched_.clear();
}

Rgb Canvas::pixel(int x, int y) const {
    const float* p = &rgb_[(static_cast<size_t>(y) * width_ + x) * 3];
    return {p[0], p[1], p[2]};
}

void Canvas::set_pixel(int x, int y, Rgb c) {
    float* p = &rgb_[(static_cast<size_t>(y) * width_ + x) * 3];
    p[0] = c.r, p[1] = c.g, p[2] = c.b;
}

std::string Canvas::encode_png() const {
    std::vector<std::uint8_t> bytes(rgb_.size());
    for (size_t i = 0; i < rgb_.size(); ++i) bytes[i] = static_cast<std::uint8_t>(to_byte(rgb_[i]));
    std::string out;
    auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<size_t>(size));
    };
    if (!stbi_write_png_to_func(append, &out, width_, height_, 3, bytes.data(), width_ * 3))
        throw Error(ErrorKind::internal, "PNG encoding failed");
    return out;
}

}  // namespace tessera::render
