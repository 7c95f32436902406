// geometry/write_gltf.cpp — the scene as glTF 2.0 (.gltf with the buffer embedded as a
// base64 data URI, or binary .glb), through tinygltf. Shared meshes (a rigid type's mesh,
// a type's default sphere) are one glTF mesh each, their instances placed either by the
// EXT_mesh_gpu_instancing extension (write_gltf_instancing.cpp) or by one node per
// element (gltf_model.cpp); deformed meshes and tubes are meshes of their own under
// untransformed nodes. Each type gets a material coloured as in the previews.
// glTF fixes +y up; tessera's data are z-up (2D data lie in the x-y plane). As DESIGN.md's
// "Frames and interchange" asks, the writer turns them: every node hangs under one root
// node whose rotation of -90 degrees about x takes +z to +y, so the element nodes keep the
// data's own coordinates (and ids, poses, instancing attributes stay as in the data) while
// viewers and importers (Blender's turns +y back to +z) show the scene upright.
#include <cmath>
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

    gltf::add_root(model);

    std::ostringstream out;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, /*prettyPrint=*/!binary, /*writeBinary=*/binary))
        throw Error(ErrorKind::internal, "tinygltf could not serialise the scene");
    return out.str();
}

}  // namespace tessera::geometry
