// How elements are drawn, shared by the PNG and SVG writers so both pictures
// agree: the size of a disk with no radius (0.4 x mean nearest-neighbour
// distance: neighbours nearly touch but stay apart), the width of polylines,
// the orientation tick, and the 2D picture frame (view box in data units and
// the pixel mapping, y up in the data and down in the picture).
#pragma once

#include <cmath>

#include "tessera/exemplar.hpp"
#include "tessera/render.hpp"

namespace tessera::render {

inline constexpr int min_width = 16, max_size = 16384;  // pixels
inline constexpr double max_pixels = 64.0 * 1024 * 1024;  // about 1 GB of float canvas
inline constexpr double margin_fraction = 0.03;         // of the larger view side, on each side

struct Style {
    double spacing = 1.0;          // mean nearest-neighbour distance (fallback: 1/10 of the smallest domain side)
    double default_radius = 0.4;   // disk / sphere radius of elements with radius 0
    double line_half_width = 0.125;  // multi-sample elements: width 0.25 x spacing

    double radius_of(const Element& e) const { return e.radius > 0.0 ? e.radius : default_radius; }
};

Style make_style(const Exemplar& data, const RenderOptions& options);

// Throws Error(input) if the data cannot be drawn: dimension not 2 or 3, an
// unknown type, a sample run outside the samples, a non-finite position or sample.
void check_drawable(const Exemplar& data);

// Throws Error(option) when the requested width is outside [16, 16384].
void check_options(const RenderOptions& options);

// Throws Error(option) when width x height exceeds max_pixels.
void check_picture_size(int width, int height);

// True when the rotation differs from the identity (q and -q are the same rotation).
inline bool has_rotation(const Quat& q) { return std::abs(std::abs(q.w) - 1.0) > 1e-9; }

struct Frame2D {
    Vec3 lo, hi;          // view box in data units (domain + elements + margin)
    double scale = 1.0;   // pixels per data unit
    int width = 0, height = 0;

    double px(double x) const { return (x - lo.x) * scale; }
    double py(double y) const { return (hi.y - y) * scale; }
};

// Frame of a 2D picture `options.width` pixels wide. Throws Error(option) if the
// height the aspect ratio asks for exceeds 16384 pixels.
Frame2D make_frame_2d(const Exemplar& data, const Style& style, const RenderOptions& options);

}  // namespace tessera::render
