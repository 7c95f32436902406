// geometry/shapes.cpp — the default shapes of element types that name no mesh:
// spheres for single-sample elements and tubes for multi-sample ones, so that every
// arrangement can be looked at in a 3D viewer without authoring any geometry.
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include "core/rigid_fit.hpp"
#include "geometry/geometry_internal.hpp"

namespace tessera::geometry {

TriangleMesh icosphere(const Vec3& center, double radius, int subdivisions) {
    // The icosahedron: vertices (0, +-1, +-g) and their cyclic permutations, g = golden ratio.
    const double g = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<Vec3> unit = {{-1, g, 0}, {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                              {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    for (Vec3& v : unit) v = v / norm(v);
    std::vector<std::array<int, 3>> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                             {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                             {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                             {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int level = 0; level < subdivisions; ++level) {
        // Each triangle becomes four; an edge's midpoint is shared by its two triangles.
        std::map<std::pair<int, int>, int> midpoint;
        const auto middle = [&](int a, int b) {
            const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
            const auto it = midpoint.find(key);
            if (it != midpoint.end()) return it->second;
            const Vec3 m = unit[a] + unit[b];
            unit.push_back(m / norm(m));
            return midpoint[key] = static_cast<int>(unit.size()) - 1;
        };
        std::vector<std::array<int, 3>> finer;
        finer.reserve(faces.size() * 4);
        for (const auto& f : faces) {
            const int ab = middle(f[0], f[1]), bc = middle(f[1], f[2]), ca = middle(f[2], f[0]);
            finer.push_back({f[0], ab, ca});
            finer.push_back({f[1], bc, ab});
            finer.push_back({f[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        faces = std::move(finer);
    }
    TriangleMesh mesh;
    mesh.vertices.reserve(unit.size());
    for (const Vec3& u : unit) mesh.vertices.push_back(center + u * radius);
    mesh.triangles = std::move(faces);
    return mesh;
}

namespace {

// Some unit vector perpendicular to the unit vector t (prefers +z for curves in the
// z = 0 plane, so that tubes of 2D data start their rings at the top).
Vec3 perpendicular(const Vec3& t) {
    Vec3 axis{0, 0, 1};
    if (std::abs(t.z) > 0.9) axis = {1, 0, 0};
    const Vec3 p = axis - t * dot(axis, t);
    return p / norm(p);
}

// Unit direction of each point: the bisector of its segments (zero-length segments
// borrow the nearest non-zero one; all points coinciding gives +x).
std::vector<Vec3> directions(const std::vector<Vec3>& points) {
    const int n = static_cast<int>(points.size());
    std::vector<Vec3> segment(n - 1);  // zero where two points coincide
    bool any = false;
    for (int i = 0; i + 1 < n; ++i) {
        const Vec3 d = points[i + 1] - points[i];
        if (norm(d) > 0.0) segment[i] = d / norm(d), any = true;
    }
    if (!any) return std::vector<Vec3>(n, Vec3{1, 0, 0});
    for (int i = 1; i + 1 < n; ++i)  // forward fill from the previous segment...
        if (norm(segment[i]) == 0.0) segment[i] = segment[i - 1];
    for (int i = n - 3; i >= 0; --i)  // ...then the leading zero ones from the next
        if (norm(segment[i]) == 0.0) segment[i] = segment[i + 1];
    std::vector<Vec3> out(n);
    out[0] = segment[0];
    out[n - 1] = segment[n - 2];
    for (int i = 1; i + 1 < n; ++i) {
        const Vec3 b = segment[i - 1] + segment[i];
        out[i] = norm(b) > 1e-12 ? b / norm(b) : segment[i];  // a hairpin: take the outgoing one
    }
    return out;
}

}  // namespace

TriangleMesh tube(const std::vector<Vec3>& points, double radius, int sides) {
    const int n = static_cast<int>(points.size());
    const std::vector<Vec3> t = directions(points);
    TriangleMesh mesh;
    mesh.vertices.reserve(n * sides + 2);
    Vec3 normal = perpendicular(t[0]);
    for (int i = 0; i < n; ++i) {
        // Parallel transport: the ring frame turns with the direction and never twists.
        if (i > 0) {
            normal = core::rotation_between(t[i - 1], t[i]).rotate(normal);
            normal = normal - t[i] * dot(normal, t[i]);
            normal = normal / norm(normal);
        }
        const Vec3 binormal = cross(t[i], normal);
        for (int k = 0; k < sides; ++k) {
            const double angle = 2.0 * std::numbers::pi * k / sides;
            mesh.vertices.push_back(points[i] + (normal * std::cos(angle) + binormal * std::sin(angle)) * radius);
        }
    }
    const auto ring = [sides](int i, int k) { return i * sides + (k % sides); };
    for (int i = 0; i + 1 < n; ++i)
        for (int k = 0; k < sides; ++k) {
            mesh.triangles.push_back({ring(i, k), ring(i, k + 1), ring(i + 1, k + 1)});
            mesh.triangles.push_back({ring(i, k), ring(i + 1, k + 1), ring(i + 1, k)});
        }
    // Caps: a fan around the end point, facing away from the tube.
    const int first = static_cast<int>(mesh.vertices.size());
    mesh.vertices.push_back(points[0]);
    mesh.vertices.push_back(points[n - 1]);
    for (int k = 0; k < sides; ++k) {
        mesh.triangles.push_back({first, ring(0, k + 1), ring(0, k)});
        mesh.triangles.push_back({first + 1, ring(n - 1, k), ring(n - 1, k + 1)});
    }
    return mesh;
}

}  // namespace tessera::geometry
