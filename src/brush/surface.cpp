// The surface of a surface canvas (brush/surface.hpp).
#include "brush/surface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/triangle_closest.hpp"
#include "tessera/error.hpp"

namespace tessera::brush {

namespace {

// Cells of the band's grid across its width (2 x thickness): enough that the voxel band's
// interpolated inside keeps the surface inside with room on both sides.
constexpr double kBandCells = 6.0;
constexpr double kMaxBandCells = 4.0e6;

Vec3 unit_or_zero(const Vec3& v) {
    const double n = norm(v);
    return n > 1e-300 ? v / n : Vec3{};
}


}  // namespace

Surface::Surface(const TriangleMesh& mesh, double thickness, const std::string& name)
    : mesh_(mesh), thickness_(thickness) {
    if (mesh.triangles.empty()) throw Error(ErrorKind::domain, "surface " + name + " has no triangles");
    if (!(thickness > 0.0) || !std::isfinite(thickness))
        throw Error(ErrorKind::domain, "surface " + name + ": the thickness must be a number > 0");
    vertex_normals_.assign(mesh.vertices.size(), Vec3{});
    for (const auto& t : mesh.triangles) {
        const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
        const Vec3 area_normal = cross(b - a, c - a);  // twice the area along the normal
        face_normals_.push_back(unit_or_zero(area_normal));
        for (int k = 0; k < 3; ++k) vertex_normals_[t[k]] += area_normal;
        const Vec3 centre = (a + b + c) / 3.0;
        centroids_.push_back(centre);
        for (const Vec3* v : {&a, &b, &c}) reach_ = std::max(reach_, norm(*v - centre));
    }
    for (Vec3& n : vertex_normals_) n = unit_or_zero(n);
    grid_.build(centroids_, std::max(reach_, 1e-6), 3);

    Box b{mesh.vertices.front(), mesh.vertices.front()};
    for (const Vec3& v : mesh.vertices)
        for (int a = 0; a < 3; ++a) b.lo[a] = std::min(b.lo[a], v[a]), b.hi[a] = std::max(b.hi[a], v[a]);
    const Vec3 margin{2 * thickness, 2 * thickness, 2 * thickness};
    const Box box{b.lo - margin, b.hi + margin};
    const Vec3 size = box.size();
    const double cell = std::max(2.0 * thickness / kBandCells, std::cbrt(size.x * size.y * size.z / kMaxBandCells));
    band_ = Domain::region(
        Domain::box(box.lo, box.hi, 3),
        [&](const Vec3& p) {
            // A point with no centroid near cannot be near the surface: skips the exact query.
            if (grid_.nearest(p, thickness + reach_, [](int) { return true; }) < 0) return false;
            return closest(p).distance <= thickness;
        },
        cell, "the band within " + std::to_string(thickness) + " of surface " + name);
}

SurfacePoint Surface::closest(const Vec3& p) const {
    // The closest triangle's centroid lies within (distance to it) + reach_ of p, and that
    // distance is at most the distance to the nearest centroid.
    const int near = grid_.nearest(p, std::numeric_limits<double>::infinity(), [](int) { return true; });
    const double bound = norm(centroids_[near] - p) + reach_;
    double best = std::numeric_limits<double>::infinity();
    int best_t = -1;
    std::array<double, 3> best_w{1, 0, 0};
    grid_.for_each_within(p, bound, [&](int t, double) {
        const auto& tri = mesh_.triangles[t];
        const Vec3 &a = mesh_.vertices[tri[0]], &b = mesh_.vertices[tri[1]], &c = mesh_.vertices[tri[2]];
        const auto w = core::closest_barycentric(p, a, b, c);
        const double d2 = squared_norm(a * w[0] + b * w[1] + c * w[2] - p);
        if (d2 < best || (d2 == best && t < best_t)) best = d2, best_t = t, best_w = w;
    });
    const auto& tri = mesh_.triangles[best_t];
    SurfacePoint out;
    out.p = mesh_.vertices[tri[0]] * best_w[0] + mesh_.vertices[tri[1]] * best_w[1] + mesh_.vertices[tri[2]] * best_w[2];
    out.normal = unit_or_zero(vertex_normals_[tri[0]] * best_w[0] + vertex_normals_[tri[1]] * best_w[1] +
                              vertex_normals_[tri[2]] * best_w[2]);
    if (out.normal == Vec3{}) out.normal = face_normals_[best_t];
    out.distance = std::sqrt(best);
    return out;
}

Vec3 tangent_direction(const Vec3& d, const Vec3& normal) {
    // frame_from_direction(d, normal) already falls back to a tangent when d is normal.
    return frame_from_direction(d, normal).rotate(Vec3{1, 0, 0});
}

OrientationField surface_field(const Surface& surface, const OrientationField& field) {
    const TriangleMesh& mesh = surface.mesh();
    std::vector<Vec3> directions;
    directions.reserve(mesh.vertices.size());
    for (const Vec3& v : mesh.vertices) {
        const SurfacePoint sp = surface.closest(v);
        const Vec3 d = field.active() ? field.direction(v) : Vec3{1, 0, 0};
        directions.push_back(tangent_direction(d, sp.normal));
    }
    return OrientationField::mesh_vertices(mesh, directions, "the stroke field on the surface");
}

}  // namespace tessera::brush
