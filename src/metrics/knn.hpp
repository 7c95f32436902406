// k nearest neighbours of a point of a set, on top of core::SpatialGrid: gather
// the points within a radius, grow the radius until k were found (then the k
// nearest are surely among them), and keep the k closest with ties broken by
// index so that the answer is deterministic.
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "core/spatial_grid.hpp"

namespace tessera::metrics {

// Fills `out` with up to k (squared distance, index) pairs, nearest first, for
// point `self` (excluded). radius0 > 0 is the first search radius; the search
// stops at max_radius, so fewer than k come back only when fewer exist.
// `out` is reused scratch: no allocation once it has grown.
inline void k_nearest(const core::SpatialGrid& grid, const Vec3& p, int self, int k, double radius0,
                      double max_radius, std::vector<std::pair<double, int>>& out) {
    double radius = std::min(radius0, max_radius);
    for (;;) {
        out.clear();
        grid.for_each_within(p, radius, [&](int j, double d2) {
            if (j != self) out.emplace_back(d2, j);
        });
        if (static_cast<int>(out.size()) >= k || radius >= max_radius) break;
        radius = std::min(2.0 * radius, max_radius);
    }
    const int keep = std::min<int>(k, static_cast<int>(out.size()));
    std::partial_sort(out.begin(), out.begin() + keep, out.end());
    out.resize(keep);
}

}  // namespace tessera::metrics
