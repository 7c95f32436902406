// Hexatic bond-orientational order |psi6| (Nelson & Halperin): for element i
// with bonds to its 6 nearest neighbours at angles theta_k,
//   psi6(i) = | (1/6) sum_k exp(6 i theta_k) |,
// 1 on a perfect hexagonal lattice, around 0.3-0.4 for uncorrelated points. It
// tells a crystalline output from a merely well-spaced one, which the PCF alone
// hides. Elements near the domain boundary are skipped: their neighbourhood is
// cut, so their bonds are not the pattern's.
#include <cmath>
#include <complex>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

#include "core/parallel.hpp"
#include "core/spatial_grid.hpp"
#include "metrics/knn.hpp"
#include "metrics/points.hpp"
#include "tessera/error.hpp"
#include "tessera/metrics.hpp"

namespace tessera {

double mean_psi6(const Exemplar& points, double boundary_margin) {
    metrics::check_points(points, "psi6");
    if (points.dimension != 2)
        throw Error(ErrorKind::option, "psi6 (hexatic order) is defined for 2D data only");
    if (!std::isfinite(boundary_margin) || boundary_margin < 0.0) {
        std::ostringstream s;
        s << "psi6 boundary margin must be a finite number >= 0 (0 = automatic), got " << boundary_margin;
        throw Error(ErrorKind::option, s.str());
    }
    constexpr int neighbours = 6;
    const double undefined = std::numeric_limits<double>::quiet_NaN();
    const std::vector<Vec3> p = metrics::element_positions(points);
    const int n = static_cast<int>(p.size());
    if (n <= neighbours) return undefined;

    const double nn_mean = nearest_neighbor_distances(points).mean;
    const double margin = boundary_margin > 0.0 ? boundary_margin : 1.5 * nn_mean;
    core::SpatialGrid grid;
    grid.build(p, metrics::grid_cell(p, metrics::typical_spacing(p, 2)), 2);
    const double max_radius = metrics::bounding_diagonal(p) * 1.001 + 1e-300;
    const double radius0 = nn_mean > 0.0 ? 2.5 * nn_mean : grid.cell_size();

    // Per-element slots (NaN = skipped), summed in element order afterwards.
    std::vector<double> value(n, undefined);
    const int threads = core::resolve_threads(0);
    std::vector<std::vector<std::pair<double, int>>> scratch(threads);
    core::parallel_for(n, threads, [&](int begin, int end, int thread) {
        auto& near = scratch[thread];
        for (int i = begin; i < end; ++i) {
            if (points.domain.distance_to_boundary(p[i]) < margin) continue;
            metrics::k_nearest(grid, p[i], i, neighbours, radius0, max_radius, near);
            std::complex<double> sum = 0.0;
            for (const auto& [d2, j] : near) {
                const double theta = std::atan2(p[j].y - p[i].y, p[j].x - p[i].x);
                sum += std::polar(1.0, neighbours * theta);
            }
            value[i] = std::abs(sum) / neighbours;
        }
    });
    double total = 0.0;
    int kept = 0;
    for (const double v : value)
        if (!std::isnan(v)) total += v, ++kept;
    return kept > 0 ? total / kept : undefined;
}

}  // namespace tessera
