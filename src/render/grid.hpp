// The faint grid of a world's tile borders (RenderOptions::grid), as segments in data units.
#pragma once

#include <utility>
#include <vector>

#include "tessera/domain.hpp"

namespace tessera::render {

// Lines at the multiples of `spacing` (from the world origin) across `bounds`: in 2D the
// vertical and horizontal lines strictly inside, in 3D every cell edge inside or on the box.
// Throws Error(option) "grid: ..." when an axis would hold more than 4096 cells.
std::vector<std::pair<Vec3, Vec3>> grid_lines(const Box& bounds, double spacing, int dimension);

}  // namespace tessera::render
