// Meshes shared by the tests: an icosphere (closed, outward, counter-clockwise).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "tessera/mesh.hpp"

namespace tessera::test {

// Icosphere of `radius` centred on the origin: an icosahedron whose triangles are split
// into four `levels` times, new vertices pushed out to the sphere; 20 * 4^levels triangles.
inline TriangleMesh icosphere(int levels, double radius = 1.0) {
    const double t = (1 + std::sqrt(5.0)) / 2;
    TriangleMesh m;
    m.vertices = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                  {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (Vec3& v : m.vertices) v = v * (1.0 / norm(v));
    m.triangles = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                   {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                   {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    for (int l = 0; l < levels; ++l) {
        std::map<std::pair<int, int>, int> mid;
        auto midpoint = [&](int a, int b) {
            const auto key = std::minmax(a, b);
            const auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            const Vec3 v = (m.vertices[a] + m.vertices[b]) * 0.5;
            m.vertices.push_back(v * (1.0 / norm(v)));
            return mid[key] = static_cast<int>(m.vertices.size()) - 1;
        };
        std::vector<std::array<int, 3>> next;
        for (const auto& f : m.triangles) {
            const int a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
            next.push_back({f[0], a, c}), next.push_back({f[1], b, a}), next.push_back({f[2], c, b});
            next.push_back({a, b, c});
        }
        m.triangles = std::move(next);
    }
    for (Vec3& v : m.vertices) v = v * radius;
    return m;
}

// Torus around the z axis: tube of radius `tube` whose centre circle has radius `ring`;
// `around` x `across` quads split into outward, counter-clockwise triangles. A mesh with
// a hole through it, whose inside a voxel grid gets wrong within a cell of the surface.
inline TriangleMesh torus(double ring, double tube, int around = 48, int across = 24) {
    TriangleMesh m;
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < across; ++j) {
            const double u = 2 * M_PI * i / around, v = 2 * M_PI * j / across;
            const double r = ring + tube * std::cos(v);
            m.vertices.push_back({r * std::cos(u), r * std::sin(u), tube * std::sin(v)});
        }
    const auto at = [&](int i, int j) { return (i % around) * across + (j % across); };
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < across; ++j) {
            m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return m;
}

}  // namespace tessera::test
