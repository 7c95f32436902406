// tessera/geometry.hpp — elements with geometry (Discrete Element Textures, sections
// 5 and 6): after synthesis every output element is rebuilt as a triangle mesh from
// its samples, and the whole arrangement is written as one scene (OBJ, PLY, glTF).
//
// Conventions (docs/format.md, "Element geometry"):
// - An element type may name a mesh file (ElementType::mesh, OBJ or ASCII PLY). The
//   mesh is authored in the element's local frame: the frame whose origin is the
//   centroid of the element's samples and whose axes are those of orientation = identity.
//   A local point v lands at  position + scale * orientation.rotate(v).
// - The type's reference sample layout (ElementType::reference) is where the samples sit
//   in that local frame. When a type gives none, it is taken from the first element of
//   the type in the data (its samples brought back by the inverse of its pose).
// - Rigid types: the pose of an output element is the best-fit rotation and translation
//   (Kabsch) of the reference layout, scaled by the element's scale, onto its samples;
//   the mesh is instanced with it. When the element's own orientation fits as well (up
//   to rounding), it is kept, so data built consistently keep their pose exactly and a
//   twist that the samples leave free (samples on a line) comes from the element.
//   Single-sample elements are placed by their own pose.
// - Deformable types (rigid = false, spaghetti, bags): every mesh vertex follows the
//   samples by a smooth deformation: each sample gets the best-fit rotation of its
//   neighbouring samples (reference -> output; a Kabsch fit of all samples weighted by
//   the same Gaussian, which also gives the motion's translation), and a vertex moves
//   with the Gaussian-weighted blend of the samples' rigid motions (linear blend
//   skinning with weights by distance to the reference samples; Gaussian width =
//   deform_falloff x the mean distance between consecutive reference samples). Small
//   per-sample translations are added so that the blend passes through the samples
//   (at an element's ends the one-sided neighbourhoods would miss them). What the
//   samples leave free (the turn of a single sample, the twist about a straight line of
//   samples) comes from the element's orientation. The result is a mesh of its own per
//   element.
// - Types without a mesh get a default shape: an icosphere of the element radius for
//   single-sample elements, a tube through the samples for multi-sample elements (the
//   radius). Without a radius, spheres get 0.5 and tubes 0.2 x the mean nearest-neighbour
//   distance between element centroids. The spheres of a type share one unit icosphere,
//   instanced with the radius as scale, so that instancing outputs (USD, glTF) carry them
//   as points; tubes follow their samples and are meshes of their own.
// 2D data are placed in the plane z = 0; their meshes are 3D (rotated about z).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tessera/exemplar.hpp"
#include "tessera/mesh.hpp"
#include "tessera/vec.hpp"

namespace tessera {

struct GeometryOptions {
    // Directory that relative ElementType::mesh paths are resolved against; "" = as given
    // (relative to the working directory). load() already resolves paths read from a file.
    std::string base_directory;
    // Default shapes: subdivisions of the icosphere (0..5) and sides of tubes (3..64).
    int sphere_subdivisions = 2;
    int tube_sides = 10;
    // Width of a sample's influence on the vertices of a deformable mesh, times the mean
    // distance between consecutive reference samples; > 0.
    double deform_falloff = 1.0;
};

struct SceneInstance {
    int element = -1;   // index into the data's elements
    std::uint64_t id = 0;  // that element's stable id (Element::id); written scenes name nodes by it
    int type = 0;       // index into Scene::type_names
    int mesh = 0;       // index into Scene::meshes
    // true: the mesh is the type's shared mesh, placed by the pose below;
    // false: the mesh is this element's own, already in world coordinates (deformed
    // meshes and default shapes), and the pose is informational.
    bool instanced = false;
    // Where the mesh's local origin lands: the samples' centroid when the reference
    // layout is centred (derived layouts are); a default sphere's sample.
    Vec3 position;
    Quat orientation;
    double scale = 1.0;      // the element's scale; a default sphere's radius
    double fit_error = 0.0;  // rigid: RMS distance between posed reference samples and the samples
    std::vector<double> attributes;  // the element's free attributes (Scene::attribute_names)
};

struct Scene {
    int dimension = 3;
    std::vector<std::string> type_names;
    std::vector<std::string> attribute_names;  // the data's free attributes, written by instancing formats
    std::vector<TriangleMesh> meshes;
    std::vector<SceneInstance> instances;  // one per element, in element order

    // The world-space mesh of instance i (its pose applied when instanced); Error(option)
    // for an index out of range.
    TriangleMesh world_mesh(int instance) const;
    // All instances in world space as one mesh; when `triangle_instance` is given it
    // receives the instance index of every triangle.
    TriangleMesh merged(std::vector<int>* triangle_instance = nullptr) const;
};

// Builds the scene of `data` (every element, in order). Throws Error(io) for a mesh
// file that cannot be read, Error(input) naming the type for a mesh with no triangles,
// a deformable type whose reference layout cannot be found, or a reference layout
// whose sample count differs from the type's elements; Error(option) for bad options.
Scene build_scene(const Exemplar& data, const GeometryOptions& options = {});

// True when `path` names a scene format: .obj, .gltf, .glb, .usda or .mesh.ply (a plain
// .ply is the point-instancing output of save()).
bool is_scene_path(const std::string& path);

// How glTF files place the instances of a shared mesh (docs/format.md, "glTF").
enum class GltfInstancing {
    gpu,    // one node per shared mesh with the EXT_mesh_gpu_instancing extension: per-instance
            // TRANSLATION, ROTATION, SCALE (and _ID) accessors; compact, for engines and viewers
            // that support the extension (it is listed as required)
    nodes,  // one node per element carrying its pose, for viewers without the extension
};

struct SceneWriteOptions {
    GltfInstancing gltf_instancing = GltfInstancing::gpu;  // .gltf / .glb only
};

// Writes the scene by extension, atomically:
//   .obj       one object (o) per element, grouped by type (g), shared vertices per element;
//   .mesh.ply  ASCII PLY with per-face `element` and `class` properties;
//   .gltf/.glb glTF 2.0: one mesh per shared mesh (a rigid type's, a type's default sphere),
//              its instances as EXT_mesh_gpu_instancing attributes of one node (gpu) or as
//              one node each with the pose (nodes); deformed meshes and tubes as meshes of
//              their own under untransformed nodes;
//   .usda      a USD layer: the instanced elements as one UsdGeomPointInstancer whose
//              prototypes are the shared meshes, the others as world-space Mesh prims.
// Throws Error(option) for another extension, Error(io) when it cannot write.
void write_scene(const Scene& scene, const std::string& path, const SceneWriteOptions& options = {});

}  // namespace tessera
