// The 3D preview scene: camera, element spheres, frame and shading (scene_3d.hpp).
#include "render/scene_3d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "render/palette.hpp"
#include "render/sheet_surface.hpp"
#include "tessera/error.hpp"

namespace tessera::render {

View3D View3D::standard() {
    constexpr double azimuth = 35.0 * std::numbers::pi / 180.0;
    constexpr double elevation = 25.0 * std::numbers::pi / 180.0;
    View3D v;
    v.toward = {std::sin(azimuth) * std::cos(elevation), -std::cos(azimuth) * std::cos(elevation), std::sin(elevation)};
    const Vec3 z_up{0.0, 0.0, 1.0};
    v.right = cross(-v.toward, z_up);  // forward x up
    v.right = v.right / norm(v.right);
    v.up = cross(v.right, -v.toward);
    return v;
}

namespace {

// A tube from a to b as overlapping spheres half a radius apart: the silhouette ripples by
// under 4% of the radius, invisible at preview sizes. b's own sphere is the caller's.
void add_tube(std::vector<Sphere>& spheres, const Vec3& a, const Vec3& b, double tube, int type) {
    const int steps = std::clamp(static_cast<int>(std::ceil(norm(b - a) / (0.5 * tube))), 1, 10000);
    for (int i = 0; i < steps; ++i) spheres.push_back({a + (b - a) * (double(i) / steps), tube, type, false});
}

// The border of a sheet's grid of samples, once round.
void add_sheet_border(std::vector<Sphere>& spheres, const Exemplar& data, const Element& e, double tube) {
    const int cols = data.types[e.type].sheet_columns, rows = e.sample_count / cols;
    const Sample* s = &data.samples[e.first_sample];
    std::vector<int> ring;
    for (int c = 0; c < cols; ++c) ring.push_back(c);
    for (int r = 1; r < rows; ++r) ring.push_back(r * cols + cols - 1);
    for (int c = cols - 2; c >= 0; --c) ring.push_back((rows - 1) * cols + c);
    for (int r = rows - 2; r >= 0; --r) ring.push_back(r * cols);
    for (size_t k = 0; k + 1 < ring.size(); ++k) add_tube(spheres, s[ring[k]].p, s[ring[k + 1]].p, tube, e.type);
}

}  // namespace

std::vector<Sphere> collect_spheres(const Exemplar& data, const Style& style, bool show_samples, bool sheet_borders) {
    std::vector<Sphere> spheres;
    spheres.reserve(data.elements.size());
    for (const auto& e : data.elements) {
        if (e.sample_count <= 1) {
            spheres.push_back({e.position, style.radius_of(e), e.type, false});
            continue;
        }
        const Sample* s = &data.samples[e.first_sample];
        if (sheet_borders && is_sheet(data, e)) {
            add_sheet_border(spheres, data, e, 0.25 * style.line_half_width);
        } else {
            for (int k = 0; k + 1 < e.sample_count; ++k)
                add_tube(spheres, s[k].p, s[k + 1].p, style.line_half_width, e.type);
            spheres.push_back({s[e.sample_count - 1].p, style.line_half_width, e.type, false});
        }
        if (show_samples)
            for (int k = 0; k < e.sample_count; ++k) spheres.push_back({s[k].p, 1.35 * style.line_half_width, e.type, true});
    }
    return spheres;
}

std::array<std::pair<Vec3, Vec3>, 12> box_edges(const Box& b) {
    auto corner = [&](int i) {
        return Vec3{(i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y, (i & 4) ? b.hi.z : b.lo.z};
    };
    std::array<std::pair<Vec3, Vec3>, 12> edges;
    int n = 0;
    for (int i = 0; i < 8; ++i)
        for (int bit = 1; bit < 8; bit <<= 1)
            if (!(i & bit)) edges[n++] = {corner(i), corner(i | bit)};
    return edges;
}

Frame3D make_frame_3d(const Exemplar& data, const std::vector<Sphere>& spheres, const View3D& view,
                      const RenderOptions& options) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    double x0 = inf, x1 = -inf, y0 = inf, y1 = -inf, near = -inf, far = inf;
    auto include = [&](const Vec3& p, double r) {
        if (!is_finite(p)) return;
        x0 = std::min(x0, view.sx(p) - r), x1 = std::max(x1, view.sx(p) + r);
        y0 = std::min(y0, view.sy(p) - r), y1 = std::max(y1, view.sy(p) + r);
        near = std::max(near, view.depth(p) + r), far = std::min(far, view.depth(p) - r);
    };
    if (options.view) {  // a fixed view (the frames of an animation): its box alone
        for (const auto& [a, b] : box_edges(*options.view)) include(a, 0.0), include(b, 0.0);
    } else {
        for (const auto& [a, b] : box_edges(data.domain.bounds())) include(a, 0.0), include(b, 0.0);
        for (const auto& s : spheres) include(s.center, s.radius);
    }
    const double margin = margin_fraction * std::max(x1 - x0, y1 - y0);
    Frame3D f;
    f.x0 = x0 - margin;
    f.y1 = y1 + margin;
    f.width = options.width;
    f.scale = options.width / (x1 - x0 + 2.0 * margin);
    f.near = near, f.far = far;
    const double height = std::round((y1 - y0 + 2.0 * margin) * f.scale);
    if (height > max_size)
        throw Error(ErrorKind::option, "width: a " + std::to_string(options.width) + " pixel wide view of this domain would be " +
                                           std::to_string(static_cast<long long>(height)) +
                                           " pixels tall (more than 16384); use a smaller width");
    f.height = std::max(1, static_cast<int>(height));
    check_picture_size(f.width, f.height);
    return f;
}

Rgb shade_sphere(Rgb base, const Vec3& n, double farness) {
    static const Vec3 light = Vec3{-0.4, 0.7, 0.6} / norm(Vec3{-0.4, 0.7, 0.6});
    static const Vec3 half = (light + Vec3{0, 0, 1}) / norm(light + Vec3{0, 0, 1});
    const float diffuse = static_cast<float>(std::max(0.0, dot(n, light)));
    const float specular = static_cast<float>(0.28 * std::pow(std::max(0.0, dot(n, half)), 48.0));
    const float lit = 0.32f + 0.68f * diffuse;
    const Rgb c{std::min(1.0f, base.r * lit + specular), std::min(1.0f, base.g * lit + specular),
                std::min(1.0f, base.b * lit + specular)};
    return toward_white(c, static_cast<float>(0.4 * std::clamp(farness, 0.0, 1.0)));
}

}  // namespace tessera::render
