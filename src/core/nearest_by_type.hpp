// Nearest-neighbour distances between element classes: for every element of class a, the
// distance (centroid to centroid) to the nearest other element of class b. The crowding
// statistic (metrics) and the crowding repair both synthesis methods end with
// (core/crowding_repair.hpp) read the same numbers, so they are computed here once.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/spatial_grid.hpp"
#include "tessera/exemplar.hpp"

namespace tessera::core {

// Element centroids, z = 0 in 2D.
inline std::vector<Vec3> centroids_of(const Exemplar& data) {
    std::vector<Vec3> p;
    p.reserve(data.elements.size());
    for (const Element& e : data.elements) {
        Vec3 q = e.position;
        if (data.dimension == 2) q.z = 0.0;
        p.push_back(q);
    }
    return p;
}

// nearest[i * types + b]: distance from element i to the nearest other element of type b
// within `reach` (infinity beyond it or when b has no other element).
inline std::vector<double> nearest_by_type(const Exemplar& data, const std::vector<Vec3>& p,
                                           const SpatialGrid& grid, double reach) {
    const int types = static_cast<int>(data.types.size());
    std::vector<double> nearest(p.size() * static_cast<size_t>(types), std::numeric_limits<double>::infinity());
    for (size_t i = 0; i < p.size(); ++i) {
        double* row = &nearest[i * types];
        grid.for_each_within(p[i], reach, [&](int j, double d2) {
            if (static_cast<size_t>(j) == i) return;
            double& best = row[data.elements[j].type];
            best = std::min(best, std::sqrt(d2));
        });
    }
    return nearest;
}

// The q-quantile of `values` (linear interpolation between order statistics, R's type 7);
// `values` is reordered. NaN when empty.
inline double quantile_of(std::vector<double>& values, double q) {
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::sort(values.begin(), values.end());
    const double h = q * static_cast<double>(values.size() - 1);
    const size_t lo = static_cast<size_t>(std::floor(h));
    const size_t hi = std::min(values.size() - 1, lo + 1);
    return values[lo] + (h - static_cast<double>(lo)) * (values[hi] - values[lo]);
}

}  // namespace tessera::core
