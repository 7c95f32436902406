// The domain a 2D world tile is synthesized in by the PCF method (tile_maker.cpp): the
// tile and the margin strips of the neighbours it depends on. Private to the library.
#pragma once

#include <vector>

#include "tessera/domain.hpp"
#include "tessera/world.hpp"

namespace tessera::world {

// The union of the tile's box and, for each earlier-phase neighbour, the part of the
// margin band around the box on that neighbour's side (a side strip or a corner square):
// a rectilinear polygon. Sides towards later-phase tiles end at the tile's border, so the
// PCFs see nothing beyond it, as will be true until those tiles are made, and no element
// is synthesized there only to be thrown away.
Domain pcf_tile_domain(const TileCoord& tile, double tile_size, double margin);

}  // namespace tessera::world
