// io/save.cpp — save() by extension, the one entry point every writer is reached from
// (the CLI and the Python module call only this): data formats from the exemplar, preview
// pictures through render, and scene formats (USD, glTF, OBJ, mesh PLY) through
// build_scene + write_scene, so that a library user needs no second call to get geometry.
// Every path goes through write_file_atomic (directly or in the writer it calls).
#include <filesystem>
#include <string>

#include "io/io_util.hpp"
#include "tessera/error.hpp"
#include "tessera/io.hpp"
#include "tessera/render.hpp"

namespace tessera {

using namespace io_detail;

namespace {

// to_ply does not know the file it is for; its input errors get the file's name here.
template <class Serialise>
std::string named(const std::string& path, Serialise serialise) {
    try {
        return serialise();
    } catch (const Error& e) {
        if (e.kind() != ErrorKind::input) throw;
        throw Error(e.kind(), "cannot save " + path + ": " + e.what());
    }
}

void save_by_extension(const Exemplar& data, const std::string& path, const RunStats* stats,
                       const SaveOptions& options) {
    if (is_scene_path(path)) {
        save_scene(data, path, options);
        return;
    }
    const std::string extension = extension_of(path);
    if (extension == ".json")
        return write_file_atomic(path, to_json_with_mesh_paths(data, stats, [&](const std::string& mesh) {
                                     return mesh_path_from(path, mesh);
                                 }));
    if (extension == ".csv") return write_file_atomic(path, to_csv(data));
    if (extension == ".ply") return write_file_atomic(path, named(path, [&] { return to_ply(data); }));
    if (extension == ".png" || extension == ".svg") return render_to_file(data, path);
    throw Error(ErrorKind::option,
                "cannot save " + path + ": unsupported extension '" + extension +
                    "' (supported: .json, .csv, .ply, .usda, .gltf, .glb, .obj, .mesh.ply, "
                    ".png, .svg)");
}

}  // namespace

Scene save_scene(const Exemplar& data, const std::string& path, const SaveOptions& options) {
    if (!is_scene_path(path))
        throw Error(ErrorKind::option, "cannot write scene " + path + ": unsupported extension '" +
                                           extension_of(path) +
                                           "' (supported: .usda, .gltf, .glb, .obj, .mesh.ply)");
    Scene scene = build_scene(data, options.geometry);
    SceneWriteOptions write;
    write.gltf_instancing = options.gltf_instancing;
    write_scene(scene, path, write);
    return scene;
}

void save(const Exemplar& data, const std::string& path, const SaveOptions& options) {
    save_by_extension(data, path, nullptr, options);
}

void save(const Arrangement& data, const std::string& path, const SaveOptions& options) {
    save_by_extension(data, path, &data.stats, options);
}

}  // namespace tessera
