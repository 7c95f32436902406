// render_to_file: the picture format follows the file extension (.png / .svg,
// any case); the file is written atomically by the io module so a failed run
// leaves no partial picture.
#include <algorithm>
#include <cctype>
#include <string>

#include "tessera/error.hpp"
#include "tessera/io.hpp"
#include "tessera/render.hpp"

namespace tessera {

void render_to_file(const Exemplar& data, const std::string& path, const RenderOptions& options) {
    const auto dot = path.find_last_of('.');
    const auto slash = path.find_last_of("/\\");
    std::string extension = dot == std::string::npos || (slash != std::string::npos && dot < slash) ? "" : path.substr(dot);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".png") return write_file_atomic(path, render_png(data, options));
    if (extension == ".svg") return write_file_atomic(path, render_svg(data, options));
    throw Error(ErrorKind::option, "cannot render '" + path + "': the picture extension must be .png or .svg");
}

}  // namespace tessera
