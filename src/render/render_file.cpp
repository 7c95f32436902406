// render_to_file: the picture format follows the file extension (.png / .svg,
// any case); the file is written atomically by the io module so a failed run
// leaves no partial picture. PNG pictures show the element meshes (build_scene +
// render_scene_png) when options.meshes asks for them.
#include <algorithm>
#include <cctype>
#include <string>

#include "tessera/error.hpp"
#include "tessera/geometry.hpp"
#include "tessera/io.hpp"
#include "tessera/render.hpp"

namespace tessera {

void render_to_file(const Exemplar& data, const std::string& path, const RenderOptions& options) {
    const auto dot = path.find_last_of('.');
    const auto slash = path.find_last_of("/\\");
    std::string extension = dot == std::string::npos || (slash != std::string::npos && dot < slash) ? "" : path.substr(dot);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const bool has_mesh = std::any_of(data.types.begin(), data.types.end(),
                                      [](const ElementType& t) { return !t.mesh.empty(); });
    const bool meshes = options.meshes == RenderOptions::Meshes::on ||
                        (options.meshes == RenderOptions::Meshes::automatic && has_mesh);
    if (extension == ".png") {
        if (meshes) return write_file_atomic(path, render_scene_png(data, build_scene(data), options));
        return write_file_atomic(path, render_png(data, options));
    }
    if (extension == ".svg") {
        // SVG pictures draw disks and polylines; element meshes are drawn in PNG only.
        if (options.meshes == RenderOptions::Meshes::on)
            throw Error(ErrorKind::option, "meshes: on draws element meshes, which only .png pictures show, not '" + path + "'");
        return write_file_atomic(path, render_svg(data, options));
    }
    throw Error(ErrorKind::option, "cannot render '" + path + "': the picture extension must be .png or .svg");
}

}  // namespace tessera
