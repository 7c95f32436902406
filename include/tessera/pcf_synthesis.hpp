// tessera/pcf_synthesis.hpp — multi-class distributions of (possibly overlapping) disks
// from pair correlation functions: Ecormier-Nocca, Memari, Gain and Cani, "Accurate
// Synthesis of Multi-Class Disk Distributions" (Eurographics 2019), sections 3 to 5,
// Algorithm 1, Equations 1 to 11. The second synthesis method beside det.hpp
// (`tessera synth --method pcf`), 2D only.
//
// Distances on the PCF axis are normalised by r_max (Eq. 1, from the density of the
// exemplar's elements in the domain, all classes together):
//   - points (both radii 0): x = d / r_max;
//   - disks: x = f_norm(d, r1, r2) (Eq. 7 to 10), which maps the salient configurations
//     to fixed values: inner border (d = r1 - r2) -> 1, centre on the border (d = r1) -> 2,
//     outer border / tangent (d = r1 + r2) -> 3. Beyond contact Eq. 10 as printed is not
//     continuous (f - 4 r1 + 2 r2 + 3 gives 3 + 4 r2 at tangency); tessera uses
//     x = 3 + (d - r1 - r2) / r_max, continuous, so the axis beyond 3 is the gap between
//     the disks in units of r_max. Equal radii (r1 = r2): the nested branch collapses to
//     d = 0 -> x = 0. The Euclidean centre distance is kept for r_max and for the
//     boundary correction, as the paper does.
// The PCF of Eq. 2 in a domain W of area |W| for an ordered class pair (a, b):
//   PCF_ab(x_k) = |W| / (A_k n_a n_b) * sum_{i in a, j in b, i != j} step k_sigma(x_k - x_ij) / c_i(d_ij)
// with the ring area A_k = 2 pi x_k step r_max^2 (x_k >= step / 2) (step k_sigma is the
// kernel's mass in a bin, so the sum counts neighbours in the ring and a uniform random
// point pattern gives PCF = 1; for disks, whose x beyond 3 is not a centre distance, it
// tends to (x - 3 + (r1 + r2) / r_max) / x instead, as in the paper), the paper's kernel
// k_sigma(t) = exp(-t^2 / sigma^2) / (sqrt(pi) sigma), n_a n_b -> n_a (n_a - 1) when a == b,
// and c_i(d) the fraction of the circle of radius d around P_i that lies in W, at the
// pair's Euclidean centre distance d_ij (the perimeter-fraction boundary correction of
// section 3.1; for points it is the paper's per-ring weight c_i(x_k r_max) up to the
// kernel's width). Individual PCFs (Eq. 3) are the same sum restricted to one reference
// element i, divided by n_b (n_a - 1 when a == b) instead of n_a n_b, so the mean PCF is
// their average; their lower and upper envelopes over the exemplar's elements bound the
// validity region (section 5.1). src/pcf/pcf_accumulate.hpp holds this arithmetic.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tessera/domain.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/progress.hpp"

namespace tessera {

// Analysis parameters (the paper's section 6 values are the defaults).
struct PcfAnalysisSettings {
    double sigma = 0.25;   // Gaussian kernel width on the normalised axis, > 0
    double step = 0.1;     // spacing of the PCF's x values on the normalised axis, > 0
    double extent = 5.0;   // neighbourhood: points up to x = extent; disks up to x = 3 + extent; > 0
};

// The disk metric f (Eq. 7 to 9); radii in either order, >= 0.
double disk_metric(double d, double ra, double rb);
// The normalised disk metric on the PCF axis (see above); points when both radii are 0.
double disk_metric_normalised(double d, double ra, double rb, double r_max);
// r_max of Eq. 1 for n elements in an area: 2 sqrt(area / (2 sqrt(3) n)).
double pcf_r_max(double area, int n);

// One PCF of the model: mean (Eq. 2) and the envelopes of the individual PCFs (Eq. 3).
struct PcfEnvelope {
    int parent = 0, child = 0;    // class indices: the child depends on the parent (equal: within a class)
    std::vector<double> mean;     // one value per x of PcfModel::x
    std::vector<double> lower;    // lowest individual PCF at each x (over the child's elements)
    std::vector<double> upper;    // highest individual PCF at each x
};

// Two classes without a PCF between them (neither depends on the other): the closest
// approach of their elements in the exemplar on the normalised axis, at most the end of
// the salient configurations plus one kernel width (3 + sigma for disks, sigma for
// points). Synthesis keeps every pair of elements of these classes at least this far
// apart, so that classes the dependency graph leaves unrelated do not overlap (or nest)
// where the exemplar's never do. 0 when the exemplar has such a pair at distance 0.
struct PcfSeparation {
    int a = 0, b = 0;  // class indices, a < b
    double x = 0.0;    // on the normalised axis
};

// A class with fewer than kPcfSparseCount elements (a forest's single aspen): its own
// PCF has at most 6 pairs and its envelopes are those few curves, too little to place
// anything by. Its PCFs stay in the model (measured like the others) but synthesis
// places it by this fallback instead (docs/pcf_synthesis.md, "Classes with few
// elements"): its density (the count per area), at least `spacing` between its own
// elements, no closer to any class than its exemplar elements come (`closest`), and
// each element within `tether` of an element of every parent class (the farthest
// nearest-parent distance of its exemplar elements plus one kernel width). The PCFs
// of its children on it are left out of their placement as well (they have at most 3
// neighbours per reference); `closest` keeps the children off it instead.
inline constexpr int kPcfSparseCount = 4;
struct PcfSparseClass {
    int cls = 0;
    double spacing = 0.0;         // data units: the closest two of its elements (half the
                                  // mean spacing sqrt(area / count) for a single element)
    std::vector<double> closest;  // per class (normalised axis): its closest approach; own entry 0
    std::vector<double> tether;   // per class (normalised axis): for parents, the farthest nearest-
                                  // element distance; 0 for the other classes (no tether)
};

// The analysed exemplar: everything synthesis needs.
struct PcfModel {
    std::vector<std::string> classes;        // element type names, in the exemplar's order
    std::vector<std::vector<int>> parents;   // dependency DAG: parents[c] = the classes c depends on
    std::vector<int> order;                  // a topological order of the classes
    std::vector<PcfEnvelope> pcfs;           // one per class (within) and one per DAG edge
    std::vector<PcfSeparation> separations;  // one per pair of classes without an edge, (a, b) in index order
    std::vector<PcfSparseClass> sparse;      // the classes with fewer than kPcfSparseCount elements, in index order
    std::vector<double> x;                   // the normalised axis: x_k = k * step
    std::vector<int> counts;                 // elements per class in the exemplar
    std::vector<std::vector<double>> radii;  // per class: the exemplar's radii, sorted largest first
    bool disks = false;                      // some element has a radius > 0
    double r_max = 0.0;                      // Eq. 1, data units
    double area = 0.0;                       // |W| of the exemplar's domain
    PcfAnalysisSettings settings;
};

// Analyses an exemplar (2D, single-sample elements). The dependency graph comes from the
// types (ElementType::depends_on); a type without one depends on every earlier type.
// Throws Error(input) naming the class for: a class without elements, a
// radius < 0, a dependency cycle (naming the classes on it) or an unknown class name;
// Error(option) for bad settings; Error(input) for 3D data or multi-sample elements.
// `threads`: worker threads (0 = all); the model is the same for any value.
PcfModel analyze_distribution(const Exemplar& exemplar, const PcfAnalysisSettings& settings = {}, int threads = 0);

// The model as JSON (`tessera analyze -o model.json`) and back.
std::string pcf_model_to_json(const PcfModel& model);
PcfModel pcf_model_from_json(const std::string& text, const std::string& source);

// PCFs of an arrangement on a model's axis and class pairs (r_max and settings of the
// model, the arrangement's own domain and counts): mean and envelopes, in model.pcfs order.
std::vector<PcfEnvelope> measure_distribution(const PcfModel& model, const Exemplar& data, int threads = 0);

struct PcfSynthOptions {
    PcfAnalysisSettings analysis;
    std::uint64_t seed = 1;
    int threads = 0;                  // 0 = all hardware threads; results identical for any value
    // Initialisation (Algorithm 1): threshold eps = epsilon0 + epsilon_step * fails; after
    // max_fails successive rejections, grid search (grid_cells cells along the longer side).
    double epsilon0 = 0.0;
    double epsilon_step = 0.001;
    int max_fails = 1000;
    int grid_cells = 64;
    // Refinement (Eq. 4 to 6): at most max_iterations sweeps per class; stops when a sweep
    // moves the elements by less than convergence * r_max in total (0: never), or when the
    // class's lowest PCF error fell by less than a fraction `stall` per sweep over the last
    // 10 sweeps (0: never); the class is left at its lowest error.
    int max_iterations = 100;
    double convergence = 3e-3;
    double stall = 5e-3;
    // Re-initialise elements whose individual PCF leaves the validity region after
    // refinement (section 6.4), at most this many rounds.
    int outlier_rounds = 2;
    // Synthesis from an exemplar: sweeps of the final pair-correlation relaxation (every
    // class pair's g(r) towards the exemplar's, docs/pcf_synthesis.md); 0 = off, <= 1000.
    int relax_sweeps = 4;
};

// Synthesizes the model's distribution in `domain` (2D: box or polygon, any size): element
// counts = the exemplar's density x the domain's area per class. Returns the arrangement
// (single-sample elements with their radii) and stats (method "pcf", the refinement error
// per iteration in stats.energy, bound hits in stats.solver_bound_hits and notes of
// fallbacks). Throws Error(domain) when the domain is too small for one element of some
// class, Error(option) for bad options, Cancelled when progress returns false.
Arrangement synthesize_pcf(const PcfModel& model, const Domain& domain, const PcfSynthOptions& options = {},
                           const Progress& progress = {});
// Synthesis next to elements that stay where they are (a world's tile next to its finished
// neighbours, tessera/world.hpp): `fixed` (single-sample elements of the model's classes,
// types in the model's order, inside `domain`) count in every PCF, and nothing moves them.
// The new elements, the model's density times the area of `fill` (the part of `domain`
// the fixed elements leave empty), are placed and stay inside `fill`; the result holds
// the new elements only. Each class is synthesized after its
// fixed elements are in, so the new ones continue their pattern. Error(input) naming the
// element for a fixed element of another class, with several samples or outside the domain.
Arrangement synthesize_pcf_next_to(const PcfModel& model, const Domain& domain, const Exemplar& fixed,
                                   const Domain& fill, const PcfSynthOptions& options = {},
                                   const Progress& progress = {});
// The same from the model's exemplar, then its passes (relaxation, holes, crowding repair,
// as synthesize_pcf from an exemplar runs them) over the fixed and the new elements
// together, the fixed ones never moving; returns the new elements, with the exemplar's types.
Arrangement synthesize_pcf_next_to(const Exemplar& exemplar, const PcfModel& model, const Domain& domain,
                                   const Exemplar& fixed, const Domain& fill, const PcfSynthOptions& options = {},
                                   const Progress& progress = {});
// analyze_distribution(exemplar, options.analysis) + synthesize_pcf.
Arrangement synthesize_pcf(const Exemplar& exemplar, const Domain& domain, const PcfSynthOptions& options = {},
                           const Progress& progress = {});

// The salient disk configurations of section 4.1, counted over pairs of disks whose
// centres are closer than the sum of radii plus `margin` (all pairs within a class pair):
// disjoint (gap > tolerance), tangent (|gap| <= tolerance), overlapping, nested (one inside
// the other). `tolerance` is relative to the smaller radius.
struct DiskConfigurationShares {
    double disjoint = 0, tangent = 0, overlapping = 0, nested = 0;  // fractions, sum 1 (0 when no pairs)
    int pairs = 0;
};
DiskConfigurationShares disk_configurations(const Exemplar& data, double margin, double tolerance = 0.05);

// How well an output reproduces a model (the acceptance measures).
struct PcfQuality {
    std::vector<double> inside_fraction;  // per model PCF: share of x values where the output's mean PCF
                                          // lies within [lower, upper] of the model
    std::vector<double> count_ratio;      // per class: output count / (model density x output area)
    DiskConfigurationShares input_shares, output_shares;
};
PcfQuality compare_distribution(const PcfModel& model, const Exemplar& exemplar, const Exemplar& output);

}  // namespace tessera
