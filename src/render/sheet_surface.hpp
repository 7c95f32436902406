// Sheets (elements of a sheet type: a grid of samples, paper, cloth) drawn as what they are,
// a surface: the grid's quads split into triangles, shaded with normals interpolated from
// the grid (both sides lit alike), into the 3D preview's z-buffer. The sheet's border is
// drawn as a thin tube by collect_spheres (scene_3d.cpp) so that its outline reads.
#pragma once

#include <vector>

#include "render/hires_buffer.hpp"
#include "render/scene_3d.hpp"
#include "tessera/exemplar.hpp"

namespace tessera::render {

// True when `e` is a sheet: its type has the sheet topology, at least 2 x 2 samples.
bool is_sheet(const Exemplar& data, const Element& e);

// Draws every sheet of `data` into `buf` (supersampling factor ss), in `colors` by type.
void draw_sheets(HiResBuffer& buf, const Exemplar& data, const View3D& view, const Frame3D& frame, double ss,
                 const std::vector<Rgb>& colors);

}  // namespace tessera::render
