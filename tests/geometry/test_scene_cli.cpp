// End to end: `tessera synth -o SCENE` and `tessera scene INPUT -o SCENE` write element
// geometry files a viewer can open, find meshes relative to the JSON file wherever the
// command runs, and on any error exit non-zero with one line and leave no file.
#include <stdlib.h>
#include <sys/wait.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>

#include "geometry_test_util.hpp"
#include "gltf_test_util.hpp"
#include "tessera/io.hpp"

using namespace geometry_test;

namespace {

struct CliRun {
    int code = -1;
    std::string err;
};

class SceneCli : public TempDir {
protected:
    void SetUp() override {
        TempDir::SetUp();
        fs::create_directories(dir_ / "in" / "meshes");
        fs::create_directories(dir_ / "out");
        write_mesh("in/meshes/tetra.obj", tetrahedron());
        // Meshes named relative to the JSON file, which the commands get by absolute path
        // while running in another directory.
        write("in/mix.json", R"({"format": "tessera", "version": 1, "dimension": 3,
            "domain": {"type": "box", "min": [0, 0, 0], "max": [6, 6, 6]},
            "types": [{"name": "shard", "mesh": "meshes/tetra.obj"},
                      {"name": "worm", "rigid": false, "mesh": "meshes/tetra.obj",
                       "reference": [[-0.5, 0, 0], [0, 0, 0], [0.5, 0, 0]]},
                      {"name": "ball"}],
            "elements": [
              {"type": "shard", "samples": [[1, 1, 1], [2, 1, 1], [1.5, 2, 1]]},
              {"type": "shard", "samples": [[4, 1, 1], [4, 2, 1], [3, 1.5, 1]]},
              {"type": "shard", "samples": [[1, 4, 2], [1, 4, 3], [1, 5, 2.5]]},
              {"type": "worm", "samples": [[3, 3, 3], [3.5, 3.3, 3], [4, 3, 3]]},
              {"type": "worm", "samples": [[2, 5, 5], [2.5, 5, 5], [3, 5.5, 5]]},
              {"type": "ball", "position": [5, 5, 1], "radius": 0.4},
              {"type": "ball", "position": [5, 3, 4], "radius": 0.3}]})");
    }

    // Runs `tessera <args>` from the system temporary directory.
    CliRun run(const std::string& args) const {
        const std::string err = path("stderr.txt");
        const std::string command = "cd '" + fs::temp_directory_path().string() + "' && '" +
                                    std::string(TESSERA_CLI) + "' " + args + " 2>'" + err + "'";
        const int status = std::system(command.c_str());
        CliRun r;
        r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        r.err = read("stderr.txt");
        fs::remove(err);
        return r;
    }
    std::string q(const std::string& name) const { return "'" + path(name) + "'"; }
    std::set<std::string> out_files() const {
        std::set<std::string> names;
        for (const auto& entry : fs::directory_iterator(dir_ / "out")) names.insert(entry.path().filename().string());
        return names;
    }
    void expect_failure(const CliRun& r, int code, const std::string& fragment) {
        EXPECT_EQ(r.code, code) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
        EXPECT_TRUE(out_files().empty()) << "a file was left behind";
    }
};

}  // namespace

TEST_F(SceneCli, SynthWritesAGltfThatParses) {
    const CliRun json = run("synth " + q("in/mix.json") + " -o " + q("out/result.json") + " --iterations 1 --seed 5 -q");
    ASSERT_EQ(json.code, 0) << json.err;
    const CliRun r = run("synth " + q("in/mix.json") + " -o " + q("out/result.gltf") + " --iterations 1 --seed 5");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("scene: "), std::string::npos) << r.err;
    const nlohmann::json doc = nlohmann::json::parse(read("out/result.gltf"));
    EXPECT_EQ(doc["asset"]["version"], "2.0");
    // Every element of the same synthesis: an instance of an instancing node (the shards,
    // the balls) or a node of its own (the worms).
    const Exemplar result = load(path("out/result.json"));
    size_t elements = 0;
    for (const auto& node : gltf_test::content_nodes(doc)) {
        if (!node.contains("extensions")) {
            ++elements;
            continue;
        }
        const auto& attributes = node["extensions"]["EXT_mesh_gpu_instancing"]["attributes"];
        elements += doc["accessors"][attributes["TRANSLATION"].get<size_t>()]["count"].get<size_t>();
    }
    EXPECT_EQ(elements, result.elements.size());
    // The fallback: one node per element.
    const CliRun nodes = run("synth " + q("in/mix.json") + " -o " + q("out/nodes.gltf") +
                             " --iterations 1 --seed 5 -q --gltf-instancing nodes");
    ASSERT_EQ(nodes.code, 0) << nodes.err;
    EXPECT_EQ(gltf_test::content_nodes(nlohmann::json::parse(read("out/nodes.gltf"))).size(), result.elements.size());
    // The saved arrangement names the mesh relative to itself, so it rebuilds too.
    EXPECT_NE(read("out/result.json").find(R"("mesh":"../in/meshes/tetra.obj")"), std::string::npos);
    const CliRun again = run("scene " + q("out/result.json") + " -o " + q("out/again.obj"));
    ASSERT_EQ(again.code, 0) << again.err;
}

TEST_F(SceneCli, SceneCommandReportsWhatItWrote) {
    const CliRun r = run("scene " + q("in/mix.json") + " -o " + q("out/mix.obj") + " --tube-sides 5");
    ASSERT_EQ(r.code, 0) << r.err;
    // One line: instances, meshes, triangles, max rigid fit error.
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    const TriangleMesh mesh = read_triangle_mesh(path("out/mix.obj"));
    // Meshes: the shards', the balls' sphere, one per worm.
    const std::string expected = "scene: 7 instances, 4 meshes, " + std::to_string(mesh.triangles.size()) +
                                 " triangles, max rigid fit error ";
    EXPECT_EQ(r.err.rfind(expected, 0), 0u) << r.err;
    for (const char* format : {"mix.mesh.ply", "mix.glb", "mix.gltf", "mix.usda"})
        EXPECT_EQ(run("scene " + q("in/mix.json") + " -o " + q(std::string("out/") + format) + " -q").code, 0);
    EXPECT_EQ(read("out/mix.usda").rfind("#usda 1.0\n", 0), 0u);
    EXPECT_NE(read("out/mix.usda").find("def PointInstancer \"Elements\""), std::string::npos);
    EXPECT_EQ(run("scene " + q("in/mix.json") + " -o " + q("out/nodes.glb") + " -q --gltf-instancing nodes").code, 0);
}

TEST_F(SceneCli, SynthToAMissingDirectoryWritesNothing) {
    const CliRun r = run("synth " + q("in/mix.json") + " -o " + q("out/none/result.gltf") + " --iterations 1");
    EXPECT_NE(r.code, 0);
    EXPECT_NE(r.err.find("none/result.gltf"), std::string::npos) << r.err;
    EXPECT_TRUE(out_files().empty());
}

TEST_F(SceneCli, ErrorsLeaveNoFile) {
    expect_failure(run("scene " + q("in/mix.json") + " -o " + q("out/mix.ply")), 2, ".mesh.ply");
    expect_failure(run("scene " + q("in/mix.json") + " -o " + q("out/mix.stl")), 2, ".stl");
    expect_failure(run("scene " + q("in/mix.json") + " -o " + q("out/mix.obj") + " --tube-sides 2"), 2,
                   "--tube-sides");
    expect_failure(run("scene " + q("in/mix.json") + " -o " + q("out/mix.glb") + " --gltf-instancing all"), 2,
                   "--gltf-instancing must be gpu or nodes, got 'all'");
    expect_failure(run("synth " + q("in/mix.json") + " -o " + q("out/mix.glb") + " --gltf-instancing x"), 2,
                   "--gltf-instancing");
    fs::remove(path("in/meshes/tetra.obj"));
    expect_failure(run("scene " + q("in/mix.json") + " -o " + q("out/mix.glb")), 5, "tetra.obj");
    // synth finds the missing mesh before synthesizing.
    const CliRun r = run("synth " + q("in/mix.json") + " -o " + q("out/mix.gltf") + " --iterations 1");
    expect_failure(r, 5, "tetra.obj");
    EXPECT_EQ(r.err.find("iteration"), std::string::npos) << r.err;
}
