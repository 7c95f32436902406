// Spacing statistics of an exemplar that set the automatic defaults of the solver.
#include <cmath>
#include <limits>
#include <vector>

#include "core/spatial_grid.hpp"
#include "tessera/det.hpp"

namespace tessera {

double mean_nearest_neighbor_distance(const Exemplar& exemplar) {
    const int n = static_cast<int>(exemplar.elements.size());
    if (n < 2) return 0.0;
    std::vector<Vec3> centers(n);
    for (int i = 0; i < n; ++i) centers[i] = exemplar.elements[i].position;
    // Cell size from the mean spacing of a uniform pattern of the same density.
    const Box b = exemplar.domain.bounds();
    const int d = exemplar.dimension;
    const double cell = std::pow(exemplar.domain.measure() / n, 1.0 / d);
    core::SpatialGrid grid;
    grid.build(centers, cell, d);
    const double max_r = 2.0 * norm(b.size()) + 1.0;
    double sum = 0.0;
    int counted = 0;
    for (int i = 0; i < n; ++i) {
        const int j = grid.nearest(centers[i], max_r, [i](int k) { return k != i; });
        if (j < 0) continue;
        const Vec3 diff = centers[j] - centers[i];
        sum += d == 2 ? std::hypot(diff.x, diff.y) : norm(diff);
        ++counted;
    }
    return counted ? sum / counted : 0.0;
}

// About two rings in 2D (the second hexagonal ring lies at 1.73 spacings); the
// first shell in 3D, where a second shell would triple the neighbourhood's size
// (and the matching cost) for little gain.
double default_radius_factor(int dimension) { return dimension == 3 ? 1.5 : 2.0; }

double default_radius(const Exemplar& exemplar) {
    return default_radius_factor(exemplar.dimension) * mean_nearest_neighbor_distance(exemplar);
}

}  // namespace tessera
