// A uniform grid over a fixed set of points for fixed-radius neighbour queries,
// the hot query of neighbourhood matching. Points are bucketed by a counting
// sort into one flat index array (no per-cell allocation); a query visits the
// 3^d cells around the point. Serves 2D (z ignored) and 3D alike.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "tessera/vec.hpp"

namespace tessera::core {

class SpatialGrid {
public:
    SpatialGrid() = default;

    // Builds over `points` with cells of side >= cell_size (grown if the grid would
    // exceed about 4 cells per point). dimension 2 ignores z.
    void build(const std::vector<Vec3>& points, double cell_size, int dimension) {
        points_ = &points;
        dimension_ = dimension;
        const int n = static_cast<int>(points.size());
        lo_ = Vec3{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), 0.0};
        Vec3 hi{std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest(), 0.0};
        if (dimension == 3) lo_.z = std::numeric_limits<double>::max(), hi.z = std::numeric_limits<double>::lowest();
        for (const auto& p : points)
            for (int k = 0; k < dimension; ++k) lo_[k] = std::min(lo_[k], p[k]), hi[k] = std::max(hi[k], p[k]);
        if (n == 0) lo_ = hi = Vec3{};
        cell_ = cell_size > 0.0 ? cell_size : 1.0;
        const double max_cells = 4.0 * std::max(n, 1) + 64.0;
        // Extents are measured in doubles before any int conversion, so a far-away
        // point coarsens the grid instead of overflowing a cell count.
        for (;;) {
            double total = 1.0;
            double counts[3] = {1.0, 1.0, 1.0};
            for (int k = 0; k < dimension; ++k) {
                counts[k] = std::floor((hi[k] - lo_[k]) / cell_) + 1.0;
                total *= counts[k];
            }
            if (total <= max_cells) {
                for (int k = 0; k < 3; ++k) dims_[k] = static_cast<int>(counts[k]);
                break;
            }
            cell_ *= std::max(1.5, std::pow(total / max_cells, 1.0 / dimension));
        }
        inv_cell_ = 1.0 / cell_;
        const int cells = dims_[0] * dims_[1] * dims_[2];
        start_.assign(cells + 1, 0);
        cell_of_.resize(n);
        for (int i = 0; i < n; ++i) {
            cell_of_[i] = cell_index(points[i]);
            ++start_[cell_of_[i] + 1];
        }
        for (int c = 0; c < cells; ++c) start_[c + 1] += start_[c];
        items_.resize(n);
        std::vector<int> fill(start_.begin(), start_.end() - 1);
        for (int i = 0; i < n; ++i) items_[fill[cell_of_[i]]++] = i;  // stable: index order within a cell
    }

    double cell_size() const { return cell_; }

    // Calls fn(index, squared_distance) for every point within `radius` of p
    // (radius <= cell size visits 3^d cells; larger radii visit more).
    template <class Fn>
    void for_each_within(const Vec3& p, double radius, Fn&& fn) const {
        if (items_.empty()) return;
        const double r2 = radius * radius;
        int lo[3], hi[3];
        for (int k = 0; k < 3; ++k) {
            if (k < dimension_) {
                // Clamped as doubles first: a huge radius must not overflow the int cast.
                lo[k] = static_cast<int>(std::clamp(std::floor((p[k] - radius - lo_[k]) * inv_cell_), 0.0,
                                                    static_cast<double>(dims_[k] - 1)));
                hi[k] = static_cast<int>(std::clamp(std::floor((p[k] + radius - lo_[k]) * inv_cell_), -1.0,
                                                    static_cast<double>(dims_[k] - 1)));
            } else {
                lo[k] = hi[k] = 0;
            }
        }
        const auto& pts = *points_;
        for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y) {
                const int row = (z * dims_[1] + y) * dims_[0];
                for (int c = row + lo[0]; c <= row + hi[0]; ++c)
                    for (int it = start_[c]; it < start_[c + 1]; ++it) {
                        const int i = items_[it];
                        const Vec3 d = pts[i] - p;
                        const double d2 = dimension_ == 2 ? d.x * d.x + d.y * d.y : squared_norm(d);
                        if (d2 <= r2) fn(i, d2);
                    }
            }
    }

    // Nearest point to p accepted by `accept(index)`, searching shells of cells
    // outward up to `max_radius`; returns -1 if none. Ties go to the lower index.
    template <class Accept>
    int nearest(const Vec3& p, double max_radius, Accept&& accept) const {
        int best = -1;
        double best_d2 = max_radius * max_radius;
        double radius = cell_;
        for (;;) {
            for_each_within(p, std::min(radius, max_radius), [&](int i, double d2) {
                if ((d2 < best_d2 || (d2 == best_d2 && (best < 0 || i < best))) && accept(i)) best = i, best_d2 = d2;
            });
            if (best >= 0 || radius >= max_radius) return best;
            radius *= 2.0;
        }
    }

private:
    int cell_index(const Vec3& p) const {
        int c[3] = {0, 0, 0};
        for (int k = 0; k < dimension_; ++k)
            c[k] = static_cast<int>(
                std::clamp(std::floor((p[k] - lo_[k]) * inv_cell_), 0.0, static_cast<double>(dims_[k] - 1)));
        return (c[2] * dims_[1] + c[1]) * dims_[0] + c[0];
    }

    const std::vector<Vec3>* points_ = nullptr;
    int dimension_ = 2;
    Vec3 lo_;
    double cell_ = 1.0, inv_cell_ = 1.0;
    int dims_[3] = {1, 1, 1};
    std::vector<int> start_, items_, cell_of_;
};

}  // namespace tessera::core
