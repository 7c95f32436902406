// Neighbour pairs for the PCF method without an O(n^2) scan: a uniform 2D grid of
// element centres whose cells are about as wide as the axis's Euclidean reach (the
// largest centre distance that still adds to some bin), so a query visits the 3 x 3
// cells around a point. Elements can be inserted, moved and removed one at a time,
// as synthesis places and refines them (pcf_synthesis.hpp); analysis fills it once.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "pcf/pcf_math.hpp"
#include "tessera/domain.hpp"
#include "tessera/vec.hpp"

namespace tessera::pcf {

// The largest centre distance at which a pair with radii ra, rb still reaches the axis:
// beyond it the pair's normalised distance exceeds axis.x_limit() (points: d / r_max;
// disks: 3 + (d - r1 - r2) / r_max, pcf_synthesis.hpp).
inline double pair_reach(const Axis& axis, double r_max, double ra, double rb) {
    if (!(ra > 0.0) && !(rb > 0.0)) return axis.x_limit() * r_max;
    return std::max(0.0, axis.x_limit() - 3.0) * r_max + ra + rb;
}

// The largest pair_reach over elements whose radii are at most `largest_radius`
// (`has_points`: some element has radius 0, whose pairs use the longer point reach).
inline double max_pair_reach(const Axis& axis, double r_max, double largest_radius, bool has_points) {
    const double disks = largest_radius > 0.0 ? pair_reach(axis, r_max, largest_radius, largest_radius) : 0.0;
    return std::max(disks, has_points ? pair_reach(axis, r_max, 0.0, 0.0) : 0.0);
}

class NeighbourGrid {
public:
    NeighbourGrid() = default;

    // A grid over `bounds` (x, y) for ids 0 .. capacity - 1, cells of side >= `cell`
    // (grown so that there are at most about 4 cells per id: a tiny reach on a huge
    // domain must not allocate millions of empty cells). Points outside the bounds go
    // to the nearest border cell, so queries stay correct for them too.
    NeighbourGrid(const Box& bounds, double cell, int capacity) : lo_(bounds.lo), cell_of_(std::max(capacity, 0), -1) {
        const double w = std::max(bounds.hi.x - bounds.lo.x, 0.0), h = std::max(bounds.hi.y - bounds.lo.y, 0.0);
        cell_ = cell > 0.0 && std::isfinite(cell) ? cell : std::max({w, h, 1.0});
        const double max_cells = 4.0 * std::max(capacity, 1) + 64.0;
        while ((std::floor(w / cell_) + 1.0) * (std::floor(h / cell_) + 1.0) > max_cells) cell_ *= 1.5;
        nx_ = static_cast<int>(std::floor(w / cell_)) + 1;
        ny_ = static_cast<int>(std::floor(h / cell_)) + 1;
        inv_cell_ = 1.0 / cell_;
        cells_.assign(static_cast<size_t>(nx_) * ny_, {});
    }

    double cell_size() const { return cell_; }
    bool contains(int id) const { return cell_of_[id] >= 0; }

    // Adds id at p (id not present yet).
    void insert(int id, const Vec3& p) {
        const int c = cell_index(p);
        cells_[c].push_back({id, p.x, p.y});
        cell_of_[id] = c;
    }
    // Removes id (present).
    void remove(int id) {
        auto& cell = cells_[cell_of_[id]];
        cell.erase(std::find_if(cell.begin(), cell.end(), [&](const Entry& e) { return e.id == id; }));
        cell_of_[id] = -1;
    }
    // Moves id (present) to p.
    void move(int id, const Vec3& p) {
        const int c = cell_index(p);
        if (c == cell_of_[id]) {
            for (Entry& e : cells_[c])
                if (e.id == id) e.x = p.x, e.y = p.y;
            return;
        }
        remove(id);
        insert(id, p);
    }

    // Calls fn(id, squared_distance) for every id within `radius` of p (including an id
    // at p itself: callers skip the reference element), cell by cell in a fixed order.
    template <class Fn>
    void for_each_within(const Vec3& p, double radius, Fn&& fn) const {
        if (cells_.empty()) return;
        const double r2 = radius * radius;
        const int x0 = clamp_cell((p.x - radius - lo_.x) * inv_cell_, nx_);
        const int x1 = clamp_cell((p.x + radius - lo_.x) * inv_cell_, nx_);
        const int y0 = clamp_cell((p.y - radius - lo_.y) * inv_cell_, ny_);
        const int y1 = clamp_cell((p.y + radius - lo_.y) * inv_cell_, ny_);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x)
                for (const Entry& e : cells_[static_cast<size_t>(y) * nx_ + x]) {
                    const double dx = e.x - p.x, dy = e.y - p.y;
                    const double d2 = dx * dx + dy * dy;
                    if (d2 <= r2) fn(e.id, d2);
                }
    }

private:
    struct Entry {
        int id;
        double x, y;
    };

    // Clamped as a double first: a far-away point must not overflow the int cast.
    static int clamp_cell(double v, int n) {
        return static_cast<int>(std::clamp(std::floor(v), 0.0, static_cast<double>(n - 1)));
    }
    int cell_index(const Vec3& p) const {
        return clamp_cell((p.y - lo_.y) * inv_cell_, ny_) * nx_ + clamp_cell((p.x - lo_.x) * inv_cell_, nx_);
    }

    Vec3 lo_;
    double cell_ = 1.0, inv_cell_ = 1.0;
    int nx_ = 0, ny_ = 0;
    std::vector<std::vector<Entry>> cells_;
    std::vector<int> cell_of_;  // per id: its cell, -1 when absent
};

}  // namespace tessera::pcf
