// Shared helpers of the metrics module: the element positions every statistic
// works on (centroids, z dropped in 2D so that stray z values cannot leak into
// 2D distances) and the checks of the data the statistics accept.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "tessera/error.hpp"
#include "tessera/exemplar.hpp"

namespace tessera::metrics {

// Throws Error(input) naming `what` if the dimension is not 2 or 3, the domain's
// dimension differs, an element refers to an unknown type or has a non-finite position.
inline void check_points(const Exemplar& points, const std::string& what) {
    if (points.dimension != 2 && points.dimension != 3)
        throw Error(ErrorKind::input, what + ": dimension must be 2 or 3, got " + std::to_string(points.dimension));
    if (points.domain.dimension() != points.dimension)
        throw Error(ErrorKind::input, what + ": domain dimension differs from the data's dimension");
    for (size_t i = 0; i < points.elements.size(); ++i) {
        const int t = points.elements[i].type;
        if (t < 0 || t >= static_cast<int>(points.types.size()))
            throw Error(ErrorKind::input, what + ": element " + std::to_string(i) + " has an unknown element type");
        if (!is_finite(points.elements[i].position))
            throw Error(ErrorKind::input, what + ": element " + std::to_string(i) + " has a position that is not finite");
    }
}

// Element positions (centroids); z = 0 in 2D.
inline std::vector<Vec3> element_positions(const Exemplar& points) {
    std::vector<Vec3> p;
    p.reserve(points.elements.size());
    for (const auto& e : points.elements) {
        Vec3 q = e.position;
        if (points.dimension == 2) q.z = 0.0;
        p.push_back(q);
    }
    return p;
}

// Diagonal of the bounding box of `p` (0 for fewer than 2 points).
inline double bounding_diagonal(const std::vector<Vec3>& p) {
    if (p.size() < 2) return 0.0;
    Vec3 lo = p[0], hi = p[0];
    for (const auto& q : p)
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], q[k]), hi[k] = std::max(hi[k], q[k]);
    return norm(hi - lo);
}

// Typical spacing of n points over their bounding box, (box measure / n)^(1/d),
// a cell size for core::SpatialGrid. Degenerate axes borrow the largest extent.
inline double typical_spacing(const std::vector<Vec3>& p, int dimension) {
    if (p.size() < 2) return 1.0;
    Vec3 lo = p[0], hi = p[0];
    for (const auto& q : p)
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], q[k]), hi[k] = std::max(hi[k], q[k]);
    double largest = 0.0;
    for (int k = 0; k < dimension; ++k) largest = std::max(largest, hi[k] - lo[k]);
    if (!(largest > 0.0)) return 1.0;
    double measure = 1.0;
    for (int k = 0; k < dimension; ++k) measure *= hi[k] - lo[k] > 0.0 ? hi[k] - lo[k] : largest;
    return std::pow(measure / static_cast<double>(p.size()), 1.0 / dimension);
}

// A cell size for core::SpatialGrid over `p` that keeps the grid's per-axis cell
// counts far below INT_MAX even when a stray point lies very far away (the grid
// casts extent / cell to int before it coarsens itself).
inline double grid_cell(const std::vector<Vec3>& p, double wanted) {
    double extent = 0.0;
    if (!p.empty()) {
        Vec3 lo = p[0], hi = p[0];
        for (const auto& q : p)
            for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], q[k]), hi[k] = std::max(hi[k], q[k]);
        for (int k = 0; k < 3; ++k) extent = std::max(extent, hi[k] - lo[k]);
    }
    return std::max(wanted, extent * 1e-6);
}

}  // namespace tessera::metrics
