#include "det/structure_range.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tessera/metrics.hpp"

namespace tessera::det {
namespace {

constexpr int bins = 101;
constexpr double noise_factor = 3.0;  // |g - 1| beyond 3 standard deviations of the estimate is structure
constexpr double min_threshold = 0.1; // and beyond 10% whatever the count (very large exemplars)

// End of the first structured stretch of one curve over `pairs` ordered pairs: bins
// (from 3 bandwidths on) where |g(r) - 1| exceeds the noise threshold are structured;
// the stretch ends at the last structured bin before `quiet` of r without one. Stopping
// there, rather than at the last structured bin overall, keeps chance bumps at large r
// out: a clustered pattern of few clusters fluctuates far more than the Poisson noise
// says. 0 when the curve starts with such a quiet run (no structure).
double structured_stretch(const PcfResult& pcf, const std::vector<double>& g, double pairs, double measure,
                          int dimension, double quiet) {
    if (pairs < 1.0) return 0.0;
    const double h = pcf.bandwidth;
    double start = -1.0, last = 0.0;
    for (size_t k = 1; k < g.size(); ++k) {
        const double r = pcf.r[k];
        if (r < 3.0 * h || !std::isfinite(g[k])) continue;
        if (start < 0.0) start = r;
        const double surface = dimension == 2 ? 2.0 * std::numbers::pi * r : 4.0 * std::numbers::pi * r * r;
        const double sd = std::sqrt(measure / (surface * pairs * h * std::sqrt(std::numbers::pi)));
        if (std::abs(g[k] - 1.0) > std::max(min_threshold, noise_factor * sd))
            last = r;
        else if (r - std::max(last, start) >= quiet)
            break;
    }
    return last;
}

}  // namespace

double structure_range(const Exemplar& exemplar, double spacing, double r_limit, int threads) {
    const size_t n = exemplar.elements.size();
    if (n < 3 || !(r_limit > 0.0) || !(spacing > 0.0)) return 0.0;
    const double measure = exemplar.domain.measure();
    if (!(measure > 0.0)) return 0.0;

    // Only centroids and classes matter: a light copy without samples or attributes.
    Exemplar points;
    points.dimension = exemplar.dimension;
    points.domain = exemplar.domain;
    points.types = exemplar.types;
    points.elements.reserve(n);
    std::vector<double> count(exemplar.types.size(), 0.0);
    for (const Element& e : exemplar.elements) {
        Element light;
        light.type = e.type;
        light.position = e.position;
        points.elements.push_back(light);
        count[e.type] += 1.0;
    }
    // Smoothing: a quarter spacing resolves the first peaks; r_limit / 50 keeps the
    // estimate of a large range from chasing single pairs.
    PcfOptions options;
    options.r_max = r_limit;
    options.bins = bins;
    options.bandwidth = std::max(0.25 * spacing, r_limit / 50.0);
    options.threads = threads;

    // A structured stretch ends after two spacings (or a tenth of the range examined)
    // without structure: longer than the gaps between a lattice's peaks.
    const double quiet = std::max(2.0 * spacing, 0.1 * r_limit);
    double range = 0.0;
    if (points.types.size() > 1) {
        const PcfResult by_class = pair_correlation(points, options);
        for (const PcfCurve& c : by_class.curves) {
            const double pairs = c.class_a == c.class_b ? count[c.class_a] * (count[c.class_a] - 1.0)
                                                        : count[c.class_a] * count[c.class_b];
            range = std::max(range, structured_stretch(by_class, c.g, pairs, measure, points.dimension, quiet));
        }
        for (Element& e : points.elements) e.type = 0;
        points.types.resize(1);
    }
    const PcfResult pooled = pair_correlation(points, options);
    const double n_d = static_cast<double>(n);
    range = std::max(range, structured_stretch(pooled, pooled.curves[0].g, n_d * (n_d - 1.0), measure,
                                              points.dimension, quiet));
    return range;
}

}  // namespace tessera::det
