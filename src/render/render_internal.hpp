// The picture writers behind render_png / render_svg, one per dimension and
// format. They take checked data and options (render_api.cpp checks them).
#pragma once

#include <string>

#include "tessera/exemplar.hpp"
#include "tessera/render.hpp"

namespace tessera::render {

std::string render_png_2d(const Exemplar& data, const RenderOptions& options);
std::string render_png_3d(const Exemplar& data, const RenderOptions& options);
std::string render_svg_2d(const Exemplar& data, const RenderOptions& options);
std::string render_svg_3d(const Exemplar& data, const RenderOptions& options);

}  // namespace tessera::render
