// The incremental state of PCF synthesis (pcf_synthesis.hpp, sections 3 to 5): the
// output elements placed so far, a uniform grid over the output domain for neighbour
// queries, each element's boundary correction, and for every model PCF the running sum
// of Eq. 2, so that adding, moving or removing one element costs O(neighbours x kernel
// bins) instead of a new analysis. Private to the library.
//
// Conventions (the header's): a model PCF (parent p, child c) has reference elements in
// the child class and neighbours in the parent class; within a class both ends of a pair
// are references. Its mean is norm_k * sum_k with
//   sum_k  = sum over (reference i, neighbour j) of k_sigma(x_k - x_ij) / c_i(x_k),
//   norm_k = |W| / (A_k n_child n_parent'), n_parent' = n - 1 within a class,
// and the individual PCF of a reference i is ind_norm_k / c_i(x_k) * sum_j k_sigma(x_k - x_ij)
// with ind_norm_k = |W| / (A_k n_parent). n are the final output counts throughout, so
// during initialisation the PCFs grow towards their targets from below (as in [OG12]).
//
// Boundary correction: c_i(x_k) = circle_inside_fraction at the element's position,
// computed for all bins when an element is placed or moved, and bin by bin for
// candidates and trial positions (only the bins their pairs touch). Bins whose circle
// lies inside the domain (radius <= distance to the boundary) need no sampling. The
// estimate is coarse where few of its 64 points are inside (1 / c up to 64), so it is
// always taken at the exact position: a shifted one lets the refinement chase noise.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "pcf/pair_distance.hpp"
#include "pcf/pcf_math.hpp"
#include "tessera/domain.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera::pcf {

// Eq. 11 divides differences by the target value; where a target is (close to) 0 that
// would divide by 0, so tessera divides by max(target, floor) instead, with floor = 1% of
// the value an uncorrelated distribution has (the PCF of Eq. 2 with the ring width
// step * r_max is 1 / step there): an excess of 1% of that where the exemplar has nothing
// counts as a 100% error.
inline constexpr double kFloorShare = 0.01;

// The distances of the refinement's trial moves, in units of r_max (section 3.1).
inline constexpr double kTrialSteps[] = {1e-1, 1e-2, 1e-3, 1e-4, 1e-5};
inline constexpr double kMaxMove = 1e-1;

// One model PCF during synthesis.
struct Term {
    int parent = 0, child = 0;
    bool within = false;
    std::vector<double> norm;      // mean PCF = norm_k * sum_k (0 when the class pair has no pairs)
    std::vector<double> ind_norm;  // individual PCF = ind_norm_k / c_i(x_k) * sum_j k_sigma
    std::vector<double> target, lower, upper;
    std::vector<double> inv_target, inv_upper, inv_lower;  // 1 / max(value, floor)
    std::vector<double> sum;                    // the running sum of Eq. 2
    double base_max = 0.0;  // max_k (mean_k - target_k) * inv_target_k of the current state
    double reach = 0.0;     // Euclidean distance beyond which a pair of these classes is off the axis
};

struct Elem {
    Vec3 p;
    double r = 0.0;
    int cls = 0;
    bool placed = false;
    int cell = -1;           // grid cell holding its entry (placed elements)
};

// A grid entry: the element and its position when the entry was made (the refinement
// reads entries made at the start of a sweep and filters by that position first, so that
// concurrent tiles never look at each other's moving elements).
struct CellEntry {
    int index = 0;
    double x = 0.0, y = 0.0;
};

// 1 / c(x_k) at a position, computed bin by bin on demand (0 = not computed yet).
struct LazyInverse {
    Vec3 q;             // the position
    double dist = 0.0;  // distance to the boundary there: bins within it need no correction
    double* values = nullptr;
};

class State {
public:
    // elements: the output's radii per class (all unplaced).
    State(const PcfModel& model, const Domain& domain, const std::vector<std::vector<double>>& radii);

    const PcfModel& model;
    const Domain& domain;
    Axis axis;
    int bins = 0;
    double r_max = 0.0, area = 0.0, x_limit = 0.0;
    double floor = 0.0;                         // of the relative errors (kFloorShare / step)
    int kernel_max = 0;                         // most bins one pair touches
    std::vector<int> count;                     // output elements per class
    std::vector<Term> terms;                    // in model.pcfs order
    std::vector<std::vector<int>> class_terms;  // per class: the terms whose child it is
    std::vector<Elem> elems;
    std::vector<std::vector<int>> members;      // per class: its element indices (largest radius first)
    std::vector<double> inverse;                // elems x bins: 1 / c_i(x_k) of placed elements

    // The kernel values k_sigma(x_k - x) of the bins a pair at x touches: value(m) is bin
    // lo + m. They come from a table over the position of x between two bins (1024 steps,
    // linear interpolation: within 1e-7 of the exact value, whose peak is 2.26 for sigma
    // 0.25), which avoids two exponentials per pair. The bins are Axis::bin_range's
    // (computed with reciprocals and integer rounding, so a pair exactly on a cut-off may
    // differ by one bin of weight e^-16).
    struct Span {
        int lo = 0, n = 0;
        const double* a = nullptr;  // table row
        const double* d = nullptr;  // next row - this row
        double w = 0.0;
        double value(int m) const { return a[m] + w * d[m]; }
    };
    Span kernel_span(double x) const {
        Span sp;
        const double u = x * inv_step_;
        const double ua = u - reach_steps_, uc = u + reach_steps_;
        int lo = static_cast<int>(ua);
        lo += lo < ua;
        lo = std::max(0, lo);
        int hi = static_cast<int>(uc);
        hi -= hi > uc;
        hi = std::min(bins - 1, hi);
        if (lo > hi) return sp;
        int fl = static_cast<int>(u);
        fl -= fl > u;
        const double pos = (u - fl) * kKernelSteps;
        const int j = std::min(static_cast<int>(pos), kKernelSteps - 1);
        sp.lo = lo;
        sp.n = hi - lo + 1;
        sp.w = pos - j;
        const size_t at = static_cast<size_t>(j) * kernel_width_ + (lo - fl + kernel_half_);
        sp.a = &kernel_table_[at];
        sp.d = &kernel_delta_[at];
        return sp;
    }
    int kernel(double x, int& lo, double* values) const {
        const Span sp = kernel_span(x);
        lo = sp.lo;
        for (int m = 0; m < sp.n; ++m) values[m] = sp.value(m);
        return sp.n;
    }

    PairDistance pair(const Vec3& a, double ra, const Vec3& b, double rb) const {
        const double dx = a.x - b.x, dy = a.y - b.y;
        return normalised_pair_distance_slope(std::sqrt(dx * dx + dy * dy), ra, rb, r_max, inv_r_max_);
    }

    // Boundary correction.
    void fractions_at(const Vec3& p, double* inverse_out) const;  // all bins
    LazyInverse lazy_at(const Vec3& p, double* storage) const;    // storage: bins doubles
    double lazy_value(LazyInverse& lazy, int k) const {
        double& v = lazy.values[k];
        if (v == 0.0) {
            const double rho = axis.x(k) * r_max;
            v = rho <= lazy.dist ? 1.0 : 1.0 / inside_fraction(lazy.q, rho);
        }
        return v;
    }
    // circle_inside_fraction (pcf_math.hpp): the share of 64 points on the circle that
    // lie in the domain. For a box the points outside each side form a run of indices
    // around the side's normal (|k - centre| < acos(distance / rho) * 64 / 2 pi), so the
    // count comes from at most four arcs instead of 64 tests (it can differ from the tests
    // only for a point exactly on a side); other domains test the 64 points.
    double inside_fraction(const Vec3& p, double rho) const {
        if (!(rho > 0.0)) return 1.0;
        int inside = 0;
        if (domain.kind() == Domain::Kind::box) {
            const Box& b = domain.bounds();
            const double distance[4] = {hi_x_ - p.x, hi_y_ - p.y, p.x - b.lo.x, p.y - b.lo.y};
            std::uint64_t outside = 0;
            for (int side = 0; side < 4; ++side) {  // normals at angles 0, pi/2, pi, 3 pi/2
                const double t = distance[side] / rho;
                if (t >= 1.0) continue;
                if (t <= -1.0) return 1.0 / kCircleSamples;
                const double half = std::acos(t) * (kCircleSamples / (2.0 * kPi));
                const double centre = side * (kCircleSamples / 4.0) - 0.5;
                const int first = static_cast<int>(std::floor(centre - half)) + 1;
                const int last = static_cast<int>(std::ceil(centre + half)) - 1;
                const int n = last - first + 1;
                if (n <= 0) continue;
                if (n >= kCircleSamples) return 1.0 / kCircleSamples;
                const int start = ((first % kCircleSamples) + kCircleSamples) % kCircleSamples;
                outside |= std::rotl((std::uint64_t{1} << n) - 1, start);
            }
            inside = kCircleSamples - std::popcount(outside);
        } else if (!polygon_edges_.empty()) {
            inside = polygon_inside_count(p, rho);
        } else {
            for (int k = 0; k < kCircleSamples; ++k)
                inside += domain.inside({p.x + rho * circle_cos_[k], p.y + rho * circle_sin_[k], 0.0});
        }
        return std::max(inside, 1) / static_cast<double>(kCircleSamples);
    }
    // For a polygon: the circle crosses the rings at a few angles; the arcs between them
    // are wholly inside or outside (one test at each arc's middle), and the count is that
    // of the 64 points on the inside arcs (the same as testing them, but for a point
    // exactly on an edge).
    int polygon_inside_count(const Vec3& p, double rho) const;

    // Calls f(index) for the entries of class c whose recorded position lies within
    // `radius` of p, until f returns false; returns false if stopped.
    template <class F>
    bool for_each_near(int c, const Vec3& p, double radius, F&& f) const {
        const int x0 = std::max(0, static_cast<int>(std::floor((p.x - radius - lo_.x) * inv_cell_)));
        const int x1 = std::min(nx_ - 1, static_cast<int>(std::floor((p.x + radius - lo_.x) * inv_cell_)));
        const int y0 = std::max(0, static_cast<int>(std::floor((p.y - radius - lo_.y) * inv_cell_)));
        const int y1 = std::min(ny_ - 1, static_cast<int>(std::floor((p.y + radius - lo_.y) * inv_cell_)));
        const double r2 = radius * radius;
        const auto& cells = cells_[c];
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x)
                for (const CellEntry& e : cells[y * nx_ + x]) {
                    const double dx = e.x - p.x, dy = e.y - p.y;
                    if (dx * dx + dy * dy <= r2 && !f(e.index)) return false;
                }
        return true;
    }

    // Places element i at p (inside the domain): boundary correction, sums, grid.
    void insert(int i, const Vec3& p);
    // Takes a placed element out again.
    void remove(int i);
    // A class's positions, corrections and PCF sums, to undo changes to it.
    struct Snapshot {
        std::vector<Vec3> positions;
        std::vector<double> inverse;
        std::vector<std::vector<double>> sums;
    };
    Snapshot snapshot(int c) const;
    void restore(int c, const Snapshot& snap);
    // Rebuilds class c's grid entries from the current positions (element order).
    void rebuild_grid(int c);
    // Refreshes a term's base_max after its sum changed.
    void refresh(int t);
    // sum_k (mean_k - target_k)^2 of a term (the refinement's error).
    double term_error(int t) const;
    // Placed elements of class c.
    int placed(int c) const { return placed_[c]; }
    // The largest reach of class c's terms.
    double class_reach(int c) const;

private:
    void add_pairs(int i, double sign);
    int cell_of(const Vec3& p) const;

    static constexpr int kCircleSamples = 64;  // as circle_inside_fraction
    double hi_x_ = 0.0, hi_y_ = 0.0;
    std::vector<std::pair<Vec3, Vec3>> polygon_edges_;  // every ring's edges, world coordinates
    double circle_cos_[kCircleSamples] = {}, circle_sin_[kCircleSamples] = {};
    static constexpr int kKernelSteps = 1024;
    int kernel_half_ = 0, kernel_width_ = 0;  // table columns: bins -half .. +half around floor(x / step)
    std::vector<double> kernel_table_;        // kKernelSteps x kernel_width_
    std::vector<double> kernel_delta_;        // the next row minus this one
    double inv_step_ = 0.0, reach_steps_ = 0.0, inv_r_max_ = 0.0;
    Vec3 lo_;
    double inv_cell_ = 0.0;
    int nx_ = 1, ny_ = 1;
    std::vector<std::vector<std::vector<CellEntry>>> cells_;  // class -> cell -> entries
    std::vector<int> placed_;
};

}  // namespace tessera::pcf
