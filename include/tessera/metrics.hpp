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
    int threads = 0;         // worker threads, 0 = all; the result is the same for any value
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
// over r >= bandwidth: sqrt(sum (g_a - g_b)^2 / sum g_a^2), pooled over pairs.
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
NearestNeighborStats nearest_neighbor_distances(const Exemplar& points, int threads = 0);  // 0 = all threads

// Hexatic order |psi6| of each element: |1/6 sum_k exp(6 i theta_k)| over its 6
// nearest neighbours (2D only). Elements closer than `boundary_margin` to the domain
// boundary are skipped (their neighbourhood is cut); 0 = automatic: 1.5 x mean
// nearest-neighbour distance. Returns the mean over the elements kept.
double mean_psi6(const Exemplar& points, double boundary_margin = 0.0);

// --- Defects a user sees at a glance (docs/metrics.md, "Defects") ---

// Crowding of one ordered class pair (a, b): `threshold` is the exemplar's `quantile`
// (1% by default; linear interpolation) of the distances from an a element to its nearest
// b element; the shares are the fractions of a elements whose nearest b is not farther
// (<=: an exemplar whose closest pair is mutual still has a share above 0).
// An output with many more such elements than the exemplar has near-duplicates or
// crowded seams. `*_coincident` count a elements with a b closer than threshold / 100.
struct CrowdingPair {
    int class_a = 0, class_b = 0;  // exemplar type indices
    std::string name_a, name_b;
    double threshold = 0.0;
    double exemplar_share = 0.0, output_share = 0.0;
    int exemplar_coincident = 0, output_coincident = 0;
    long output_elements = 0;      // a elements in the output
};
// One entry per ordered class pair of which the exemplar has at least 2 distances and
// whose names the output also has. Positions are element centroids.
std::vector<CrowdingPair> crowding(const Exemplar& exemplar, const Exemplar& output, double quantile = 0.01);

// The largest ball (circle in 2D) inside the domain that holds no sample: no sample
// centre and, for elements with a radius, no part of their disk. A hole or a vacancy in
// an output shows as a radius above the exemplar's. Found on a lattice of a fifth of the
// typical spacing (a third in 3D) refined by a pattern search: within a few percent.
struct EmptyCircle {
    double radius = 0.0;
    Vec3 center;
};
EmptyCircle largest_empty_circle(const Exemplar& data, int threads = 0);  // 0 = all threads

// Shapes of multi-sample elements, per type the exemplar and the output share: the mean
// distance between consecutive samples in both, the 95th percentile of the output's
// relative deviation from the exemplar's mean length of the same segment, and the 95th
// percentile of the bend (degrees) between consecutive segments in both.
struct ShapeStats {
    std::string type;
    bool rigid = true;
    double spacing_exemplar = 0.0, spacing_output = 0.0, spacing_deviation_p95 = 0.0;
    double bend_exemplar_p95 = 0.0, bend_output_p95 = 0.0;
};
std::vector<ShapeStats> shape_statistics(const Exemplar& exemplar, const Exemplar& output);

// Share of the samples inside the data's own domain (Domain::inside, exact for every kind).
double inside_fraction(const Exemplar& data);

// Report comparing an exemplar and an output, as JSON text (what `tessera metrics` prints).
std::string metrics_report_json(const Exemplar& exemplar, const Exemplar& output,
                                const PcfOptions& options = {});

}  // namespace tessera
