// save() to .usda (src/geometry/write_usda.cpp through src/io/save.cpp), read back with
// the strict reader of usda_reader.hpp: the stage metadata, the prim types, one
// PointInstancer entry per instanced element with arrays of equal length, protoIndices
// within the prototypes, prototype targets that exist, unit quaternions written w first,
// values that round-trip at the precision of their USD types, and the elements that
// cannot be instanced as world-space meshes of their own.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>

#include "geometry/geometry_test_util.hpp"
#include "io/usda_reader.hpp"
#include "tessera/error.hpp"
#include "tessera/io.hpp"

using namespace geometry_test;
using usda_test::Layer;
using usda_test::Prim;
using usda_test::Value;

namespace {

const std::string examples = std::string(TESSERA_SOURCE_DIR) + "/examples/";

class SaveUsda : public TempDir {
protected:
    Layer save_and_read(const Exemplar& data, const std::string& name) {
        save(data, path(name));
        return usda_test::read_usda(read(name));
    }
};

const std::vector<Value>& items(const Prim& prim, const std::string& property) {
    return prim.property(property).value.items;
}

// The quaternion (w, x, y, z) of a tuple value.
Quat quat(const Value& v) {
    return {v.items[0].x, v.items[1].x, v.items[2].x, v.items[3].x};
}

double quat_norm(const Quat& q) {
    return std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
}

// Checks the layer's structure and the PointInstancer against `scene` (its instanced
// instances in element order); returns the instancer.
const Prim& check_instancer(const Layer& layer, const Scene& scene) {
    EXPECT_EQ(layer.metadata.at("upAxis").text, "Z");
    EXPECT_EQ(layer.metadata.at("metersPerUnit").x, 1.0);
    EXPECT_EQ(layer.metadata.at("defaultPrim").text, "World");
    const Prim* world = layer.find("/World");
    const Prim* found = layer.find("/World/Elements");
    if (!world || !found) throw std::runtime_error("no /World/Elements");
    EXPECT_EQ(world->type, "Xform");
    const Prim& instancer = *found;
    EXPECT_EQ(instancer.type, "PointInstancer");

    std::vector<const SceneInstance*> instanced;
    for (const SceneInstance& inst : scene.instances)
        if (inst.instanced) instanced.push_back(&inst);
    const size_t n = instanced.size();
    for (const char* array : {"positions", "orientations", "orientationsf", "scales", "protoIndices", "ids",
                              "primvars:tessera:class", "primvars:tessera:id"})
        EXPECT_EQ(items(instancer, array).size(), n) << array;
    EXPECT_EQ(instancer.property("orientations").type, "quath");
    EXPECT_EQ(instancer.property("orientationsf").type, "quatf");
    EXPECT_EQ(instancer.property("primvars:tessera:class").metadata.at("interpolation").text, "vertex");

    // Every prototype target is a Mesh under the instancer, in an `over`.
    const std::vector<Value>& targets = items(instancer, "prototypes");
    const Prim* prototypes = layer.find("/World/Elements/Prototypes");
    if (!prototypes) throw std::runtime_error("no /World/Elements/Prototypes");
    EXPECT_EQ(prototypes->specifier, "over");
    for (const Value& target : targets) {
        const Prim* mesh = layer.find(target.text);
        EXPECT_NE(mesh, nullptr) << target.text;
        if (!mesh) continue;
        EXPECT_EQ(mesh->type, "Mesh");
        EXPECT_EQ(target.text.rfind("/World/Elements/Prototypes/", 0), 0u);
    }
    const std::vector<Value>& class_names = items(instancer, "primvars:tessera:classNames");
    EXPECT_EQ(class_names.size(), scene.type_names.size());
    for (size_t i = 0; i < n; ++i) {
        const SceneInstance& inst = *instanced[i];
        const int proto = static_cast<int>(items(instancer, "protoIndices")[i].x);
        EXPECT_GE(proto, 0);
        EXPECT_LT(proto, static_cast<int>(targets.size()));
        // The prototype belongs to the instance's class.
        const Prim* mesh = layer.find(targets[proto].text);
        if (mesh) {
            EXPECT_EQ(mesh->property("tessera:className").value.text, scene.type_names[inst.type]);
        }
        EXPECT_EQ(items(instancer, "primvars:tessera:class")[i].x, inst.type);
        EXPECT_EQ(class_names[inst.type].text, scene.type_names[inst.type]);
        EXPECT_EQ(static_cast<std::uint64_t>(items(instancer, "ids")[i].x), inst.id);
        EXPECT_EQ(static_cast<std::uint64_t>(items(instancer, "primvars:tessera:id")[i].x), inst.id);
        // Values at the precision of their types: float, and half for quath.
        const Value& p = items(instancer, "positions")[i];
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(p.items[k].x, inst.position[k], 1e-6 * (1.0 + std::abs(inst.position[k])));
            EXPECT_NEAR(items(instancer, "scales")[i].items[k].x, inst.scale, 1e-6 * inst.scale);
        }
        const Quat qf = quat(items(instancer, "orientationsf")[i]),
                   qh = quat(items(instancer, "orientations")[i]);
        EXPECT_NEAR(quat_norm(qf), 1.0, 1e-6);
        EXPECT_NEAR(quat_norm(qh), 1.0, 2e-3);
        const Quat& q = inst.orientation;  // written (w, x, y, z)
        EXPECT_NEAR(qf.w, q.w, 1e-6);
        EXPECT_NEAR(qf.x, q.x, 1e-6);
        EXPECT_NEAR(qf.y, q.y, 1e-6);
        EXPECT_NEAR(qf.z, q.z, 1e-6);
        EXPECT_NEAR(qh.w, q.w, 2e-3);
        EXPECT_NEAR(qh.z, q.z, 2e-3);
    }
    return instancer;
}

// A Mesh prim holds a valid triangle mesh equal to `expected` at float precision.
void check_mesh(const Prim& mesh, const TriangleMesh& expected) {
    EXPECT_EQ(mesh.type, "Mesh");
    EXPECT_EQ(mesh.property("subdivisionScheme").value.text, "none");
    const std::vector<Value>& points = items(mesh, "points");
    ASSERT_EQ(points.size(), expected.vertices.size());
    EXPECT_EQ(items(mesh, "normals").size(), points.size());
    EXPECT_EQ(items(mesh, "faceVertexCounts").size(), expected.triangles.size());
    for (const Value& c : items(mesh, "faceVertexCounts")) EXPECT_EQ(c.x, 3);
    const std::vector<Value>& indices = items(mesh, "faceVertexIndices");
    ASSERT_EQ(indices.size(), 3 * expected.triangles.size());
    for (size_t t = 0; t < expected.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) EXPECT_EQ(indices[3 * t + k].x, expected.triangles[t][k]);
    const std::vector<Value>& extent = items(mesh, "extent");
    for (size_t v = 0; v < points.size(); ++v)
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(points[v].items[k].x, expected.vertices[v][k],
                        1e-6 * (1.0 + std::abs(expected.vertices[v][k])));
            EXPECT_GE(points[v].items[k].x, extent[0].items[k].x);
            EXPECT_LE(points[v].items[k].x, extent[1].items[k].x);
        }
}

}  // namespace

TEST_F(SaveUsda, ExampleSceneIsOnePointInstancer) {
    const Exemplar ex = load(examples + "scenes/bananas_3d.json");
    const Scene scene = build_scene(ex);
    const Layer layer = save_and_read(ex, "bananas.usda");
    const Prim& instancer = check_instancer(layer, scene);
    // Every banana is instanced: the arrays hold every element.
    EXPECT_EQ(items(instancer, "positions").size(), ex.elements.size());
    ASSERT_EQ(items(instancer, "prototypes").size(), 1u);
    const Prim* banana = layer.find("/World/Elements/Prototypes/banana");
    ASSERT_NE(banana, nullptr);
    check_mesh(*banana, scene.meshes[scene.instances[0].mesh]);
    EXPECT_EQ(layer.find("/World/Meshes"), nullptr);  // nothing left to write on its own
}

TEST_F(SaveUsda, DeformedMeshesAndTubesAreMeshesOfTheirOwn) {
    Exemplar ex = mixed_exemplar(write_mesh("tetra.obj", tetrahedron()));
    ex.attribute_names = {"hue", "class"};  // "class" clashes with the class primvar
    for (size_t e = 0; e < ex.elements.size(); ++e) ex.elements[e].attributes = {0.5 * double(e), 1.0};
    const Scene scene = build_scene(ex);
    Arrangement result;
    static_cast<Exemplar&>(result) = ex;
    const Layer layer = save_and_read(result, "mixed.usda");  // the Arrangement overload
    const Prim& instancer = check_instancer(layer, scene);
    EXPECT_EQ(items(instancer, "prototypes").size(), 2u);  // the shards' mesh and the balls' sphere
    EXPECT_EQ(items(instancer, "primvars:tessera:hue").size(), 5u);
    EXPECT_EQ(items(instancer, "primvars:tessera:class_2")[0].x, 1.0);

    const Prim* meshes = layer.find("/World/Meshes");
    ASSERT_NE(meshes, nullptr);
    EXPECT_EQ(items(instancer, "positions").size() + meshes->children.size(), ex.elements.size());
    std::set<std::uint64_t> ids;
    for (const Prim& mesh : meshes->children) {
        const std::uint64_t id = static_cast<std::uint64_t>(mesh.property("tessera:id").value.x);
        ids.insert(id);
        size_t i = 0;
        while (scene.instances[i].id != id) ++i;
        EXPECT_FALSE(scene.instances[i].instanced);
        EXPECT_EQ(mesh.name, ex.types[scene.instances[i].type].name + "_" + std::to_string(id));
        check_mesh(mesh, scene.world_mesh(static_cast<int>(i)));
    }
    EXPECT_EQ(ids.size(), 3u);  // two worms and the rope
}

TEST_F(SaveUsda, NamesBecomeUniqueIdentifiersAnd2DLiesInThePlane) {
    Exemplar ex;
    ex.dimension = 2;
    ex.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    const std::vector<std::string> names = {"big rock", "big_rock", "3d", "say \"hi\""};
    for (size_t t = 0; t < names.size(); ++t) {
        const int e = ex.add_element(ex.type_index(names[t]), {{1.0 + 2.0 * double(t), 2.0, 0.0}}, 0.25);
        ex.elements[e].orientation = Quat::from_angle_z(0.3 * double(t));
    }
    const Scene scene = build_scene(ex);
    const Layer layer = save_and_read(ex, "names.USDA");  // extensions are case-insensitive
    const Prim& instancer = check_instancer(layer, scene);
    std::vector<std::string> prototypes;
    for (const Value& target : items(instancer, "prototypes")) prototypes.push_back(target.text);
    const std::string base = "/World/Elements/Prototypes/";
    EXPECT_EQ(prototypes, (std::vector<std::string>{base + "big_rock", base + "big_rock_2", base + "_3d",
                                                    base + "say__hi_"}));
    for (size_t t = 0; t < names.size(); ++t)
        EXPECT_EQ(items(instancer, "primvars:tessera:classNames")[t].text, names[t]);  // kept as written
    for (const Value& p : items(instancer, "positions")) EXPECT_EQ(p.items[2].x, 0.0);
    for (const Value& s : items(instancer, "scales")) EXPECT_EQ(s.items[0].x, 0.25);  // a sphere's radius
}

TEST_F(SaveUsda, IdsBeyondInt64AreAnErrorNamingTheFile) {
    Exemplar ex;
    ex.add_element(ex.type_index("dot"), {{0.5, 0.5, 0}}, 0.1);
    ex.elements[0].id = std::uint64_t(1) << 63;
    try {
        save(ex, path("big.usda"));
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::input);
        EXPECT_NE(std::string(e.what()).find("big.usda"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("9223372036854775808"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(path("big.usda")));
    ex.elements[0].id = (std::uint64_t(1) << 63) - 1;  // the largest int64 is fine
    EXPECT_NE(save_and_read(ex, "max.usda").find("/World/Elements"), nullptr);
}
