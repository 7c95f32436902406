// geometry/geometry_internal.hpp — the pieces build_scene and write_scene are made of,
// one file each under src/geometry/, declared here so that each can be tested and
// reused on its own. Private to the library.
#pragma once

#include <string>
#include <vector>

#include "tessera/exemplar.hpp"
#include "tessera/geometry.hpp"
#include "tessera/mesh.hpp"

namespace tessera::geometry {

// ---- default shapes (shapes.cpp) -------------------------------------------
// A sphere of `radius` around `center`: the icosahedron subdivided `subdivisions`
// times (20 * 4^s triangles), every vertex at exactly `radius`, outward-facing.
TriangleMesh icosphere(const Vec3& center, double radius, int subdivisions);
// A closed tube of `radius` along the polyline `points` (>= 2): a ring of `sides`
// vertices at every point, perpendicular to the local direction, with frames carried
// along by the smallest rotations (no twist), and a flat cap at each end.
// 2 * sides * (points - 1) + 2 * sides triangles.
TriangleMesh tube(const std::vector<Vec3>& points, double radius, int sides);

// ---- rigid elements (rigid_pose.cpp) ---------------------------------------
struct Pose {
    Vec3 position;  // where the local origin lands
    Quat orientation;
    double scale = 1.0;
    double fit_error = 0.0;  // RMS distance between the posed reference samples and the samples
};
// The pose placing `reference` (local frame) onto `samples` (n = reference.size()):
// scale = the element's scale, rotation and translation by Kabsch. The element's own
// orientation is kept when it fits as well as the Kabsch rotation (so consistent data
// keep their pose exactly, and a twist the samples leave free comes from the element).
Pose fit_rigid_pose(const std::vector<Vec3>& reference, const Vec3* samples, const Element& element,
                    int dimension);

// ---- deformable elements (deform.cpp) --------------------------------------
// Moves every vertex of `mesh` (local frame, where `reference` holds the samples) with
// the samples `samples` (world; as many as reference): the smooth deformation of
// geometry.hpp, after scaling the local frame by `scale`. `falloff` times the mean
// distance between consecutive reference samples is the Gaussian width. `orientation`
// (the element's) settles what the samples leave free: the turn of a single sample,
// the twist about a straight line of samples.
TriangleMesh deform_mesh(const TriangleMesh& mesh, const std::vector<Vec3>& reference, const Vec3* samples,
                         double scale, double falloff, int dimension, const Quat& orientation = {});

// ---- reference layouts and meshes of the types (type_geometry.cpp) --------------
struct TypeGeometry {
    bool has_mesh = false;
    TriangleMesh mesh;             // local frame
    std::vector<Vec3> reference;   // local frame; empty when the type has no mesh
};
// Loads every used type's mesh and finds its reference layout; throws as build_scene says.
std::vector<TypeGeometry> type_geometry(const Exemplar& data, const GeometryOptions& options);

// ---- vertex normals (normals.cpp) -------------------------------------------
// Area-weighted average of the adjacent triangles' normals, unit length; (0, 0, 1)
// for a vertex no triangle with an area touches.
std::vector<Vec3> vertex_normals(const TriangleMesh& mesh);

// ---- writers (write_obj.cpp, write_mesh_ply.cpp, write_gltf.cpp, write_usda.cpp) ----
// The name of an instance in written scenes: type name + "_" + element id.
std::string instance_name(const Scene& scene, int instance);
std::string to_obj(const Scene& scene);
std::string to_mesh_ply(const Scene& scene);
std::string to_gltf(const Scene& scene, bool binary, GltfInstancing instancing);
std::string to_usda(const Scene& scene);
// The /World/Elements PointInstancer prim of the instanced elements of `frames` (the same
// instances in every frame), poses as time samples at `codes` when there are several
// frames; the animated layer's part (write_usda_animated.cpp, animated_scene.hpp).
std::string usda_point_instancer(const std::vector<Scene>& frames, const std::vector<double>& codes);

}  // namespace tessera::geometry
