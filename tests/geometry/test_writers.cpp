// Scene writers (geometry.hpp): OBJ and .mesh.ply files read back with
// read_triangle_mesh give the merged scene, with objects, groups and per-face
// element / class properties; extensions choose the format.
#include <sstream>

#include "geometry_test_util.hpp"
#include "tessera/error.hpp"

using namespace geometry_test;

namespace {

class SceneWriters : public TempDir {
protected:
    Scene scene() { return build_scene(mixed_exemplar(write_mesh("tetra.obj", tetrahedron()))); }

    // Lines of `text` starting with `prefix`.
    static std::vector<std::string> lines(const std::string& text, const std::string& prefix) {
        std::vector<std::string> found;
        std::istringstream in(text);
        for (std::string line; std::getline(in, line);)
            if (line.rfind(prefix, 0) == 0) found.push_back(line);
        return found;
    }
};

}  // namespace

TEST_F(SceneWriters, ObjReadsBackAsTheMergedScene) {
    const Scene s = scene();
    write_scene(s, path("scene.obj"));
    const TriangleMesh merged = s.merged();
    const TriangleMesh back = read_triangle_mesh(path("scene.obj"));
    ASSERT_EQ(back.vertices.size(), merged.vertices.size());
    EXPECT_EQ(back.triangles, merged.triangles);
    EXPECT_EQ(max_distance(back.vertices, merged.vertices), 0.0);  // numbers round-trip exactly

    const std::string text = read("scene.obj");
    const auto objects = lines(text, "o ");
    ASSERT_EQ(objects.size(), s.instances.size());
    EXPECT_EQ(objects[0], "o shard_100");
    EXPECT_EQ(objects[3], "o worm_3");
    EXPECT_EQ(lines(text, "g shard").size(), 3u);
    EXPECT_EQ(lines(text, "g ball").size(), 2u);
}

TEST_F(SceneWriters, MeshPlyCarriesElementAndClassPerFace) {
    const Scene s = scene();
    write_scene(s, path("scene.MESH.ply"));  // extensions are case-insensitive
    std::vector<int> owner;
    const TriangleMesh merged = s.merged(&owner);
    const TriangleMesh back = read_triangle_mesh(path("scene.MESH.ply"));
    EXPECT_EQ(back.vertices.size(), merged.vertices.size());
    EXPECT_EQ(back.triangles, merged.triangles);

    const std::string text = read("scene.MESH.ply");
    for (const char* header : {"property list uchar int vertex_indices", "property int element", "property int class",
                               "comment class 1 worm"})
        EXPECT_NE(text.find(header), std::string::npos) << header;
    // After the header and the vertices, each face line: 3 i j k element class.
    std::istringstream body(text.substr(text.find("end_header\n") + 11));
    std::vector<std::string> faces;
    size_t row = 0;
    for (std::string line; std::getline(body, line); ++row)
        if (row >= merged.vertices.size()) faces.push_back(line);
    ASSERT_EQ(faces.size(), merged.triangles.size());
    for (size_t f = 0; f < faces.size(); f += 37) {
        std::istringstream in(faces[f]);
        int count, a, b, c, element, type;
        in >> count >> a >> b >> c >> element >> type;
        EXPECT_EQ(element, s.instances[owner[f]].element);
        EXPECT_EQ(type, s.instances[owner[f]].type);
    }
}

TEST_F(SceneWriters, ExtensionsChooseTheFormat) {
    EXPECT_TRUE(is_scene_path("a/b.obj"));
    EXPECT_TRUE(is_scene_path("x.GLTF"));
    EXPECT_TRUE(is_scene_path("x.glb"));
    EXPECT_TRUE(is_scene_path("x.mesh.ply"));
    EXPECT_FALSE(is_scene_path("x.ply"));  // save()'s point output
    EXPECT_FALSE(is_scene_path("x.json"));
    EXPECT_FALSE(is_scene_path(".obj.json"));
    try {
        write_scene(scene(), path("scene.stl"));
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::option);
        EXPECT_NE(std::string(e.what()).find("scene.stl"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(path("scene.stl")));
}

TEST_F(SceneWriters, UnwritableDirectoryLeavesNothing) {
    try {
        write_scene(scene(), path("missing/scene.gltf"));
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::io);
        EXPECT_NE(std::string(e.what()).find("missing/scene.gltf"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(path("missing")));
}
