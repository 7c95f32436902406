// geometry/write_gltf_instancing.cpp — GltfInstancing::gpu: the instances of each shared
// mesh as one node with the EXT_mesh_gpu_instancing extension (Khronos, ratified), whose
// per-instance accessors TRANSLATION (float VEC3), ROTATION (float VEC4, unit quaternion
// x, y, z, w), SCALE (float VEC3) place the mesh like the node-per-element fallback would.
// Application attributes ride along as the extension allows (names start with '_'):
// _ID, the element ids (unsigned int, written when every id of the scene fits in 32 bits,
// as in the extension's own _ID sample), and _<NAME> per free attribute (float).
// The extension is listed as used and, as the extension says files using it should, as
// required: a viewer without it then refuses the file instead of drawing each mesh once.
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>

#include "geometry/gltf_model.hpp"

namespace tessera::geometry::gltf {

namespace {

constexpr const char* extension_name = "EXT_mesh_gpu_instancing";

// "_" + the attribute's name in upper case, other characters than letters and digits as
// '_' (glTF attribute names are upper case by convention); clashes get a _2, _3... suffix.
std::vector<std::string> attribute_semantics(const std::vector<std::string>& names) {
    std::set<std::string> used = {"_ID"};
    std::vector<std::string> out;
    for (const std::string& name : names) {
        std::string base = "_";
        for (char c : name) base += std::isalnum(static_cast<unsigned char>(c)) ? char(std::toupper(c)) : '_';
        std::string unique = base;
        for (int n = 2; used.count(unique); ++n) unique = base + "_" + std::to_string(n);
        used.insert(unique);
        out.push_back(unique);
    }
    return out;
}

// The instance data of one shared mesh, in element order.
struct Instances {
    std::vector<float> translation, rotation, scale;
    std::vector<std::uint32_t> ids;
    std::vector<std::vector<float>> attributes;  // [attribute][instance]
};

Instances instances_of(const Scene& scene, int mesh) {
    Instances out;
    out.attributes.resize(scene.attribute_names.size());
    for (const SceneInstance& inst : scene.instances) {
        if (!inst.instanced || inst.mesh != mesh) continue;
        const Vec3& p = inst.position;
        out.translation.insert(out.translation.end(), {float(p.x), float(p.y), float(p.z)});
        // Normalised after the cast to float, as the extension asks of ROTATION.
        const Quat& q = inst.orientation;
        float r[4] = {float(q.x), float(q.y), float(q.z), float(q.w)};
        const float n = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
        for (float& c : r) c /= n;
        out.rotation.insert(out.rotation.end(), r, r + 4);
        const float s = float(inst.scale);
        out.scale.insert(out.scale.end(), {s, s, s});
        out.ids.push_back(static_cast<std::uint32_t>(inst.id));
        for (size_t a = 0; a < out.attributes.size(); ++a)
            out.attributes[a].push_back(float(inst.attributes.at(a)));
    }
    return out;
}

}  // namespace

void add_instancing_nodes(tinygltf::Model& model, const Scene& scene, const std::vector<int>& shared) {
    bool ids_fit = true;
    for (const SceneInstance& inst : scene.instances)
        ids_fit = ids_fit && inst.id <= std::numeric_limits<std::uint32_t>::max();
    const std::vector<std::string> semantics = attribute_semantics(scene.attribute_names);
    std::vector<int> type_of(shared.size(), -1);
    for (const SceneInstance& inst : scene.instances)
        if (inst.instanced) type_of.at(static_cast<size_t>(inst.mesh)) = inst.type;
    bool any = false;
    for (int mesh = 0; mesh < static_cast<int>(shared.size()); ++mesh) {
        if (shared[mesh] < 0) continue;
        const Instances data = instances_of(scene, mesh);
        tinygltf::Value::Object attributes;
        attributes["TRANSLATION"] =
            tinygltf::Value(add_floats(model, data.translation, TINYGLTF_TYPE_VEC3, 0));
        attributes["ROTATION"] = tinygltf::Value(add_floats(model, data.rotation, TINYGLTF_TYPE_VEC4, 0));
        attributes["SCALE"] = tinygltf::Value(add_floats(model, data.scale, TINYGLTF_TYPE_VEC3, 0));
        if (ids_fit) {
            const int view = add_view(model, data.ids.data(), data.ids.size() * sizeof(std::uint32_t), 0);
            attributes["_ID"] = tinygltf::Value(add_accessor(
                model, view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, data.ids.size()));
        }
        for (size_t a = 0; a < semantics.size(); ++a)
            attributes[semantics[a]] =
                tinygltf::Value(add_floats(model, data.attributes[a], TINYGLTF_TYPE_SCALAR, 0));
        tinygltf::Value::Object extension;
        extension["attributes"] = tinygltf::Value(std::move(attributes));
        tinygltf::Node node;
        node.name = scene.type_names.at(static_cast<size_t>(type_of[mesh]));
        node.mesh = shared[mesh];
        node.extensions[extension_name] = tinygltf::Value(std::move(extension));
        model.nodes.push_back(node);
        any = true;
    }
    if (any) {
        model.extensionsUsed.push_back(extension_name);
        model.extensionsRequired.push_back(extension_name);
    }
}

}  // namespace tessera::geometry::gltf
