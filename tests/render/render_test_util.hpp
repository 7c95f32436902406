// Test helpers for the render tests: decode PNG bytes with stb_image (from
// Debian's libstb), compare colours, build an icosphere.
#pragma once

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

// An icosahedron centred on the origin, each triangle split into four `subdivisions`
// times with the new vertices pushed out to the sphere; outward counter-clockwise.
inline TriangleMesh icosphere(int subdivisions, double radius) {
    const double g = (1.0 + std::sqrt(5.0)) / 2.0;
    TriangleMesh m;
    m.vertices = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                  {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    m.triangles = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                   {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                   {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<int, int>, int> middle;
        auto mid = [&](int a, int b) {
            const auto key = std::minmax(a, b);
            if (const auto it = middle.find(key); it != middle.end()) return it->second;
            m.vertices.push_back((m.vertices[a] + m.vertices[b]) * 0.5);
            return middle[key] = static_cast<int>(m.vertices.size()) - 1;
        };
        std::vector<std::array<int, 3>> finer;
        for (const auto& [a, b, c] : m.triangles) {
            const int ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
            finer.insert(finer.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
        }
        m.triangles = std::move(finer);
    }
    for (Vec3& v : m.vertices) v = v * (radius / std::sqrt(dot(v, v)));
    return m;
}

}  // namespace tessera::test
