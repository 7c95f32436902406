// glTF with EXT_mesh_gpu_instancing (GltfInstancing::gpu, the default): the extension is
// listed; every element is either one instance of an instancing node or a node of its
// own; every accessor fills its buffer view exactly; the instance attributes hold each
// instance's pose (ROTATION unit, x, y, z, w), id and free attributes; and the `nodes`
// fallback has one node per element and no extension.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "geometry_test_util.hpp"
#include "gltf_test_util.hpp"
#include "tessera/io.hpp"

using namespace geometry_test;
using namespace gltf_test;

namespace {

constexpr const char* instancing = "EXT_mesh_gpu_instancing";

size_t component_bytes(int component) {
    return component == 5126 || component == 5125 ? 4 : component == 5123 || component == 5122 ? 2 : 1;
}

size_t components(const std::string& type) {
    const std::map<std::string, size_t> n = {
        {"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4}, {"MAT4", 16}};
    return n.at(type);
}

// Every accessor's count x element size is its (tightly packed) view's byteLength, and
// every view lies within the buffer.
void expect_accessors_fill_their_views(const GltfFile& file) {
    const Json& doc = file.doc;
    const size_t buffer_length = doc["buffers"][0]["byteLength"];
    EXPECT_GE(file.buffer.size(), buffer_length);
    for (const Json& view : doc["bufferViews"]) {
        EXPECT_FALSE(view.contains("byteStride"));
        EXPECT_LE(view.value("byteOffset", size_t(0)) + view["byteLength"].get<size_t>(), buffer_length);
    }
    for (const Json& a : doc["accessors"]) {
        const Json& view = doc["bufferViews"][a["bufferView"].get<size_t>()];
        const size_t stride = components(a["type"]) * component_bytes(a["componentType"]);
        EXPECT_EQ(a["count"].get<size_t>() * stride, view["byteLength"].get<size_t>());
    }
}

// A scene of every kind of element, with a free attribute and large element ids.
Exemplar attributed(const std::string& mesh) {
    Exemplar ex = mixed_exemplar(mesh);
    ex.attribute_names = {"hue"};
    for (size_t e = 0; e < ex.elements.size(); ++e) ex.elements[e].attributes = {0.125 * double(e)};
    return ex;
}

class GltfInstancingTest : public TempDir {};

// Checks a gpu-instanced document against the scene it was written from.
void expect_instanced(const GltfFile& file, const Scene& scene, bool with_ids) {
    const Json& doc = file.doc;
    ASSERT_TRUE(doc.contains("extensionsUsed"));
    EXPECT_NE(std::find(doc["extensionsUsed"].begin(), doc["extensionsUsed"].end(), instancing),
              doc["extensionsUsed"].end());
    EXPECT_NE(std::find(doc["extensionsRequired"].begin(), doc["extensionsRequired"].end(), instancing),
              doc["extensionsRequired"].end());
    expect_accessors_fill_their_views(file);
    std::map<std::uint64_t, const SceneInstance*> by_id;
    for (const SceneInstance& inst : scene.instances) by_id[inst.id] = &inst;
    size_t instances = 0, plain = 0;
    for (const Json& node : content_nodes(doc)) {
        if (!node.contains("extensions")) {
            EXPECT_FALSE(node.contains("translation"));  // own meshes are in world coordinates
            ++plain;
            continue;
        }
        const Json& attributes = node["extensions"][instancing]["attributes"];
        const size_t t = attributes["TRANSLATION"], r = attributes["ROTATION"], s = attributes["SCALE"];
        const size_t n = doc["accessors"][t]["count"];
        instances += n;
        EXPECT_EQ(doc["accessors"][t]["type"], "VEC3");
        EXPECT_EQ(doc["accessors"][r]["type"], "VEC4");
        EXPECT_EQ(doc["accessors"][s]["type"], "VEC3");
        for (const size_t a : {t, r, s}) EXPECT_EQ(doc["accessors"][a]["componentType"], 5126);
        for (const auto& [name, index] : attributes.items()) {
            EXPECT_EQ(doc["accessors"][index.get<size_t>()]["count"], n) << name;  // same count for all
            EXPECT_TRUE(name == "TRANSLATION" || name == "ROTATION" || name == "SCALE" || name[0] == '_')
                << name;
        }
        ASSERT_EQ(attributes.contains("_ID"), with_ids);
        if (!with_ids) continue;
        const std::vector<float> translation = floats(file, t), rotation = floats(file, r),
                                 scale = floats(file, s);
        const std::vector<float> hue = floats(file, attributes["_HUE"]);
        const Json& ids_accessor = doc["accessors"][attributes["_ID"].get<size_t>()];
        EXPECT_EQ(ids_accessor["componentType"], 5125);
        const Json& ids_view = doc["bufferViews"][ids_accessor["bufferView"].get<size_t>()];
        for (size_t i = 0; i < n; ++i) {
            std::uint32_t id;
            std::memcpy(&id, file.buffer.data() + ids_view.value("byteOffset", size_t(0)) + 4 * i, 4);
            ASSERT_TRUE(by_id.count(id)) << id;
            const SceneInstance& inst = *by_id[id];
            EXPECT_TRUE(inst.instanced);
            EXPECT_EQ(node["name"], scene.type_names[inst.type]);
            const float* q = &rotation[4 * i];
            EXPECT_NEAR(std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]), 1.0, 1e-6);
            const double expected[4] = {inst.orientation.x, inst.orientation.y, inst.orientation.z,
                                        inst.orientation.w};
            for (int k = 0; k < 4; ++k) EXPECT_NEAR(q[k], expected[k], 1e-6);
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(translation[3 * i + k], inst.position[k], 1e-5);
                EXPECT_NEAR(scale[3 * i + k], inst.scale, 1e-6);
            }
            EXPECT_EQ(hue[i], float(inst.attributes[0]));
        }
    }
    EXPECT_EQ(instances + plain, scene.instances.size());
    size_t own = 0;
    for (const SceneInstance& inst : scene.instances) own += inst.instanced ? 0 : 1;
    EXPECT_EQ(plain, own);
}

}  // namespace

TEST_F(GltfInstancingTest, GpuInstancingCarriesEveryInstance) {
    const Exemplar ex = attributed(write_mesh("tetra.obj", tetrahedron()));
    const Scene scene = build_scene(ex);
    write_scene(scene, path("scene.gltf"));  // gpu is the default
    const GltfFile file = parse_gltf(read("scene.gltf"));
    expect_instanced(file, scene, true);
    // One instancing node each for the shards (a mesh type) and the balls (a default sphere).
    size_t instancing_nodes = 0;
    for (const Json& node : content_nodes(file.doc)) instancing_nodes += node.contains("extensions") ? 1 : 0;
    EXPECT_EQ(instancing_nodes, 2u);
}

TEST_F(GltfInstancingTest, SaveWritesBinaryInstancedGlbAndTheNodesFallback) {
    const Exemplar ex = attributed(write_mesh("tetra.obj", tetrahedron()));
    const Scene scene = build_scene(ex);
    save(ex, path("scene.GLB"));
    expect_instanced(parse_gltf(read("scene.GLB")), scene, true);

    SaveOptions options;
    options.gltf_instancing = GltfInstancing::nodes;
    save(ex, path("nodes.glb"), options);
    const GltfFile nodes = parse_gltf(read("nodes.glb"));
    expect_accessors_fill_their_views(nodes);
    EXPECT_FALSE(nodes.doc.contains("extensionsUsed"));
    EXPECT_FALSE(nodes.doc.contains("extensionsRequired"));
    const Json element_nodes = content_nodes(nodes.doc);
    ASSERT_EQ(element_nodes.size(), ex.elements.size());  // one node per element
    for (size_t i = 0; i < ex.elements.size(); ++i) {
        EXPECT_FALSE(element_nodes[i].contains("extensions"));
        EXPECT_EQ(element_nodes[i]["name"],
                  ex.types[ex.elements[i].type].name + "_" + std::to_string(ex.elements[i].id));
    }
}

TEST_F(GltfInstancingTest, IdsBeyond32BitsLeaveOutTheIdAttribute) {
    Exemplar ex = attributed(write_mesh("tetra.obj", tetrahedron()));
    ex.elements[0].id = std::uint64_t(std::numeric_limits<std::uint32_t>::max()) + 1;
    const Scene scene = build_scene(ex);
    write_scene(scene, path("scene.gltf"));
    expect_instanced(parse_gltf(read("scene.gltf")), scene, false);
}

TEST_F(GltfInstancingTest, SphereOnlyDataAreOneInstancingNodePerType) {
    Exemplar ex;
    ex.dimension = 2;
    ex.domain = Domain::box({0, 0, 0}, {4, 4, 0}, 2);
    for (int i = 0; i < 6; ++i)
        ex.add_element(ex.type_index(i % 2 ? "odd" : "even"), {{0.5 + 0.5 * i, 1, 0}}, 0.2);
    write_scene(build_scene(ex), path("dots.gltf"));
    const GltfFile file = parse_gltf(read("dots.gltf"));
    const Json nodes = content_nodes(file.doc);
    ASSERT_EQ(nodes.size(), 2u);
    EXPECT_EQ(file.doc["meshes"].size(), 2u);
    for (const Json& node : nodes) {
        const size_t t = node["extensions"][instancing]["attributes"]["TRANSLATION"];
        EXPECT_EQ(file.doc["accessors"][t]["count"], 3u);
        const std::vector<float> translation = floats(file, t);
        for (size_t i = 0; i < 3; ++i) EXPECT_EQ(translation[3 * i + 2], 0.0f);  // 2D: z = 0
    }
}
