// geometry/write_gltf.cpp — the scene as glTF 2.0 (.gltf with the buffer embedded as a
// base64 data URI, or binary .glb), through tinygltf. Shared meshes (a rigid type's mesh,
// a type's default sphere) are one glTF mesh each, their instances placed either by the
// EXT_mesh_gpu_instancing extension (write_gltf_instancing.cpp) or by one node per
// element (gltf_model.cpp); deformed meshes and tubes are meshes of their own under
// untransformed nodes. Each type gets a material coloured as in the previews.
// Coordinates are written as they are, without turning z-up data to glTF's +y up: the
// file holds the data's own frame, and viewers that assume +y up show z-up data lying on
// their side (docs/format.md, "glTF").
#include <numeric>
#include <sstream>

#include "geometry/geometry_internal.hpp"
#include "geometry/gltf_model.hpp"
#include "tessera/error.hpp"
#include "tessera/version.hpp"

namespace tessera::geometry {

std::string to_gltf(const Scene& scene, bool binary, GltfInstancing instancing) {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = std::string("tessera ") + version;
    model.buffers.resize(1);
    for (size_t t = 0; t < scene.type_names.size(); ++t)
        model.materials.push_back(gltf::material(scene.type_names[t], static_cast<int>(t)));

    const std::vector<int> shared = gltf::add_shared_meshes(model, scene);
    if (instancing == GltfInstancing::gpu) {
        gltf::add_instancing_nodes(model, scene, shared);
        gltf::add_element_nodes(model, scene, shared, /*with_shared=*/false);
    } else {
        gltf::add_element_nodes(model, scene, shared, /*with_shared=*/true);
    }

    tinygltf::Scene root;
    root.nodes.resize(model.nodes.size());
    std::iota(root.nodes.begin(), root.nodes.end(), 0);
    model.scenes.push_back(root);
    model.defaultScene = 0;

    std::ostringstream out;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, /*prettyPrint=*/!binary, /*writeBinary=*/binary))
        throw Error(ErrorKind::internal, "tinygltf could not serialise the scene");
    return out.str();
}

}  // namespace tessera::geometry
