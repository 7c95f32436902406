// A spatial hash grid over points that come and go (DESIGN.md, "one dynamic spatial grid
// in core"): insert, move, remove and fixed-radius queries, in 2D (z ignored) or 3D, with
// no bounds fixed in advance, so that growth and streaming can add elements anywhere.
// SpatialGrid (spatial_grid.hpp) stays the faster choice for a fixed set of points.
//
// Cells are keyed by their integer coordinates and grouped in blocks; each cell holds the ids
// in it. A query visits the cells that overlap the ball and returns ids in ascending order,
// so what a caller computes from them does not depend on insertion history.
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
        : cell_(cell_size > 0.0 ? cell_size : 1.0),
          inv_(1.0 / cell_),
          dimension_(dimension),
          shift_(dimension == 3 ? 2 : 3),
          cells_per_block_(1 << (shift_ * (dimension == 3 ? 3 : 2))) {}

    int dimension() const { return dimension_; }
    double cell_size() const { return cell_; }
    std::size_t size() const { return position_count_; }

    // Inserts point `id` (ids are small non-negative integers chosen by the caller).
    void insert(int id, const Vec3& p) {
        if (id >= static_cast<int>(where_.size())) where_.resize(id + 1, kAbsent);
        const Cell c = cell_of(p);
        where_[id] = pack(c.x, c.y, c.z);
        cell_for_insert(c).push_back(id);
        ++position_count_;
    }
    void remove(int id) {
        if (id < 0 || id >= static_cast<int>(where_.size()) || where_[id] == kAbsent) return;
        const Cell c = unpack(where_[id]);
        std::vector<int>& cell = blocks_[block_index_.at(block_key(c))].cells[local_index(c)];
        cell.erase(std::find(cell.begin(), cell.end(), id));
        where_[id] = kAbsent;
        --position_count_;
    }
    void move(int id, const Vec3& p) {
        const Cell c = cell_of(p);
        if (id < static_cast<int>(where_.size()) && where_[id] == pack(c.x, c.y, c.z)) return;
        remove(id);
        insert(id, p);
    }

    // Ids whose point (given by `position(id)`) lies within `radius` of `center`, ascending,
    // appended to `out` after clearing it.
    template <class PositionOf>
    void query(const Vec3& center, double radius, const PositionOf& position, std::vector<int>& out) const {
        out.clear();
        for_each_within(center, radius, position, [&](int id) { out.push_back(id); });
        std::sort(out.begin(), out.end());
    }

    // Calls visit(id) for each id whose point lies within `radius` of `center`, in an order
    // that depends on insertion history: for callers whose result does not depend on the
    // order (a minimum, a test, or their own total sort), without query()'s sort.
    template <class PositionOf, class Visit>
    void for_each_within(const Vec3& center, double radius, const PositionOf& position,
                         const Visit& visit) const {
        const double r2 = radius * radius;
        const Cell lo = cell_of(center - Vec3{radius, radius, radius});
        const Cell hi = cell_of(center + Vec3{radius, radius, radius});
        const int last = (1 << shift_) - 1;
        // One lookup per block the ball's box overlaps, then its cells in the box.
        for (int bz = lo.z >> shift_; bz <= hi.z >> shift_; ++bz)
            for (int by = lo.y >> shift_; by <= hi.y >> shift_; ++by)
                for (int bx = lo.x >> shift_; bx <= hi.x >> shift_; ++bx) {
                    const auto it = block_index_.find(pack(bx, by, bz));
                    if (it == block_index_.end()) continue;
                    const Block& block = blocks_[it->second];
                    const Cell from{std::max(lo.x, bx << shift_), std::max(lo.y, by << shift_),
                                    std::max(lo.z, bz << shift_)};
                    const Cell to{std::min(hi.x, (bx << shift_) + last),
                                  std::min(hi.y, (by << shift_) + last),
                                  std::min(hi.z, (bz << shift_) + last)};
                    for (int z = from.z; z <= to.z; ++z)
                        for (int y = from.y; y <= to.y; ++y)
                            for (int x = from.x; x <= to.x; ++x)
                                for (const int id : block.cells[local_index({x, y, z})]) {
                                    Vec3 d = position(id) - center;
                                    if (dimension_ == 2) d.z = 0.0;
                                    if (dot(d, d) <= r2) visit(id);
                                }
                }
    }

private:
    // Cells are grouped in blocks of 8 x 8 (2D) or 4 x 4 x 4 (3D), so that a query looks up
    // one to a few blocks in the hash map instead of every cell it overlaps.
    struct Cell {
        int x = 0, y = 0, z = 0;
    };
    struct Block {
        std::vector<std::vector<int>> cells;
    };
    static constexpr std::uint64_t kAbsent = ~std::uint64_t{0};
    static constexpr std::uint64_t kMask = (1u << 21) - 1, kBias = 1u << 20;

    int cell_coord(double v) const { return static_cast<int>(std::floor(v * inv_)); }
    Cell cell_of(const Vec3& p) const {
        return {cell_coord(p.x), cell_coord(p.y), dimension_ == 3 ? cell_coord(p.z) : 0};
    }
    // 21 bits per axis (about two million cells each way, centred on the origin).
    static std::uint64_t pack(int x, int y, int z) {
        return ((static_cast<std::uint64_t>(x) + kBias) & kMask) |
               (((static_cast<std::uint64_t>(y) + kBias) & kMask) << 21) |
               (((static_cast<std::uint64_t>(z) + kBias) & kMask) << 42);
    }
    static Cell unpack(std::uint64_t key) {
        auto axis = [&](int k) {
            return static_cast<int>(static_cast<std::int64_t>((key >> (21 * k)) & kMask) -
                                    static_cast<std::int64_t>(kBias));
        };
        return {axis(0), axis(1), axis(2)};
    }
    // Arithmetic shifts: the floor of the division for negative coordinates too.
    std::uint64_t block_key(const Cell& c) const { return pack(c.x >> shift_, c.y >> shift_, c.z >> shift_); }
    int local_index(const Cell& c) const {
        const int m = (1 << shift_) - 1;
        return (c.x & m) | ((c.y & m) << shift_) | ((c.z & m) << (2 * shift_));
    }
    std::vector<int>& cell_for_insert(const Cell& c) {
        const auto [it, fresh] = block_index_.try_emplace(block_key(c), static_cast<int>(blocks_.size()));
        if (fresh) blocks_.push_back(Block{std::vector<std::vector<int>>(cells_per_block_)});
        return blocks_[it->second].cells[local_index(c)];
    }

    double cell_, inv_;
    int dimension_;
    int shift_;  // log2 of a block's cells along an axis
    int cells_per_block_;
    std::size_t position_count_ = 0;
    std::unordered_map<std::uint64_t, int> block_index_;  // block key -> index into blocks_
    std::vector<Block> blocks_;
    std::vector<std::uint64_t> where_;  // per id: its cell (packed), or kAbsent
};

}  // namespace tessera::core
