// Style and 2D frame of the preview pictures (see style.hpp).
#include "render/style.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "tessera/error.hpp"
#include "tessera/metrics.hpp"

namespace tessera::render {

Style make_style(const Exemplar& data, const RenderOptions& options) {
    Style s;
    double spacing = options.spacing;
    if (!(spacing > 0.0) && data.elements.size() >= 2) spacing = nearest_neighbor_distances(data).mean;
    if (!(spacing > 0.0)) {
        // One element, or all at one spot: size elements from the domain instead.
        const Vec3 size = data.domain.bounds().size();
        double side = std::numeric_limits<double>::infinity();
        for (int k = 0; k < data.dimension; ++k) side = std::min(side, size[k]);
        spacing = 0.1 * side;
    }
    s.spacing = spacing;
    s.default_radius = 0.4 * spacing;
    s.line_half_width = 0.125 * spacing;
    return s;
}

void check_drawable(const Exemplar& data) {
    auto fail = [](const std::string& what) { throw Error(ErrorKind::input, "render: " + what); };
    if (data.dimension != 2 && data.dimension != 3) fail("dimension must be 2 or 3");
    if (data.domain.dimension() != data.dimension) fail("domain dimension differs from the data's dimension");
    for (size_t i = 0; i < data.elements.size(); ++i) {
        const auto& e = data.elements[i];
        const std::string which = "element " + std::to_string(i);
        if (e.type < 0 || e.type >= static_cast<int>(data.types.size())) fail(which + " has an unknown element type");
        if (e.first_sample < 0 || e.sample_count < 0 ||
            static_cast<size_t>(e.first_sample) + e.sample_count > data.samples.size())
            fail(which + " refers to samples that do not exist");
        if (!is_finite(e.position)) fail(which + " has a position that is not finite");
        for (int k = 0; k < e.sample_count; ++k)
            if (!is_finite(data.samples[e.first_sample + k].p)) fail(which + " has a sample that is not finite");
    }
}

void check_options(const RenderOptions& options) {
    if (options.width < min_width || options.width > max_size)
        throw Error(ErrorKind::option, "width: must be between " + std::to_string(min_width) + " and " +
                                           std::to_string(max_size) + " pixels, got " + std::to_string(options.width));
    if (!(options.grid >= 0.0) || !std::isfinite(options.grid))
        throw Error(ErrorKind::option, "grid: must be a spacing >= 0 (0 = no grid)");
}

void check_picture_size(int width, int height) {
    if (static_cast<double>(width) * height > max_pixels)
        throw Error(ErrorKind::option, "width: a " + std::to_string(width) + " x " + std::to_string(height) +
                                           " picture is too large (more than 64 million pixels); use a smaller width");
}

Frame2D make_frame_2d(const Exemplar& data, const Style& style, const RenderOptions& options) {
    Frame2D f;
    f.lo = data.domain.bounds().lo;
    f.hi = data.domain.bounds().hi;
    auto include = [&](const Vec3& p, double r) {
        if (!is_finite(p)) return;
        f.lo.x = std::min(f.lo.x, p.x - r), f.lo.y = std::min(f.lo.y, p.y - r);
        f.hi.x = std::max(f.hi.x, p.x + r), f.hi.y = std::max(f.hi.y, p.y + r);
    };
    if (options.view) f.lo = options.view->lo, f.hi = options.view->hi;
    for (const auto& e : data.elements) {
        if (options.view) break;
        if (e.sample_count <= 1) {
            include(e.position, style.radius_of(e));
            continue;
        }
        for (int s = 0; s < e.sample_count; ++s) include(data.samples[e.first_sample + s].p, style.line_half_width);
    }
    const double margin = margin_fraction * std::max(f.hi.x - f.lo.x, f.hi.y - f.lo.y);
    f.lo.x -= margin, f.lo.y -= margin, f.hi.x += margin, f.hi.y += margin;
    f.width = options.width;
    f.scale = options.width / (f.hi.x - f.lo.x);
    const double height = std::round((f.hi.y - f.lo.y) * f.scale);
    if (height > max_size)
        throw Error(ErrorKind::option, "width: a " + std::to_string(options.width) + " pixel wide picture of this domain would be " +
                                           std::to_string(static_cast<long long>(height)) +
                                           " pixels tall (more than 16384); use a smaller width");
    f.height = std::max(1, static_cast<int>(height));
    check_picture_size(f.width, f.height);
    return f;
}

}  // namespace tessera::render
