// glTF 2.0 output (geometry.hpp): the .gltf document parses, holds (with node-per-element
// instancing) one node per element with the pose of instanced ones, consistent accessors,
// buffer views and an embedded buffer whose positions lie within the accessors' bounds;
// the .glb container is sound. EXT_mesh_gpu_instancing: test_gltf_instancing.cpp.
#include <cstring>
#include <nlohmann/json.hpp>

#include "geometry_test_util.hpp"
#include "gltf_test_util.hpp"

using namespace geometry_test;
using namespace gltf_test;

namespace {

// Checks every accessor against its buffer view and the buffer, and the POSITION bounds
// and index ranges against the data in `buffer`.
void check_accessors(const Json& doc, const std::vector<unsigned char>& buffer) {
    const size_t buffer_length = doc["buffers"][0]["byteLength"];
    EXPECT_GE(buffer.size(), buffer_length);
    for (const Json& view : doc["bufferViews"]) {
        EXPECT_LE(view.value("byteOffset", 0u) + view["byteLength"].get<size_t>(), buffer_length);
    }
    for (const Json& mesh : doc["meshes"]) {
        const Json& primitive = mesh["primitives"][0];
        const Json& position = doc["accessors"][primitive["attributes"]["POSITION"].get<size_t>()];
        const Json& normal = doc["accessors"][primitive["attributes"]["NORMAL"].get<size_t>()];
        const Json& indices = doc["accessors"][primitive["indices"].get<size_t>()];
        const size_t vertices = position["count"];
        EXPECT_EQ(normal["count"], vertices);
        EXPECT_EQ(position["type"], "VEC3");
        EXPECT_EQ(position["componentType"], 5126);  // float
        EXPECT_EQ(indices["componentType"], 5125);   // unsigned int
        EXPECT_EQ(indices["count"].get<size_t>() % 3, 0u);
        for (const Json* a : {&position, &normal, &indices}) {
            const Json& view = doc["bufferViews"][(*a)["bufferView"].get<size_t>()];
            const size_t size = (*a)["type"] == "VEC3" ? 12 : 4;
            EXPECT_LE(a->value("byteOffset", 0u) + (*a)["count"].get<size_t>() * size, view["byteLength"].get<size_t>());
        }
        // The positions lie within min/max, and the indices within the vertices.
        const Json& pview = doc["bufferViews"][position["bufferView"].get<size_t>()];
        const size_t pstart = pview.value("byteOffset", 0u);
        for (size_t v = 0; v < vertices; ++v)
            for (int k = 0; k < 3; ++k) {
                float x;
                std::memcpy(&x, &buffer[pstart + 12 * v + 4 * k], 4);
                EXPECT_GE(x, position["min"][k].get<double>());
                EXPECT_LE(x, position["max"][k].get<double>());
            }
        const Json& iview = doc["bufferViews"][indices["bufferView"].get<size_t>()];
        for (size_t i = 0; i < indices["count"].get<size_t>(); ++i) {
            std::uint32_t index;
            std::memcpy(&index, &buffer[iview.value("byteOffset", 0u) + 4 * i], 4);
            EXPECT_LT(index, vertices);
        }
    }
}

class SceneGltf : public TempDir {};

}  // namespace

TEST_F(SceneGltf, DocumentHasOneNodePerElementAndConsistentBuffers) {
    const Exemplar ex = mixed_exemplar(write_mesh("tetra.obj", tetrahedron()));
    const Scene scene = build_scene(ex);
    write_scene(scene, path("scene.gltf"), {.gltf_instancing = GltfInstancing::nodes});
    const Json doc = Json::parse(read("scene.gltf"));
    EXPECT_EQ(doc["asset"]["version"], "2.0");
    const Json nodes = content_nodes(doc);
    ASSERT_EQ(nodes.size(), ex.elements.size());
    // One mesh for the rigid type with a mesh, one sphere for the balls, one each for the
    // two worms and the rope.
    EXPECT_EQ(doc["meshes"].size(), 1u + 1u + 3u);
    EXPECT_FALSE(doc.contains("extensionsUsed"));
    for (size_t i = 0; i < ex.elements.size(); ++i) {
        const Json& node = nodes[i];
        const SceneInstance& inst = scene.instances[i];
        EXPECT_EQ(node["name"], ex.types[ex.elements[i].type].name + "_" + std::to_string(ex.elements[i].id));
        if (!inst.instanced) {
            EXPECT_FALSE(node.contains("rotation"));
            continue;
        }
        EXPECT_EQ(node["mesh"], inst.type == 0 ? 0 : 1);  // the shards' mesh, the balls' sphere
        const Json& r = node["rotation"];  // glTF order: x, y, z, w
        EXPECT_EQ(r[0].get<double>(), inst.orientation.x);
        EXPECT_EQ(r[1].get<double>(), inst.orientation.y);
        EXPECT_EQ(r[2].get<double>(), inst.orientation.z);
        EXPECT_EQ(r[3].get<double>(), inst.orientation.w);
        EXPECT_EQ(node["translation"][0].get<double>(), inst.position.x);
        EXPECT_EQ(node["scale"][2].get<double>(), inst.scale);
    }
    const std::string uri = doc["buffers"][0]["uri"];
    const std::string prefix = "data:application/octet-stream;base64,";
    ASSERT_EQ(uri.rfind(prefix, 0), 0u);
    check_accessors(doc, base64_decode(uri.substr(prefix.size())));
}

TEST_F(SceneGltf, BinaryContainerIsSound) {
    const Scene scene = build_scene(mixed_exemplar(write_mesh("tetra.obj", tetrahedron())));
    write_scene(scene, path("scene.glb"));
    const std::string bytes = read("scene.glb");
    ASSERT_GE(bytes.size(), 28u);
    EXPECT_EQ(bytes.substr(0, 4), "glTF");
    EXPECT_EQ(u32(bytes, 4), 2u);             // version
    EXPECT_EQ(u32(bytes, 8), bytes.size());   // total length
    const std::uint32_t json_length = u32(bytes, 12);
    EXPECT_EQ(u32(bytes, 16), 0x4E4F534Au);   // "JSON"
    EXPECT_EQ(json_length % 4, 0u);
    const Json doc = Json::parse(bytes.substr(20, json_length));
    EXPECT_EQ(doc["asset"]["version"], "2.0");
    EXPECT_FALSE(doc["buffers"][0].contains("uri"));  // the buffer is the BIN chunk
    const size_t bin = 20 + json_length;
    ASSERT_LE(bin + 8, bytes.size());
    EXPECT_EQ(u32(bytes, bin + 4), 0x004E4942u);  // "BIN"
    EXPECT_EQ(bin + 8 + u32(bytes, bin), bytes.size());
    const std::vector<unsigned char> buffer(bytes.begin() + static_cast<long>(bin + 8), bytes.end());
    check_accessors(doc, buffer);
}
