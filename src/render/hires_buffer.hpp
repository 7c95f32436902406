// The supersampled colour + depth buffer of the 3D PNG preview (render_3d.cpp): spheres
// (elements) and triangles (sheet surfaces, sheet_surface.cpp) are z-buffered into it.
#pragma once

#include <limits>
#include <vector>

#include "render/palette.hpp"

namespace tessera::render {

struct HiResBuffer {
    int width = 0, height = 0;
    std::vector<Rgb> color;
    std::vector<float> depth;  // larger = nearer; -inf = empty

    HiResBuffer(int w, int h)
        : width(w), height(h), color(static_cast<size_t>(w) * h, white),
          depth(static_cast<size_t>(w) * h, -std::numeric_limits<float>::infinity()) {}
};

}  // namespace tessera::render
