// tessera/render.hpp — preview pictures of an exemplar or arrangement.
// 2D: elements as disks (radius, or a size derived from the spacing) or as
// polylines through their samples, coloured by class, with the domain outline.
// 3D: an orthographic view along a tilted axis with depth shading.
#pragma once

#include <string>

#include "tessera/exemplar.hpp"

namespace tessera {

struct RenderOptions {
    int width = 800;           // picture width in pixels; height follows the aspect ratio
    bool show_domain = true;   // draw the domain outline
    bool show_samples = true;  // mark the samples of multi-sample elements
};

// PNG bytes (8-bit RGB).
std::string render_png(const Exemplar& data, const RenderOptions& options = {});
// SVG text.
std::string render_svg(const Exemplar& data, const RenderOptions& options = {});
// Writes .png or .svg by extension, atomically. Throws Error(option) for another extension.
void render_to_file(const Exemplar& data, const std::string& path, const RenderOptions& options = {});

}  // namespace tessera
