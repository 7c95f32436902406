// Pair correlation g(r) per class pair, computed as spatstat 3.0's pcf / pcfcross
// with kernel = "gaussian", correction = "translate", divisor = "r" (see
// tests/data/spatstat/README.md and docs/metrics.md), so tessera's numbers can be
// held against R's:
//   g_ab(r) = |W| / (S(r) n_a n_b) sum_{i in a, j in b, i != j} k_h(r - d_ij) e_ij,
//   e_ij = |W| / |W ∩ (W + x_j - x_i)|,  S(r) = 2 pi r (2D), 4 pi r^2 (3D),
// n_a n_b -> n_a (n_a - 1) when a == b. spatstat bins distances for an FFT;
// here the kernel sums are exact, over the pairs with d < r_max + 5 h only.
//
// Each unordered pair is visited once (j > i). Its kernel weight goes to the
// curve (min(t_i, t_j), max(t_i, t_j)): twice when the classes agree (both
// ordered pairs belong to the sum), once when they differ (only the ordering
// i in a, j in b does). The edge weight is symmetric because
// |W ∩ (W + d)| = |W ∩ (W - d)| for every W.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "core/parallel.hpp"
#include "core/spatial_grid.hpp"
#include "metrics/points.hpp"
#include "tessera/error.hpp"
#include "tessera/metrics.hpp"
#include "tessera/option_table.hpp"

namespace tessera {
namespace {

constexpr int default_bins = 101;
constexpr double kernel_reach = 5.0;  // kernel truncated at 5 standard deviations (relative mass < 6e-7)

struct ResolvedOptions {
    double r_max = 0.0, bandwidth = 0.0;
    int bins = default_bins;
    int threads = 0;
};

// PcfOptions defaults (metrics.hpp): r_max 5 x mean nearest-neighbour distance,
// bandwidth r_max / 40, 101 bins.
ResolvedOptions resolve_options(const Exemplar& points, const PcfOptions& options) {
    check_options(pair_correlation_option_table(), options);  // names the field: "bins must be ..."
    ResolvedOptions r;
    r.bins = options.bins == 0 ? default_bins : options.bins;
    r.threads = options.threads;
    r.r_max = options.r_max;
    if (r.r_max == 0.0) {
        const double nn = points.elements.size() >= 2 ? nearest_neighbor_distances(points, options.threads).mean : 0.0;
        if (nn > 0.0) {
            r.r_max = 5.0 * nn;
        } else {
            // No spacing to go by (one element, or all coincide): a quarter of the
            // domain's smallest side keeps the estimate defined.
            const Vec3 size = points.domain.bounds().size();
            double side = std::numeric_limits<double>::infinity();
            for (int k = 0; k < points.dimension; ++k) side = std::min(side, size[k]);
            r.r_max = 0.25 * side;
        }
    }
    r.bandwidth = options.bandwidth > 0.0 ? options.bandwidth : r.r_max / 40.0;
    return r;
}

// Index of curve (a, b), a <= b, among T types in (a, b) order.
int curve_index(int a, int b, int types) { return a * types - a * (a - 1) / 2 + (b - a); }

// Adds weight * k_h(r_k - d) (without the 1 / (h sqrt(2 pi)) factor) to acc[k]
// for every bin k >= 1 within kernel_reach h of d. Consecutive Gaussian values
// differ by a ratio that itself shrinks by exp(-delta^2) per bin, so a pair costs
// three exp calls instead of one per bin.
void add_kernel(double d, double weight, double dr, double h, int bins, double* acc) {
    // Clamped in floating point first: with h >> r_max the bin indices exceed int.
    const int k_lo = static_cast<int>(std::max(1.0, std::ceil((d - kernel_reach * h) / dr)));
    const int k_hi = static_cast<int>(std::min<double>(bins - 1, std::floor((d + kernel_reach * h) / dr)));
    if (k_lo > k_hi) return;
    const double delta = dr / h;
    double u = (k_lo * dr - d) / h;
    if (delta > 0.5) {  // few bins per kernel: direct evaluation, no overflow risk
        for (int k = k_lo; k <= k_hi; ++k, u += delta) acc[k] += weight * std::exp(-0.5 * u * u);
        return;
    }
    double value = weight * std::exp(-0.5 * u * u);
    double ratio = std::exp(-u * delta - 0.5 * delta * delta);
    const double shrink = std::exp(-delta * delta);
    for (int k = k_lo; k <= k_hi; ++k) {
        acc[k] += value;
        value *= ratio;
        ratio *= shrink;
    }
}

}  // namespace

PcfResult pair_correlation(const Exemplar& points, const PcfOptions& options) {
    metrics::check_points(points, "pair correlation");
    const ResolvedOptions opt = resolve_options(points, options);
    const int dim = points.dimension;
    const int types = static_cast<int>(points.types.size());
    const int curves = types * (types + 1) / 2;
    const int bins = opt.bins;
    const double h = opt.bandwidth;
    const double dr = opt.r_max / (bins - 1);
    const Domain& domain = points.domain;
    domain.prepare_overlap(opt.threads);

    const std::vector<Vec3> p = metrics::element_positions(points);
    const int n = static_cast<int>(p.size());
    std::vector<int> type_of(n);
    std::vector<double> count(types, 0.0);
    for (int i = 0; i < n; ++i) type_of[i] = points.elements[i].type, count[type_of[i]] += 1.0;

    // Per-block accumulators over a fixed split of the points (independent of the
    // thread count), reduced in block order: the result is bit-for-bit the same on
    // any machine. Fewer blocks when there are many curves, to bound memory.
    const size_t stride = static_cast<size_t>(curves) * bins;
    const size_t budget = (size_t{32} << 20) / sizeof(double);
    const int blocks = static_cast<int>(std::clamp<size_t>(std::min<size_t>(budget / stride, n / 256 + 1), 1, 64));
    std::vector<double> partial(stride * blocks, 0.0);

    const double cutoff = opt.r_max + kernel_reach * h;
    core::SpatialGrid grid;
    grid.build(p, metrics::grid_cell(p, 0.5 * cutoff), dim);  // half-size cells: 5^d cells of 1/2^d volume scan fewer candidates
    core::parallel_for(blocks, core::resolve_threads(opt.threads), [&](int block_begin, int block_end, int) {
        for (int block = block_begin; block < block_end; ++block) {
            double* acc = partial.data() + stride * block;
            const int begin = static_cast<int>(static_cast<long long>(n) * block / blocks);
            const int end = static_cast<int>(static_cast<long long>(n) * (block + 1) / blocks);
            for (int i = begin; i < end; ++i) {
                grid.for_each_within(p[i], cutoff, [&](int j, double d2) {
                    if (j <= i) return;
                    const double overlap = domain.translated_overlap(p[j] - p[i]);
                    if (!(overlap > 0.0)) return;  // a pair no translate of W can hold
                    const int a = std::min(type_of[i], type_of[j]), b = std::max(type_of[i], type_of[j]);
                    const double multiplicity = a == b ? 2.0 : 1.0;
                    add_kernel(std::sqrt(d2), multiplicity / overlap, dr, h, bins,
                               acc + static_cast<size_t>(curve_index(a, b, types)) * bins);
                });
            }
        }
    });
    for (int block = 1; block < blocks; ++block)
        for (size_t k = 0; k < stride; ++k) partial[k] += partial[stride * block + k];

    PcfResult result;
    result.bandwidth = h;
    result.r.resize(bins);
    for (int k = 0; k < bins; ++k) result.r[k] = k * dr;
    result.r.back() = opt.r_max;
    const double area = domain.measure();
    const double kernel_norm = 1.0 / (h * std::sqrt(2.0 * std::numbers::pi));
    for (int a = 0; a < types; ++a)
        for (int b = a; b < types; ++b) {
            PcfCurve c;
            c.class_a = a, c.class_b = b;
            c.name_a = points.types[a].name, c.name_b = points.types[b].name;
            const double pairs = a == b ? count[a] * (count[a] - 1.0) : count[a] * count[b];
            const double* acc = partial.data() + static_cast<size_t>(curve_index(a, b, types)) * bins;
            c.g.resize(bins);
            c.g[0] = std::numeric_limits<double>::infinity();
            for (int k = 1; k < bins; ++k) {
                const double r = result.r[k];
                const double surface = dim == 2 ? 2.0 * std::numbers::pi * r : 4.0 * std::numbers::pi * r * r;
                // No possible pair (n_a n_b = 0): nothing observed, g = 0 by convention.
                c.g[k] = pairs > 0.0 ? area * area * kernel_norm * acc[k] / (surface * pairs) : 0.0;
            }
            result.curves.push_back(std::move(c));
        }
    return result;
}

}  // namespace tessera
