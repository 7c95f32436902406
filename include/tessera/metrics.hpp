// tessera/metrics.hpp — statistics that compare an arrangement with its exemplar:
// pair correlation per class pair (Gaussian kernel, translation edge correction,
// physical units), nearest-neighbour distances, hexatic order |psi6| (2D), and a
// JSON-ready report. Element positions (centroids) and element types are used.
#pragma once

#include <string>
#include <vector>

#include "tessera/exemplar.hpp"

namespace tessera {

struct PcfOptions {
    double r_max = 0.0;      // largest r; 0 = automatic: 5 x mean nearest-neighbour distance
    double bandwidth = 0.0;  // Gaussian kernel standard deviation; 0 = automatic: r_max / 40
    int bins = 0;            // number of r values (r_k = k r_max / (bins - 1)); 0 = 101 (>= 2)
};

// g(r) for one ordered class pair (a, b), a <= b.
struct PcfCurve {
    int class_a = 0, class_b = 0;   // type indices
    std::string name_a, name_b;     // type names
    std::vector<double> g;          // one value per r; +inf at r = 0
};

struct PcfResult {
    std::vector<double> r;
    std::vector<PcfCurve> curves;   // one per class pair with a <= b, in (a, b) order
    double bandwidth = 0.0;
};

// Standard pair correlation estimate (spatstat's pcf / pcfcross with
// kernel="gaussian", correction="translate", divisor="r"):
//   g_ab(r) = |W| / (S(r) n_a n_b) sum_{i in a, j in b, i != j} k_h(r - d_ij) e_ij,
//   e_ij = |W| / |W ∩ (W + x_j - x_i)|,  S(r) = 2 pi r (2D) or 4 pi r^2 (3D),
// with n_a n_b replaced by n_a (n_a - 1) when a == b.
PcfResult pair_correlation(const Exemplar& points, const PcfOptions& options = {});

// Relative L2 difference between two PCFs on the same r grid and class pairs,
// over r >= 3 x bandwidth: sqrt(sum (g_a - g_b)^2 / sum g_a^2), pooled over pairs.
double pcf_relative_error(const PcfResult& reference, const PcfResult& other);

// The PCF of `points` on the r values and bandwidth of `grid` (another PCF), so the two
// can be compared.
PcfResult pair_correlation_on_grid_of(const Exemplar& points, const PcfResult& grid);

// What `tessera metrics` reports as pcf_relative_error: the output's PCF against the
// exemplar's (`options` set the exemplar's grid; the output uses the same one).
double pcf_relative_error(const Exemplar& exemplar, const Exemplar& output, const PcfOptions& options = {});

struct NearestNeighborStats {
    double mean = 0.0, stddev = 0.0, min = 0.0, max = 0.0;
    std::vector<double> distances;   // per element, element order
};
NearestNeighborStats nearest_neighbor_distances(const Exemplar& points);

// Hexatic order |psi6| of each element: |1/6 sum_k exp(6 i theta_k)| over its 6
// nearest neighbours (2D only). Elements closer than `boundary_margin` to the domain
// boundary are skipped (their neighbourhood is cut); 0 = automatic: 1.5 x mean
// nearest-neighbour distance. Returns the mean over the elements kept.
double mean_psi6(const Exemplar& points, double boundary_margin = 0.0);

// Report comparing an exemplar and an output, as JSON text (what `tessera metrics` prints).
std::string metrics_report_json(const Exemplar& exemplar, const Exemplar& output,
                                const PcfOptions& options = {});

}  // namespace tessera
