// A spatial hash grid over points that come and go (DESIGN.md, "one dynamic spatial grid
// in core"): insert, move, remove and fixed-radius queries, in 2D (z ignored) or 3D, with
// no bounds fixed in advance, so that growth and streaming can add elements anywhere.
// SpatialGrid (spatial_grid.hpp) stays the faster choice for a fixed set of points.
//
// Cells are keyed by their integer coordinates; each cell holds the ids in it. A query
// visits the cells that overlap the ball and returns ids in ascending order, so what a
// caller computes from them does not depend on insertion history.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "tessera/vec.hpp"

namespace tessera::core {

class DynamicGrid {
public:
    DynamicGrid(double cell_size = 1.0, int dimension = 2)
        : cell_(cell_size > 0.0 ? cell_size : 1.0), inv_(1.0 / cell_), dimension_(dimension) {}

    int dimension() const { return dimension_; }
    double cell_size() const { return cell_; }
    std::size_t size() const { return position_count_; }

    // Inserts point `id` (ids are small non-negative integers chosen by the caller).
    void insert(int id, const Vec3& p) {
        if (id >= static_cast<int>(where_.size())) where_.resize(id + 1, kAbsent);
        const std::uint64_t key = key_of(p);
        where_[id] = key;
        cells_[key].push_back(id);
        ++position_count_;
    }
    void remove(int id) {
        if (id < 0 || id >= static_cast<int>(where_.size()) || where_[id] == kAbsent) return;
        std::vector<int>& cell = cells_[where_[id]];
        cell.erase(std::find(cell.begin(), cell.end(), id));
        where_[id] = kAbsent;
        --position_count_;
    }
    void move(int id, const Vec3& p) {
        if (id < static_cast<int>(where_.size()) && where_[id] == key_of(p)) return;
        remove(id);
        insert(id, p);
    }

    // Ids whose point (given by `position(id)`) lies within `radius` of `center`, ascending,
    // appended to `out` after clearing it.
    template <class PositionOf>
    void query(const Vec3& center, double radius, const PositionOf& position, std::vector<int>& out) const {
        out.clear();
        const double r2 = radius * radius;
        const int lo[3] = {cell_coord(center.x - radius), cell_coord(center.y - radius),
                           dimension_ == 3 ? cell_coord(center.z - radius) : 0};
        const int hi[3] = {cell_coord(center.x + radius), cell_coord(center.y + radius),
                           dimension_ == 3 ? cell_coord(center.z + radius) : 0};
        for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y)
                for (int x = lo[0]; x <= hi[0]; ++x) {
                    const auto it = cells_.find(pack(x, y, z));
                    if (it == cells_.end()) continue;
                    for (const int id : it->second) {
                        Vec3 d = position(id) - center;
                        if (dimension_ == 2) d.z = 0.0;
                        if (dot(d, d) <= r2) out.push_back(id);
                    }
                }
        std::sort(out.begin(), out.end());
    }

private:
    static constexpr std::uint64_t kAbsent = ~std::uint64_t{0};

    int cell_coord(double v) const { return static_cast<int>(std::floor(v * inv_)); }
    // 21 bits per axis (about two million cells each way, centred on the origin).
    static std::uint64_t pack(int x, int y, int z) {
        constexpr std::uint64_t mask = (1u << 21) - 1, bias = 1u << 20;
        return ((static_cast<std::uint64_t>(x) + bias) & mask) | (((static_cast<std::uint64_t>(y) + bias) & mask) << 21) |
               (((static_cast<std::uint64_t>(z) + bias) & mask) << 42);
    }
    std::uint64_t key_of(const Vec3& p) const {
        return pack(cell_coord(p.x), cell_coord(p.y), dimension_ == 3 ? cell_coord(p.z) : 0);
    }

    double cell_, inv_;
    int dimension_;
    std::size_t position_count_ = 0;
    std::unordered_map<std::uint64_t, std::vector<int>> cells_;
    std::vector<std::uint64_t> where_;  // per id: its cell key, or kAbsent
};

}  // namespace tessera::core
