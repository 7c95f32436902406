// The colour of every class of one picture (tessera::type_colors) as the rasterizer's
// floating-point colours, and the test for "looks like the same colour" that keeps the
// palette clear of colours the data chose.
#pragma once

#include <vector>

#include "render/palette.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/render.hpp"

namespace tessera::render {

inline Rgb to_rgb(Color c) { return {c.r / 255.0f, c.g / 255.0f, c.b / 255.0f}; }

// type_colors(data) as Rgb, by type index.
std::vector<Rgb> class_colors(const Exemplar& data);

// True when a viewer would call `a` and `b` the same colour: saturated colours of
// nearly the same hue (within 30 degrees), or two greys of nearly the same lightness.
bool looks_alike(Rgb a, Rgb b);

}  // namespace tessera::render
