// The PCF method's domain of a world tile (pcf_tile_domain.hpp).
#include "world/pcf_tile_domain.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <utility>

#include "tessera/error.hpp"

namespace tessera::world {

namespace {

using Corner = std::pair<int, int>;  // a vertex of the 4 x 4 grid of cell corners
using Edge = std::pair<Corner, Corner>;

// The cells of the 3 x 3 grid around the tile (the tile is (1, 1)) that the domain holds.
std::set<Corner> held_cells(const TileCoord& tile) {
    std::set<Corner> cells{{1, 1}};
    for (const TileCoord& d : tile_dependencies(tile, 2))
        cells.insert({static_cast<int>(d.x - tile.x) + 1, static_cast<int>(d.y - tile.y) + 1});
    return cells;
}

// The boundary of a union of grid cells, counter-clockwise: each cell's edges, less those
// a neighbouring held cell traverses the other way, chained end to start. The cells a tile
// holds never touch at a corner only, so every corner starts at most one boundary edge.
std::vector<Corner> union_boundary(const std::set<Corner>& cells) {
    std::set<Edge> edges;
    for (const auto& [i, j] : cells) {
        const std::array<Corner, 4> v{Corner{i, j}, Corner{i + 1, j}, Corner{i + 1, j + 1}, Corner{i, j + 1}};
        for (int k = 0; k < 4; ++k) {
            const Edge e{v[k], v[(k + 1) % 4]};
            if (!edges.erase({e.second, e.first})) edges.insert(e);
        }
    }
    std::map<Corner, Corner> next;
    for (const Edge& e : edges) next[e.first] = e.second;
    std::vector<Corner> ring;
    Corner at = edges.begin()->first;
    for (size_t guard = 0; guard <= edges.size(); ++guard) {
        ring.push_back(at);
        at = next.at(at);
        if (at == ring.front()) break;
    }
    if (ring.size() != edges.size()) throw Error(ErrorKind::internal, "pcf_tile_domain: the cells do not form one ring");
    return ring;
}

}  // namespace

Domain pcf_tile_domain(const TileCoord& tile, double tile_size, double margin) {
    const Box box = tile_box(tile, tile_size, 2);
    const std::array<double, 4> xs{box.lo.x - margin, box.lo.x, box.hi.x, box.hi.x + margin};
    const std::array<double, 4> ys{box.lo.y - margin, box.lo.y, box.hi.y, box.hi.y + margin};
    const std::vector<Corner> ring = union_boundary(held_cells(tile));
    std::vector<Vec3> outer;
    for (size_t k = 0; k < ring.size(); ++k) {
        const Corner& prev = ring[(k + ring.size() - 1) % ring.size()];
        const Corner& here = ring[k];
        const Corner& next = ring[(k + 1) % ring.size()];
        const bool straight = (prev.first == here.first && here.first == next.first) ||
                              (prev.second == here.second && here.second == next.second);
        if (!straight) outer.push_back({xs[here.first], ys[here.second], 0.0});
    }
    if (outer.size() > 4) return Domain::polygon(outer);
    Vec3 lo = outer[0], hi = outer[0];  // a rectangle: kept a box, whose PCF corrections are exact and cheap
    for (const Vec3& v : outer) {
        lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), 0.0};
        hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), 0.0};
    }
    return Domain::box(lo, hi, 2);
}

}  // namespace tessera::world
