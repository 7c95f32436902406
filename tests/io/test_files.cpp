// Tests for the file side of io (src/io/files.cpp, src/io/save.cpp): load/save by
// extension, error kinds and messages naming the path, and atomic writes that leave
// neither a partial output nor a temporary file behind.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "temp_dir.hpp"
#include "tessera/error.hpp"
#include "tessera/io.hpp"

using namespace tessera;
namespace fs = std::filesystem;

namespace {

// A fresh directory per test (tests/temp_dir.hpp).
class IoFiles : public tessera::test::TempDirTest {
protected:
    // Names of the directory's entries that look like temporary files.
    std::vector<std::string> temporary_files() const {
        std::vector<std::string> found;
        for (const auto& entry : fs::directory_iterator(dir_))
            if (entry.path().filename().string().find(".tmp") != std::string::npos)
                found.push_back(entry.path().filename().string());
        return found;
    }
};

Exemplar small_exemplar() {
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {4, 4, 0}, 2);
    const int t = ex.type_index("pebble");
    ex.add_element(t, {{1, 1, 0}}, 0.5);
    ex.add_element(t, {{2, 3, 0}}, 0.25);
    ex.add_element(t, {{3.5, 0.5, 0}}, 0.75);
    return ex;
}

void expect_error(const std::function<void()>& f, ErrorKind kind, const std::string& fragment) {
    try {
        f();
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), kind) << e.what();
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos)
            << "'" << fragment << "' not in: " << e.what();
    }
}

}  // namespace

TEST_F(IoFiles, SaveAndLoadJsonAndCsv) {
    const Exemplar ex = small_exemplar();
    save(ex, path("out.json"));
    const Exemplar from_json = load(path("out.json"));
    EXPECT_EQ(from_json.elements.size(), 3u);
    EXPECT_EQ(from_json.samples[1].p, Vec3(2, 3, 0));
    EXPECT_EQ(from_json.domain.bounds().hi, Vec3(4, 4, 0));

    save(ex, path("OUT.CSV"));  // extensions are case-insensitive
    LoadOptions options;
    options.input_domain = ex.domain;
    const Exemplar from_csv = load(path("OUT.CSV"), options);
    EXPECT_EQ(from_csv.elements[2].radius, 0.75);
    EXPECT_EQ(from_csv.domain.bounds().hi, Vec3(4, 4, 0));

    save(ex, path("out.ply"));
    EXPECT_EQ(read_file(path("out.ply")).rfind("ply\n", 0), 0u);
    EXPECT_TRUE(temporary_files().empty());
}

// Type meshes are named relative to the JSON file in the file and relative to the
// working directory in memory, so load(save(x)) finds the same mesh from anywhere.
TEST_F(IoFiles, MeshPathsAreRelativeToTheJsonFile) {
    fs::create_directories(dir_ / "meshes");
    fs::create_directories(dir_ / "out");
    write("meshes/rock.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    write("in.json", R"({"format": "tessera", "version": 1, "dimension": 2,
        "domain": {"type": "box", "min": [0, 0], "max": [4, 4]},
        "types": [{"name": "rock", "mesh": "meshes/rock.obj"}, {"name": "plain"}],
        "elements": [{"type": "rock", "position": [1, 1]}, {"type": "plain", "position": [2, 2]}]})");
    const Exemplar in = load(path("in.json"));
    EXPECT_TRUE(fs::equivalent(in.types[0].mesh, path("meshes/rock.obj"))) << in.types[0].mesh;
    EXPECT_EQ(in.types[1].mesh, "");

    save(in, path("out/again.json"));
    EXPECT_NE(read_file(path("out/again.json")).find(R"("mesh":"../meshes/rock.obj")"), std::string::npos)
        << read_file(path("out/again.json"));
    const Exemplar again = load(path("out/again.json"));
    EXPECT_TRUE(fs::equivalent(again.types[0].mesh, path("meshes/rock.obj"))) << again.types[0].mesh;

    // A mesh that shares no directory with the file but the root keeps its absolute path;
    // to_json writes paths as they are.
    Exemplar elsewhere = in;
    elsewhere.types[0].mesh = "/nonexistent-tessera-dir/rock.obj";
    save(elsewhere, path("out/abs.json"));
    EXPECT_EQ(load(path("out/abs.json")).types[0].mesh, elsewhere.types[0].mesh);
    EXPECT_NE(to_json(in).find(in.types[0].mesh), std::string::npos);
}

TEST_F(IoFiles, PicturesGoThroughTheRenderer) {
    save(small_exemplar(), path("pic.svg"));
    EXPECT_NE(read_file(path("pic.svg")).find("<svg"), std::string::npos);
    save(small_exemplar(), path("pic.PNG"));
    EXPECT_EQ(read_file(path("pic.PNG")).substr(1, 3), "PNG");
    EXPECT_TRUE(temporary_files().empty());
}

TEST_F(IoFiles, ArrangementJsonCarriesStats) {
    Arrangement a;
    static_cast<Exemplar&>(a) = small_exemplar();
    a.stats.method = "det";
    save(a, path("arr.json"));
    EXPECT_NE(read_file(path("arr.json")).find("\"method\":\"det\""), std::string::npos);
    EXPECT_EQ(load(path("arr.json")).elements.size(), 3u);
}

TEST_F(IoFiles, LoadErrorsNameTheFile) {
    expect_error([&] { load(path("missing.json")); }, ErrorKind::io, "cannot read " + path("missing.json"));
    write("points.txt", "x,y\n1,2\n");
    expect_error([&] { load(path("points.txt")); }, ErrorKind::io, path("points.txt"));
    expect_error([&] { load(path("points.txt")); }, ErrorKind::io, "supported: .json, .csv");
    write("broken.json", "{\"format\": \"tessera\",\n  oops }");
    expect_error([&] { load(path("broken.json")); }, ErrorKind::input,
                 path("broken.json") + ": invalid JSON");
    write("bad.csv", "x,y\n1,2\n3\n");
    expect_error([&] { load(path("bad.csv")); }, ErrorKind::input,
                 path("bad.csv") + ":3: expected 2 fields, got 1");
    write("one.csv", "x,y\n1,2\n");
    expect_error([&] { load(path("one.csv")); }, ErrorKind::domain, path("one.csv"));
    fs::create_directory(dir_ / "dir.json");
    expect_error([&] { load(path("dir.json")); }, ErrorKind::io, "cannot read " + path("dir.json"));
}

// save() reaches every writer, for an Exemplar and an Arrangement alike: scene formats
// without a separate build_scene call.
TEST_F(IoFiles, SaveWritesEveryExtension) {
    Arrangement arrangement;
    static_cast<Exemplar&>(arrangement) = small_exemplar();
    const std::vector<std::pair<std::string, std::string>> starts = {
        {"json", "{"},       {"csv", "x,y"},        {"ply", "ply\n"},        {"usda", "#usda 1.0\n"},
        {"gltf", "{"},       {"glb", "glTF"},       {"obj", "# tessera"}, {"mesh.ply", "ply\n"},
        {"png", "\x89PNG"}, {"svg", "<?xml"}};
    for (const auto& [extension, start] : starts) {
        save(small_exemplar(), path("ex." + extension));
        save(arrangement, path("arr." + extension));
        for (const std::string& name : {"ex." + extension, "arr." + extension})
            EXPECT_EQ(read_file(path(name)).rfind(start, 0), 0u) << name;
    }
    EXPECT_EQ(read_file(path("ex.mesh.ply")).find("element face"), read_file(path("arr.mesh.ply")).find("element face"));
    EXPECT_NE(read_file(path("ex.mesh.ply")).find("element face"), std::string::npos);  // the scene, not points
    EXPECT_TRUE(temporary_files().empty());
    EXPECT_EQ(save_scene(small_exemplar(), path("scene.usda")).instances.size(), 3u);
    expect_error([&] { save_scene(small_exemplar(), path("points.ply")); }, ErrorKind::option, path("points.ply"));
}

TEST_F(IoFiles, SaveRejectsUnknownExtension) {
    expect_error([&] { save(small_exemplar(), path("out.xyz")); }, ErrorKind::option, path("out.xyz"));
    expect_error([&] { save(small_exemplar(), path("noextension")); }, ErrorKind::option,
                 path("noextension"));
    expect_error([&] { save(small_exemplar(), path("out.usdc")); }, ErrorKind::option, ".usda");
    EXPECT_FALSE(fs::exists(path("out.xyz")));
}

TEST_F(IoFiles, AtomicWriteReplacesAndLeavesNoTemporary) {
    write_file_atomic(path("a.txt"), "first");
    write_file_atomic(path("a.txt"), "second version");
    EXPECT_EQ(read_file(path("a.txt")), "second version");
    write_file_atomic(path("empty.txt"), "");
    EXPECT_EQ(read_file(path("empty.txt")), "");
    EXPECT_TRUE(temporary_files().empty());
}

TEST_F(IoFiles, AtomicWriteFailureLeavesNothing) {
    // A directory that does not exist is an error, not created on the fly.
    const std::string target = path("no/such/dir/out.json");
    expect_error([&] { write_file_atomic(target, "data"); }, ErrorKind::io, "cannot write " + target);
    EXPECT_FALSE(fs::exists(dir_ / "no"));
    // The target is a directory: the rename fails after the temporary was written.
    fs::create_directory(dir_ / "taken.json");
    expect_error([&] { save(small_exemplar(), path("taken.json")); }, ErrorKind::io, path("taken.json"));
    EXPECT_TRUE(fs::is_directory(dir_ / "taken.json"));
    EXPECT_TRUE(temporary_files().empty());
}

TEST_F(IoFiles, FailedSaveKeepsThePreviousFile) {
    write("keep.csv", "old content");
    Exemplar bad = small_exemplar();
    bad.attribute_names = {"x"};  // cannot be written as CSV
    for (auto& e : bad.elements) e.attributes = {1.0};
    EXPECT_THROW(save(bad, path("keep.csv")), Error);
    EXPECT_EQ(read_file(path("keep.csv")), "old content");
    EXPECT_TRUE(temporary_files().empty());
}
