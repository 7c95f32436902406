// geometry/gltf_model.hpp — building a tinygltf model from a Scene, shared by the two ways
// of placing instances (write_gltf.cpp: one node per element; write_gltf_instancing.cpp:
// EXT_mesh_gpu_instancing). Every buffer view is tightly packed (no byteStride), one per
// accessor, appended to the model's single buffer. Private to the library.
#pragma once

#include <string>
#include <vector>

#include "geometry/tinygltf.hpp"
#include "tessera/geometry.hpp"

namespace tessera::geometry::gltf {

// Appends raw bytes to buffer 0 and a buffer view over them; returns the view.
// `target` is TINYGLTF_TARGET_ARRAY_BUFFER / _ELEMENT_ARRAY_BUFFER, or 0 for data that
// is not a vertex attribute or index list (instance attributes).
int add_view(tinygltf::Model& model, const void* data, size_t bytes, int target);
int add_accessor(tinygltf::Model& model, int view, int component, int type, size_t count);
// A float accessor of `type` (TINYGLTF_TYPE_SCALAR, _VEC3, _VEC4) over `values`
// (count = values.size() / components), in a view with `target`.
int add_floats(tinygltf::Model& model, const std::vector<float>& values, int type, int target);
// One glTF mesh (one triangle primitive: POSITION with bounds, NORMAL, indices) of `material`.
int add_mesh(tinygltf::Model& model, const TriangleMesh& mesh, const std::string& name, int material);
// The material of type `type`: its preview colour, double-sided.
tinygltf::Material material(const std::string& name, int type);

// The glTF mesh of every scene mesh that instances share (-1 for the others), one per
// shared mesh in order of first use, named by the type.
std::vector<int> add_shared_meshes(tinygltf::Model& model, const Scene& scene);

// Adds one node per element, in element order, named type_id: elements whose mesh is
// shared (when `with_shared`) carry their pose as translation, rotation (x, y, z, w) and
// uniform scale; the others get a glTF mesh of their own (world coordinates) and no
// transform. Elements with a shared mesh are skipped when `with_shared` is false.
void add_element_nodes(tinygltf::Model& model, const Scene& scene, const std::vector<int>& shared,
                       bool with_shared);
// Adds one node per shared mesh, named by the type, with the EXT_mesh_gpu_instancing
// attributes of its instances (GltfInstancing::gpu), and lists the extension as used
// and required when there is such a node.
void add_instancing_nodes(tinygltf::Model& model, const Scene& scene, const std::vector<int>& shared);

// Adds the root node that turns tessera's z-up into glTF's y-up, parent of every node so
// far, and the scene holding it (the default scene).
void add_root(tinygltf::Model& model);

}  // namespace tessera::geometry::gltf
