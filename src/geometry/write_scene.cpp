// geometry/write_scene.cpp — write_scene: the scene format by extension, written
// atomically (write_file_atomic) so that a failed run leaves no partial file.
#include <algorithm>
#include <cctype>
#include <filesystem>

#include "geometry/geometry_internal.hpp"
#include "tessera/error.hpp"
#include "tessera/io.hpp"

namespace tessera {

namespace {

enum class SceneFormat { none, obj, mesh_ply, gltf, glb, usda };

SceneFormat format_of(const std::string& path) {
    std::string name = std::filesystem::path(path).filename().string();
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    const auto ends_with = [&](const std::string& suffix) {
        return name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
    };
    if (ends_with(".obj")) return SceneFormat::obj;
    if (ends_with(".mesh.ply")) return SceneFormat::mesh_ply;
    if (ends_with(".gltf")) return SceneFormat::gltf;
    if (ends_with(".glb")) return SceneFormat::glb;
    if (ends_with(".usda")) return SceneFormat::usda;
    return SceneFormat::none;
}

}  // namespace

namespace geometry {

std::string instance_name(const Scene& scene, int instance) {
    const SceneInstance& inst = scene.instances[instance];
    return scene.type_names.at(static_cast<size_t>(inst.type)) + "_" + std::to_string(inst.id);
}

}  // namespace geometry

bool is_scene_path(const std::string& path) {
    return format_of(path) != SceneFormat::none;
}

void write_scene(const Scene& scene, const std::string& path, const SceneWriteOptions& options) {
    switch (format_of(path)) {
        case SceneFormat::obj:
            return write_file_atomic(path, geometry::to_obj(scene));
        case SceneFormat::mesh_ply:
            return write_file_atomic(path, geometry::to_mesh_ply(scene));
        case SceneFormat::gltf:
            return write_file_atomic(path, geometry::to_gltf(scene, false, options.gltf_instancing));
        case SceneFormat::glb:
            return write_file_atomic(path, geometry::to_gltf(scene, true, options.gltf_instancing));
        case SceneFormat::usda: {
            std::string text;
            try {
                text = geometry::to_usda(scene);
            } catch (const Error& e) {  // to_usda does not know the file's name
                if (e.kind() != ErrorKind::input) throw;
                throw Error(e.kind(), "cannot write scene " + path + ": " + e.what());
            }
            return write_file_atomic(path, text);
        }
        case SceneFormat::none:
            break;
    }
    throw Error(ErrorKind::option, "cannot write scene " + path + ": unsupported extension '" +
                                       std::filesystem::path(path).extension().string() +
                                       "' (supported: .obj, .mesh.ply, .gltf, .glb, .usda)");
}

}  // namespace tessera
