// Placing and rasterizing the instances of a Scene (scene_raster.hpp).
#include "render/scene_raster.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "render/mesh_normals.hpp"
#include "tessera/error.hpp"

namespace tessera::render {
namespace {

// world = offset + c0 * v.x + c1 * v.y + c2 * v.z: the pose as a matrix, so each vertex
// costs one multiply instead of a quaternion rotation.
struct Placement {
    Vec3 c0{1, 0, 0}, c1{0, 1, 0}, c2{0, 0, 1}, offset;

    Vec3 apply(const Vec3& v) const { return offset + c0 * v.x + c1 * v.y + c2 * v.z; }
};

Placement placement_of(const SceneInstance& instance) {
    if (!instance.instanced) return {};  // already in world coordinates
    const Quat& q = instance.orientation;
    const double s = instance.scale;
    return {q.rotate({1, 0, 0}) * s, q.rotate({0, 1, 0}) * s, q.rotate({0, 0, 1}) * s, instance.position};
}

// A linear map as three rows.
struct Rows {
    Vec3 x, y, z;
    Vec3 apply(const Vec3& v) const { return {dot(x, v), dot(y, v), dot(z, v)}; }
};

// Rows taking local directions to view directions (x right, y up, z toward the viewer).
Rows view_rows(const Placement& p, const ScreenMap& m) {
    auto row = [&](const Vec3& axis) { return Vec3{dot(p.c0, axis), dot(p.c1, axis), dot(p.c2, axis)}; };
    return {row(m.right), row(m.up), row(m.toward)};
}

Vec3 unit_or_zero(const Vec3& v) {
    const double n = norm(v);
    return n > 0.0 && std::isfinite(n) ? v / n : Vec3{};
}

}  // namespace

void check_scene(const Scene& scene, int dimension) {
    if (scene.dimension != dimension)
        throw Error(ErrorKind::input, "render: the scene is " + std::to_string(scene.dimension) +
                                          "D but the data are " + std::to_string(dimension) + "D");
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        const int m = scene.instances[i].mesh;
        if (m < 0 || m >= static_cast<int>(scene.meshes.size()))
            throw Error(ErrorKind::input, "render: scene instance " + std::to_string(i) + " refers to mesh " +
                                              std::to_string(m) + ", which the scene does not have");
    }
}

Box scene_bounds(const Scene& scene) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    Box b{{inf, inf, inf}, {-inf, -inf, -inf}};
    for (const auto& instance : scene.instances) {
        const Placement p = placement_of(instance);
        for (const Vec3& v : scene.meshes[instance.mesh].vertices) {
            const Vec3 w = p.apply(v);
            if (!is_finite(w)) continue;
            for (int k = 0; k < 3; ++k) b.lo[k] = std::min(b.lo[k], w[k]), b.hi[k] = std::max(b.hi[k], w[k]);
        }
    }
    return b;
}

void rasterize_scene(const Scene& scene, const ScreenMap& map, MeshRaster& raster) {
    // Normals of a shared mesh are computed once; those of a mesh used once (deformed
    // meshes, default shapes) are not kept, so memory stays that of one mesh.
    std::vector<int> uses(scene.meshes.size(), 0);
    for (const auto& instance : scene.instances) ++uses[instance.mesh];
    std::vector<std::vector<Vec3>> shared(scene.meshes.size());
    std::vector<Vec3> single;
    std::vector<RasterVertex> points;  // the current mesh's vertices in picture space, reused

    for (size_t i = 0; i < scene.instances.size(); ++i) {
        const SceneInstance& instance = scene.instances[i];
        const TriangleMesh& mesh = scene.meshes[instance.mesh];
        const std::vector<Vec3>* normals = &single;  // 3 per triangle (corner_normals)
        if (uses[instance.mesh] > 1) {
            auto& cached = shared[instance.mesh];
            if (cached.empty() && !mesh.triangles.empty()) cached = corner_normals(mesh);
            normals = &cached;
        } else {
            single = corner_normals(mesh);
        }

        // Local point -> picture: the pose, then the camera, folded into one affine map.
        const Placement p = placement_of(instance);
        const Rows view = view_rows(p, map);
        const Vec3 sx = view.x * map.scale, sy = view.y * -map.scale;
        const double ox = (dot(p.offset, map.right) - map.x0) * map.scale;
        const double oy = (map.y1 - dot(p.offset, map.up)) * map.scale;
        const double oz = dot(p.offset, map.toward);

        points.resize(mesh.vertices.size());
        for (size_t v = 0; v < mesh.vertices.size(); ++v) {
            const Vec3& q = mesh.vertices[v];
            points[v] = {ox + dot(sx, q), oy + dot(sy, q), static_cast<float>(oz + dot(view.z, q))};
        }

        const int vertex_count = static_cast<int>(mesh.vertices.size());
        const int tag = static_cast<int>(i);
        for (size_t f = 0; f < mesh.triangles.size(); ++f) {
            const auto& t = mesh.triangles[f];
            if (t[0] < 0 || t[1] < 0 || t[2] < 0 || t[0] >= vertex_count || t[1] >= vertex_count ||
                t[2] >= vertex_count)
                continue;
            // The face normal in view coordinates, turned toward the viewer (two-sided
            // lighting). Computed from the local vertices in double precision: picture
            // depths are floats and too coarse for small faces.
            const Vec3& a = mesh.vertices[t[0]];
            Vec3 face = unit_or_zero(view.apply(cross(mesh.vertices[t[1]] - a, mesh.vertices[t[2]] - a)));
            if (face.z < 0.0) face = -face;
            RasterVertex c[3] = {points[t[0]], points[t[1]], points[t[2]]};
            for (int k = 0; k < 3; ++k) {
                Vec3 n = unit_or_zero(view.apply((*normals)[3 * f + k]));
                if (n.x == 0.0 && n.y == 0.0 && n.z == 0.0)
                    n = face;  // no corner normal (a face without area): the face's
                else if (dot(n, face) < 0.0)
                    n = -n;  // the corner normal belongs to the other side of this face
                c[k].nx = static_cast<float>(n.x), c[k].ny = static_cast<float>(n.y),
                c[k].nz = static_cast<float>(n.z);
            }
            raster.draw_triangle(c[0], c[1], c[2], tag);
        }
    }
}

}  // namespace tessera::render
