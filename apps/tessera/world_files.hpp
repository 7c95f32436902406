// apps/tessera/world_files.hpp — what `tessera world -o DIR` writes: one native JSON file per
// tile and index.json listing the tiles (docs/worlds.md).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "tessera/world.hpp"

namespace tessera_cli {

// tile_X_Y.json (2D) or tile_X_Y_Z.json (3D).
std::string tile_file_name(const tessera::TileCoord& tile, int dimension);

// Fails (option error naming -o) when `dir` holds the index of another world or a file
// index.json that is not a world index: checked before any tile is made.
void check_world_dir(const std::string& dir, const tessera::TileMaker& maker);

// Writes the tiles `wanted` of `made` into `dir` (created when missing), each file atomically,
// index.json last: a directory whose index.json exists holds every tile it lists. The index
// records the world (dimension, tile size, seed, a hash of the exemplar and options) and each
// tile's coordinates, file, bounds, element count and content hash (tessera::tile_hash),
// the tiles an earlier run wrote into `dir` included (sorted by coordinates).
void write_world_dir(const std::string& dir, const tessera::TileMaker& maker, const std::string& input,
                     const std::vector<tessera::TileCoord>& wanted,
                     const std::map<tessera::TileCoord, tessera::Arrangement>& made);

}  // namespace tessera_cli
