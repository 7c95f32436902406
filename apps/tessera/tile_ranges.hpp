// apps/tessera/tile_ranges.hpp — the --tiles ranges of `tessera world`.
#pragma once

#include <string>
#include <vector>

#include "tessera/world.hpp"

namespace tessera_cli {

// One box of tiles, ends exclusive: X0:X1,Y0:Y1[,Z0:Z1] holds x0 <= x < x1 (and so on).
struct TileRange {
    std::int64_t lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    std::string text;  // as the user wrote it, for messages
};

// Parses one --tiles value for a world of `dimension` (2: two ranges, 3: three). Fails with
// an option error naming `flag` for a malformed, empty (X1 <= X0) or oversized range.
TileRange parse_tile_range(const std::string& text, int dimension, const std::string& flag);

// The tiles of all ranges, in coordinate order; fails naming both ranges when two overlap
// (a tile asked for twice is almost always a typing error in a range).
std::vector<tessera::TileCoord> tiles_of(const std::vector<TileRange>& ranges, const std::string& flag);

}  // namespace tessera_cli
