// geometry/gltf_model.cpp — the buffer, accessor, mesh and material pieces of the glTF
// writers (gltf_model.hpp). Vertex data are written as float and indices as unsigned int;
// POSITION bounds come from the float values written, so they hold exactly for them.
#include "geometry/gltf_model.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <limits>

#include "geometry/geometry_internal.hpp"
#include "render/palette.hpp"

namespace tessera::geometry::gltf {

int add_view(tinygltf::Model& model, const void* data, size_t bytes, int target) {
    std::vector<unsigned char>& buffer = model.buffers.at(0).data;
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

int add_floats(tinygltf::Model& model, const std::vector<float>& values, int type, int target) {
    const size_t components =
        static_cast<size_t>(tinygltf::GetNumComponentsInType(static_cast<uint32_t>(type)));
    const int view = add_view(model, values.data(), values.size() * sizeof(float), target);
    return add_accessor(model, view, TINYGLTF_COMPONENT_TYPE_FLOAT, type, values.size() / components);
}

namespace {

std::vector<float> as_floats(const std::vector<Vec3>& v) {
    std::vector<float> data;
    data.reserve(v.size() * 3);
    for (const Vec3& p : v) data.insert(data.end(), {float(p.x), float(p.y), float(p.z)});
    return data;
}

}  // namespace

int add_mesh(tinygltf::Model& model, const TriangleMesh& mesh, const std::string& name, int material) {
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.material = material;
    const std::vector<float> positions = as_floats(mesh.vertices);
    const int position = add_floats(model, positions, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER);
    std::vector<double> lo(3, std::numeric_limits<double>::infinity()), hi(3, -lo[0]);
    for (size_t k = 0; k < positions.size(); ++k) {
        lo[k % 3] = std::min(lo[k % 3], double(positions[k]));
        hi[k % 3] = std::max(hi[k % 3], double(positions[k]));
    }
    model.accessors[position].minValues = lo;
    model.accessors[position].maxValues = hi;
    primitive.attributes["POSITION"] = position;
    primitive.attributes["NORMAL"] =
        add_floats(model, as_floats(vertex_normals(mesh)), TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER);
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
    const render::Rgb c = render::class_color(type);
    tinygltf::Material m;
    m.name = name;
    m.pbrMetallicRoughness.baseColorFactor = {c.r, c.g, c.b, 1.0};
    m.pbrMetallicRoughness.metallicFactor = 0.0;
    m.pbrMetallicRoughness.roughnessFactor = 0.7;
    m.doubleSided = true;  // authored meshes are not always consistently oriented
    return m;
}

std::vector<int> add_shared_meshes(tinygltf::Model& model, const Scene& scene) {
    std::vector<int> gltf_mesh(scene.meshes.size(), -1);
    for (const SceneInstance& inst : scene.instances)
        if (inst.instanced && gltf_mesh.at(static_cast<size_t>(inst.mesh)) < 0)
            gltf_mesh[inst.mesh] =
                add_mesh(model, scene.meshes[inst.mesh], scene.type_names.at(inst.type), inst.type);
    return gltf_mesh;
}

void add_element_nodes(tinygltf::Model& model, const Scene& scene, const std::vector<int>& shared,
                       bool with_shared) {
    for (int i = 0; i < static_cast<int>(scene.instances.size()); ++i) {
        const SceneInstance& inst = scene.instances[i];
        if (inst.instanced && !with_shared) continue;
        tinygltf::Node node;
        node.name = instance_name(scene, i);
        if (inst.instanced) {
            node.mesh = shared.at(static_cast<size_t>(inst.mesh));
            node.translation = {inst.position.x, inst.position.y, inst.position.z};
            node.rotation = {inst.orientation.x, inst.orientation.y, inst.orientation.z, inst.orientation.w};
            node.scale = {inst.scale, inst.scale, inst.scale};
        } else {
            node.mesh =
                add_mesh(model, scene.meshes.at(static_cast<size_t>(inst.mesh)), node.name, inst.type);
        }
        model.nodes.push_back(node);
    }
}

void add_root(tinygltf::Model& model) {
    tinygltf::Node up;
    up.name = "tessera z-up";
    up.rotation = {-std::sqrt(0.5), 0.0, 0.0, std::sqrt(0.5)};  // (x, y, z, w): -90 degrees about x
    up.children.resize(model.nodes.size());
    std::iota(up.children.begin(), up.children.end(), 0);
    model.nodes.push_back(up);
    tinygltf::Scene root;
    root.nodes = {static_cast<int>(model.nodes.size()) - 1};
    model.scenes.push_back(root);
    model.defaultScene = 0;
}

}  // namespace tessera::geometry::gltf
