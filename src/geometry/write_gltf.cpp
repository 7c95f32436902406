// geometry/write_gltf.cpp — the scene as glTF 2.0 (.gltf with the buffer embedded as a
// base64 data URI, or binary .glb), through tinygltf. Rigid types keep one mesh each,
// instanced by one node per element with the pose as translation / rotation / scale;
// deformed meshes and default shapes are meshes of their own under untransformed nodes.
// Each type gets a material coloured as in the previews. Coordinates are written as
// they are (glTF viewers take +y as up; tessera data often have z up).
#include <algorithm>
#include <cstring>
#include <limits>
#include <sstream>

#include "geometry/geometry_internal.hpp"
#include "geometry/tinygltf.hpp"
#include "render/palette.hpp"
#include "tessera/error.hpp"
#include "tessera/version.hpp"

namespace tessera::geometry {

namespace {

// Appends raw bytes to the buffer and a buffer view over them; returns the view.
int add_view(tinygltf::Model& model, const void* data, size_t bytes, int target) {
    std::vector<unsigned char>& buffer = model.buffers[0].data;
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = bytes;
    view.target = target;
    const auto* p = static_cast<const unsigned char*>(data);
    buffer.insert(buffer.end(), p, p + bytes);
    model.bufferViews.push_back(view);
    return static_cast<int>(model.bufferViews.size()) - 1;
}

int add_accessor(tinygltf::Model& model, int view, int component, int type, size_t count) {
    tinygltf::Accessor a;
    a.bufferView = view;
    a.byteOffset = 0;
    a.componentType = component;
    a.type = type;
    a.count = count;
    model.accessors.push_back(a);
    return static_cast<int>(model.accessors.size()) - 1;
}

// A float VEC3 accessor over `v`; with `bounds`, its min and max (required for POSITION).
int add_vec3(tinygltf::Model& model, const std::vector<Vec3>& v, bool bounds) {
    std::vector<float> data;
    data.reserve(v.size() * 3);
    for (const Vec3& p : v) data.insert(data.end(), {float(p.x), float(p.y), float(p.z)});
    const int view = add_view(model, data.data(), data.size() * sizeof(float), TINYGLTF_TARGET_ARRAY_BUFFER);
    const int index = add_accessor(model, view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, v.size());
    if (bounds) {
        // From the float values written, so that the bounds hold exactly for them.
        std::vector<double> lo(3, std::numeric_limits<double>::infinity()), hi(3, -lo[0]);
        for (size_t k = 0; k < data.size(); ++k) {
            lo[k % 3] = std::min(lo[k % 3], double(data[k]));
            hi[k % 3] = std::max(hi[k % 3], double(data[k]));
        }
        model.accessors[index].minValues = lo;
        model.accessors[index].maxValues = hi;
    }
    return index;
}

// One glTF mesh (one triangle primitive) from a scene mesh.
int add_mesh(tinygltf::Model& model, const TriangleMesh& mesh, const std::string& name, int material) {
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.material = material;
    primitive.attributes["POSITION"] = add_vec3(model, mesh.vertices, true);
    primitive.attributes["NORMAL"] = add_vec3(model, vertex_normals(mesh), false);
    std::vector<std::uint32_t> indices;
    indices.reserve(mesh.triangles.size() * 3);
    for (const auto& t : mesh.triangles)
        indices.insert(indices.end(), {std::uint32_t(t[0]), std::uint32_t(t[1]), std::uint32_t(t[2])});
    const int view = add_view(model, indices.data(), indices.size() * sizeof(std::uint32_t),
                              TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    primitive.indices =
        add_accessor(model, view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, indices.size());
    tinygltf::Mesh m;
    m.name = name;
    m.primitives.push_back(primitive);
    model.meshes.push_back(m);
    return static_cast<int>(model.meshes.size()) - 1;
}

tinygltf::Material material(const std::string& name, int type) {
    const render::Rgb c = render::tableau10[static_cast<size_t>(type) % render::tableau10.size()];
    tinygltf::Material m;
    m.name = name;
    m.pbrMetallicRoughness.baseColorFactor = {c.r, c.g, c.b, 1.0};
    m.pbrMetallicRoughness.metallicFactor = 0.0;
    m.pbrMetallicRoughness.roughnessFactor = 0.7;
    m.doubleSided = true;  // authored meshes are not always consistently oriented
    return m;
}

}  // namespace

std::string to_gltf(const Scene& scene, bool binary) {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = std::string("tessera ") + version;
    model.buffers.resize(1);
    for (size_t t = 0; t < scene.type_names.size(); ++t)
        model.materials.push_back(material(scene.type_names[t], static_cast<int>(t)));

    // Scene meshes shared by instances become one glTF mesh each, named by type.
    std::vector<int> gltf_mesh(scene.meshes.size(), -1);
    for (const SceneInstance& inst : scene.instances)
        if (inst.instanced && gltf_mesh[inst.mesh] < 0)
            gltf_mesh[inst.mesh] = add_mesh(model, scene.meshes[inst.mesh], scene.type_names[inst.type], inst.type);

    tinygltf::Scene root;
    for (int i = 0; i < static_cast<int>(scene.instances.size()); ++i) {
        const SceneInstance& inst = scene.instances[i];
        tinygltf::Node node;
        node.name = instance_name(scene, i);
        if (inst.instanced) {
            node.mesh = gltf_mesh[inst.mesh];
            node.translation = {inst.position.x, inst.position.y, inst.position.z};
            node.rotation = {inst.orientation.x, inst.orientation.y, inst.orientation.z, inst.orientation.w};
            node.scale = {inst.scale, inst.scale, inst.scale};
        } else {
            node.mesh = add_mesh(model, scene.meshes[inst.mesh], node.name, inst.type);
        }
        model.nodes.push_back(node);
        root.nodes.push_back(i);
    }
    model.scenes.push_back(root);
    model.defaultScene = 0;

    std::ostringstream out;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, /*prettyPrint=*/!binary, /*writeBinary=*/binary))
        throw Error(ErrorKind::internal, "tinygltf could not serialise the scene");
    return out.str();
}

}  // namespace tessera::geometry
