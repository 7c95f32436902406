// Test helpers for the render tests: decode PNG bytes with stb_image (from
// Debian's libstb), compare colours, build an icosphere.
#pragma once

#include "test_meshes.hpp"

#include <stb_image.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "render/palette.hpp"
#include "tessera/mesh.hpp"

namespace tessera::test {

struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb;

    render::Rgb at(int x, int y) const {
        const std::uint8_t* p = &rgb[(static_cast<size_t>(y) * width + x) * 3];
        return {p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f};
    }
};

inline bool has_png_signature(const std::string& bytes) {
    return bytes.size() > 8 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0;
}

// Decodes to 8-bit RGB; width 0 on failure.
inline Image decode_png(const std::string& bytes) {
    Image img;
    int channels = 0;
    unsigned char* data =
        stbi_load_from_memory(reinterpret_cast<const unsigned char*>(bytes.data()),
                              static_cast<int>(bytes.size()), &img.width, &img.height, &channels, 3);
    if (!data) return {};
    img.rgb.assign(data, data + static_cast<size_t>(img.width) * img.height * 3);
    stbi_image_free(data);
    return img;
}

// Largest component difference, in 8-bit steps.
inline int color_distance(render::Rgb a, render::Rgb b) {
    return static_cast<int>(
        std::lround(255.0 * std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)})));
}

// icosphere(levels, radius) comes from tests/test_meshes.hpp (same namespace).

}  // namespace tessera::test
