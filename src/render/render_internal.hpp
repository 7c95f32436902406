// The picture writers behind render_png / render_svg, one per dimension and
// format. They take checked data and options (render_api.cpp checks them).
#pragma once

#include <string>

#include "render/raster.hpp"
#include "render/style.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/render.hpp"

namespace tessera::render {

std::string render_png_2d(const Exemplar& data, const RenderOptions& options);
std::string render_png_3d(const Exemplar& data, const RenderOptions& options);
std::string render_svg_2d(const Exemplar& data, const RenderOptions& options);
std::string render_svg_3d(const Exemplar& data, const RenderOptions& options);

// The 2D domain outline in grey (polygon rings, or the bounding rectangle), shared
// by the disk preview and the mesh picture.
void draw_domain_outline(Canvas& canvas, const Frame2D& frame, const Domain& domain);

}  // namespace tessera::render
