// Nearest-neighbour distance of every element (to any other element, whatever
// its class) and their summary statistics. One grid query per element, run in
// parallel into per-element slots, then summed in element order so the result
// does not depend on the thread count.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel.hpp"
#include "core/spatial_grid.hpp"
#include "metrics/points.hpp"
#include "tessera/metrics.hpp"

namespace tessera {

NearestNeighborStats nearest_neighbor_distances(const Exemplar& points, int threads) {
    metrics::check_points(points, "nearest-neighbour distances");
    const std::vector<Vec3> p = metrics::element_positions(points);
    const int n = static_cast<int>(p.size());
    NearestNeighborStats stats;
    // Fewer than two elements: no neighbour exists; distances are +inf and the
    // summary stays 0 (documented in docs/metrics.md).
    stats.distances.assign(n, std::numeric_limits<double>::infinity());
    if (n < 2) return stats;

    core::SpatialGrid grid;
    grid.build(p, metrics::grid_cell(p, metrics::typical_spacing(p, points.dimension)), points.dimension);
    const double max_radius = metrics::bounding_diagonal(p) * 1.001 + 1e-300;
    core::parallel_for(n, core::resolve_threads(threads), [&](int begin, int end, int) {
        for (int i = begin; i < end; ++i) {
            const int j = grid.nearest(p[i], max_radius, [i](int k) { return k != i; });
            // j >= 0 always: max_radius spans all points (z is 0 in 2D).
            stats.distances[i] = j < 0 ? 0.0 : norm(p[j] - p[i]);
        }
    });

    double sum = 0.0;
    stats.min = std::numeric_limits<double>::infinity();
    stats.max = 0.0;
    for (const double d : stats.distances) {
        sum += d;
        stats.min = std::min(stats.min, d);
        stats.max = std::max(stats.max, d);
    }
    stats.mean = sum / n;
    double var = 0.0;  // population variance, two-pass for accuracy
    for (const double d : stats.distances) var += (d - stats.mean) * (d - stats.mean);
    stats.stddev = std::sqrt(var / n);
    return stats;
}

}  // namespace tessera
