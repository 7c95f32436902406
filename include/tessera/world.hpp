// tessera/world.hpp — unbounded worlds made of deterministic tiles (docs/worlds.md).
//
// The world is an unbounded grid of square (2D) or cubic (3D) tiles of one size, tile
// (x, y[, z]) covering [x S, (x + 1) S) x [y S, (y + 1) S) [x [z S, (z + 1) S)]. An element
// belongs to the tile that holds its centre. Tiles are made in phases of a fixed colouring:
// phase = (x mod 2) + 2 (y mod 2) in 2D (4 phases); in 3D the 8 parities in Gray-code order,
// (0,0,0), (1,0,0), (1,1,0), (0,1,0), (0,1,1), (1,1,1), (1,0,1), (0,0,1) (src/world/tiles.cpp
// says why). Two tiles of one
// phase never touch (not even at a corner), so each phase's tiles can be made in any order, on
// any machine. A tile is grown (tessera/grow.hpp, RegionEdge::open) next to the final elements
// of its neighbours of earlier phases, which it treats as locked: its elements depend only on
// (exemplar, options, seed, tile coordinates) and those neighbours, never on which other tiles
// were made, in which order or where. A tile without neighbours (phase 0) starts from
// exemplar patches at places drawn by a key of the seed and the tile's coordinates.
//
// The same exemplar, options and seed give byte-identical tiles whatever the order, the thread
// count, the process or the machine (the same build): every draw is keyed by world position,
// and the tile handed to its neighbours is the one written (tile_to_json), samples and all.
#pragma once

#include <compare>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tessera/exemplar.hpp"
#include "tessera/grow.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera {

struct TileCoord {
    std::int64_t x = 0, y = 0, z = 0;  // z = 0 in 2D
    friend auto operator<=>(const TileCoord&, const TileCoord&) = default;
    std::string describe() const;      // "x,y" or "x,y,z"
};

// A finished tile handed to the tile that depends on it.
struct NeighbourTile {
    TileCoord coord;
    const Arrangement* tile = nullptr;
};

// How a tile is made next to its finished neighbours: grown by neighbourhood matching
// (tessera/grow.hpp) or synthesized by the PCF method with the neighbours' elements fixed
// (synthesize_pcf_next_to, tessera/pcf_synthesis.hpp; 2D, single-sample elements).
enum class WorldMethod { grow, pcf };

struct WorldOptions {
    double tile_size = 0.0;  // edge of a tile, > 0 and at least TileMaker::min_tile_size()
    WorldMethod method = WorldMethod::grow;
    GrowOptions grow;        // how each tile grows (seed, threads and every growth option)
    PcfSynthOptions pcf;     // method pcf: how each tile is synthesized (its seed is grow.seed)
};

// 0..3 in 2D, 0..7 in 3D (see above).
int tile_phase(const TileCoord& tile, int dimension);
int tile_phases(int dimension);
// The neighbours of a tile (sharing an edge or a corner) of earlier phases: the tiles it
// depends on, in coordinate order.
std::vector<TileCoord> tile_dependencies(const TileCoord& tile, int dimension);
// The tile's square or cube (2D: z from 0 to 0).
Box tile_box(const TileCoord& tile, double tile_size, int dimension);
// The tile that holds a point (half-open cells).
TileCoord tile_at(const Vec3& p, double tile_size, int dimension);

// Makes tiles of one world. Validates the exemplar and options once (Error(input) /
// Error(option) naming the option as world options spell it: "tile_size", or a growth
// option's name). Thread-safe: make() may run on several threads at once.
class TileMaker {
public:
    TileMaker(const Exemplar& exemplar, const WorldOptions& options);
    ~TileMaker();
    TileMaker(TileMaker&&) noexcept;
    TileMaker& operator=(TileMaker&&) noexcept;

    // The elements of a neighbour within this distance of a tile are locked next to it: the
    // growth's reach (the copied patch and one neighbourhood radius).
    double margin() const;
    // The smallest tile edge this exemplar allows: a tile must hold one neighbourhood, so that
    // a tile's dependencies are its adjacent tiles only.
    double min_tile_size() const;
    int dimension() const;
    const Exemplar& exemplar() const;
    const WorldOptions& options() const;

    // Makes tile `tile` next to `neighbours`, the final tiles of tile_dependencies(tile) in any
    // order (Error(input) when one is missing or another tile is given). The result: the
    // elements whose centre lies in the tile, ids 0, 1, ... in creation order, the tile's box
    // as domain, no run statistics; what tile_to_json writes and parse_json reads back.
    // Progress: the tile's growth rounds (Cancelled when it returns false).
    Arrangement make(const TileCoord& tile, const std::vector<NeighbourTile>& neighbours,
                     const Progress& progress = {}) const;
    // A text that differs between worlds whose tiles differ: the exemplar, the tile size and
    // every growth option but the thread count (a cache directory is checked against it).
    const std::string& fingerprint() const;

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

// The tile in the native JSON format, exactly as make() returned it and as its neighbours
// read it back (parse_json): every number round-trips, so a tile loaded from a file or sent
// between machines is the tile made. No run statistics (no timings).
std::string tile_to_json(const Arrangement& tile);
// FNV-1a 64 of tile_to_json, as 16 hex digits: the content hash of a world's index.
std::string tile_hash(const Arrangement& tile);
// FNV-1a 64 of any text, as 16 hex digits (tile_hash is that of tile_to_json).
std::string content_hash(const std::string& content);
// Tiles merged into one arrangement (ids renumbered 0, 1, ... in the order given), the union
// of their boxes as domain.
Arrangement merge_tiles(const std::vector<const Arrangement*>& tiles, int dimension);

// The tiles `wanted` and every tile they depend on, transitively (a tile at the edge of a
// range needs neighbours outside it, which need theirs): sorted by phase, then coordinates.
std::vector<TileCoord> tile_closure(const std::vector<TileCoord>& wanted, int dimension);

// Every tile of tile_closure(wanted), made phase by phase, `threads` tiles of one phase at once
// (0 = all cores). Each tile grows with the maker's own grow.threads: give the maker 1 when the
// phases hold at least as many tiles as threads. The same tiles whatever `threads`. Progress:
// stage "tile", iteration = tiles finished, iterations = tiles in all; false cancels (Cancelled)
// once the tiles under way have finished.
std::map<TileCoord, Arrangement> make_tiles(const TileMaker& maker, const std::vector<TileCoord>& wanted,
                                            int threads, const Progress& progress = {});

// A world answered on demand ("the tiles around this point"): computes only the tiles asked
// for and their dependencies, keeps every finished tile in memory and, with a cache
// directory, as tile_X_Y[_Z].json files there (read back instead of made again). Any order of
// requests gives the tiles a whole-world build gives. Not thread-safe.
class World {
public:
    World(const Exemplar& exemplar, const WorldOptions& options, std::string cache_dir = {});
    ~World();
    World(World&&) noexcept;
    World& operator=(World&&) noexcept;

    // The finished tile, made (with its dependencies) when not yet known.
    const Arrangement& tile(const TileCoord& tile);
    // The tiles whose box comes within `radius` of p, in coordinate order.
    std::vector<TileCoord> tiles_around(const Vec3& p, double radius) const;
    // Those tiles, finished, merged into one arrangement.
    Arrangement around(const Vec3& p, double radius);
    // Tiles made by this object (not those read from the cache directory or kept in memory).
    int made() const;
    int known() const;  // tiles in memory
    const TileMaker& maker() const;

    void set_progress(Progress progress);  // passed to each tile's growth

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace tessera
