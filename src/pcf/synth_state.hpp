// The incremental state of PCF synthesis (pcf_synthesis.hpp, sections 3 to 5): the
// output elements placed so far, a uniform grid over the output domain for neighbour
// queries, each element's boundary correction, and for every model PCF the running sum
// of Eq. 2, so that adding, moving or removing one element costs O(neighbours x kernel
// bins) instead of a new analysis. Private to the library.
//
// Conventions (the header's, as the analysis in pcf_estimate.cpp computes them): a model
// PCF (parent p, child c) has reference elements in the child class and neighbours in the
// parent class; within a class both ends of a pair are references. Its mean is
// norm_k * sum_k with
//   sum_k  = sum over (reference i, neighbour j) of k_sigma(x_k - x_ij) / c_i(d_ij),
//   norm_k = |W| step / (A_k n_child n_parent'), n_parent' = n_parent - 1 within a class,
// and the individual PCF of a reference i is ind_norm_k * sum_j k_sigma(x_k - x_ij) / c_i(d_ij)
// with ind_norm_k = |W| step / (A_k n_parent'). n are the final output counts throughout,
// so during initialisation the PCFs grow towards their targets from below (as in [OG12]).
//
// Boundary correction: c_i(d) = circle_inside_fraction(domain, P_i, d), the share of 64
// points on the circle of radius d inside the domain, for each pair at its centre
// distance. Each element keeps a CircleProfile: the radii at which its 64 points leave
// (or re-enter) the domain, so c_i(d) is a binary search instead of 64 tests.
#pragma once

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
// would divide by 0, so tessera divides by max(target, kFloor) instead: an excess of 1% of
// the value of an uncorrelated distribution (1) where the exemplar has nothing counts as
// a 100% error.
inline constexpr double kFloor = 0.01;

// The distances of the refinement's trial moves, in units of r_max (section 3.1).
inline constexpr double kTrialSteps[] = {1e-1, 1e-2, 1e-3, 1e-4, 1e-5};
inline constexpr double kMaxMove = 1e-1;

// One model PCF during synthesis.
struct Term {
    int parent = 0, child = 0;
    bool within = false;
    std::vector<double> norm;      // mean PCF = norm_k * sum_k (0 when the class pair has no pairs)
    std::vector<double> ind_norm;  // individual PCF = ind_norm_k * (its share of sum_k)
    std::vector<double> target, lower, upper;
    std::vector<double> inv_target, inv_upper, inv_lower;  // 1 / max(value, kFloor)
    int lower_lo = 0, lower_hi = -1;                       // the bins where lower > 0
    std::vector<double> sum;                               // the running sum of Eq. 2
    double base_max = 0.0;  // max_k (mean_k - target_k) * inv_target_k of the current state
    double reach = 0.0;     // Euclidean distance beyond which a pair of these classes is off the axis
};

// circle_inside_fraction around one position as a function of the radius. Along each of
// the 64 directions the point leaves the domain at some radius (boxes: once; polygons:
// possibly again and again, re-entering across concave parts and holes); `at` holds these
// radii sorted and `inside[m]` the number of points inside for radii beyond at[m]. The
// count equals the 64 tests except for a point exactly on the boundary. Domains other than
// boxes and polygons test the points at each call (`sampled`).
struct CircleProfile {
    Vec3 p;
    double free = 0.0;  // distance to the boundary: circles up to it are wholly inside
    bool built = false, sampled = false;
    std::vector<double> at;
    std::vector<int> inside;
};

struct Elem {
    Vec3 p;
    double r = 0.0;
    int cls = 0;
    bool placed = false;
    int cell = -1;  // grid cell holding its entry (placed elements)
    int hint = 0;   // the refinement's last successful trial distance (index into kTrialSteps)
};

// A grid entry: the element and its position when the entry was made (the refinement
// reads entries made at the start of a sweep and filters by that position first, so that
// concurrent tiles never look at each other's moving elements).
struct CellEntry {
    int index = 0;
    double x = 0.0, y = 0.0;
};

// A separation (PcfSeparation) as class c sees it: elements of `other` stay at least x
// apart on the normalised axis; pairs further apart than `reach` (Euclidean) always are.
struct Separation {
    int other = 0;
    double x = 0.0;
    double reach = 0.0;
};

// An element that stays where it is (synthesis next to a world's finished tiles): it counts
// toward its class's count and every PCF sum but is in no `members` list, so nothing moves it.
struct FixedElem {
    int cls = 0;
    Vec3 p;
    double r = 0.0;
};

class State {
public:
    // elements: the output's radii per class (all unplaced); fixed: elements inside the
    // domain that stay put, inserted class by class by insert_fixed.
    State(const PcfModel& model, const Domain& domain, const std::vector<std::vector<double>>& radii,
          const std::vector<FixedElem>& fixed = {});

    const PcfModel& model;
    const Domain& domain;
    // Where new elements are placed and may move: the domain, or the part of it that the
    // fixed elements leave to fill (a world's tile inside the margins of its neighbours),
    // so that none drifts into the fixed elements' part, where it would be lost.
    const Domain* fill = &domain;
    Axis axis;
    int bins = 0;
    double r_max = 0.0, area = 0.0, x_limit = 0.0;
    int kernel_max = 0;                         // most bins one pair touches
    std::vector<int> count;                     // output elements per class
    std::vector<Term> terms;                    // in model.pcfs order
    std::vector<std::vector<int>> class_terms;  // per class: the terms whose child it is
    std::vector<Elem> elems;
    std::vector<CircleProfile> profiles;        // per element (placed ones)
    std::vector<std::vector<int>> members;      // per class: its element indices (largest radius first)
    std::vector<std::vector<int>> fixed;        // per class: the indices of its fixed elements
    std::vector<std::vector<Separation>> separations;  // per class: the classes it must stay apart from
    // A separation violation of dx on the normalised axis counts as dx / (kFloor sigma) in
    // the candidate error: a tenth of a kernel width inside weighs as much as a pair where
    // the exemplar has none (an upper envelope at the floor).
    double separation_scale = 0.0;

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

    double distance(const Vec3& a, const Vec3& b) const {
        const double dx = a.x - b.x, dy = a.y - b.y;
        return std::sqrt(dx * dx + dy * dy);
    }
    PairDistance pair(double d, double ra, double rb) const {
        return normalised_pair_distance_slope(d, ra, rb, r_max, inv_r_max_);
    }

    // Boundary correction. begin_profile records the position and its free distance;
    // build_profile adds the radii (needed only for a pair beyond the free distance).
    void begin_profile(const Vec3& p, CircleProfile& out) const;
    void build_profile(CircleProfile& out) const;
    // 1 / c(d) for a circle of radius d around the profile's position.
    double weight(CircleProfile& profile, double d) const {
        if (d <= profile.free) return 1.0;
        if (!profile.built) build_profile(profile);
        return inverse_fraction(profile, d);
    }
    double weight(const CircleProfile& profile, double d) const {  // a built profile
        return d <= profile.free ? 1.0 : inverse_fraction(profile, d);
    }

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

    // Places element i at p (inside the domain) with its profile there (begun or built
    // for p; it is swapped in): sums, grid.
    void insert(int i, CircleProfile& profile);
    // Takes a placed element out again.
    void remove(int i);
    // Places class c's fixed elements. Called just before the class is synthesized, when its
    // parents are complete: a pair counts in the sum of its reference's class when the
    // reference is inserted, so a fixed child inserted earlier would miss later parents.
    void insert_fixed(int c);
    // Some elements' positions and profiles and their class's PCF sums, to undo changes
    // to those elements (a copy of the elements moved, not of the whole class: a local
    // refinement must not cost the class's size per sweep).
    struct Snapshot {
        std::vector<int> elements;
        std::vector<Vec3> positions;
        std::vector<CircleProfile> profiles;
        std::vector<std::vector<double>> sums;
    };
    Snapshot snapshot(int c, const std::vector<int>& elements) const;
    void restore(int c, const Snapshot& snap);
    // The placed elements of class c within `radius` of a placed element of `around`
    // (those included), in members order.
    std::vector<int> near_members(int c, const std::vector<int>& around, double radius) const;
    // Rebuilds class c's grid entries from the current positions (element order).
    void rebuild_grid(int c);
    // Refreshes a term's base_max after its sum changed.
    void refresh(int t);
    // sum_k (mean_k - target_k)^2 of a term (the refinement's error).
    double term_error(int t) const;
    // How far (normalised axis) an element of class c with radius r at p comes inside the
    // separations of its class from placed elements of other classes: the largest
    // x_min - x over those pairs, 0 when it keeps them all.
    double separation_violation(int c, const Vec3& p, double r) const {
        double v = 0.0;
        for (const Separation& sep : separations[c])
            for_each_near(sep.other, p, sep.reach + r, [&](int j) {
                const Elem& o = elems[j];
                v = std::max(v, sep.x - pair(distance(p, o.p), r, o.r).x);
                return true;
            });
        return v;
    }
    // Placed elements of class c.
    int placed(int c) const { return placed_[c]; }

private:
    static constexpr int kKernelSteps = 1024;
    static constexpr int kCircleSamples = 64;  // as circle_inside_fraction

    double inverse_fraction(const CircleProfile& profile, double d) const {
        if (profile.sampled) return 1.0 / circle_inside_fraction(domain, profile.p, d);
        // Points still inside at radius d: those whose leaving radius is not below d
        // (std::lower_bound, without branches).
        const double* base = profile.at.data();
        size_t n = profile.at.size();
        if (n == 0) return 1.0;
        while (n > 1) {
            const size_t half = n / 2;
            base = base[half - 1] < d ? base + half : base;
            n -= half;
        }
        const size_t m = static_cast<size_t>(base - profile.at.data()) + (*base < d ? 1 : 0);
        const int inside = m == 0 ? kCircleSamples : profile.inside[m - 1];
        return inverse_count_[std::max(inside, 1)];
    }
    void add_pairs(int i, double sign);
    int cell_of(const Vec3& p) const;

    int kernel_half_ = 0, kernel_width_ = 0;  // table columns: bins -half .. +half around floor(x / step)
    std::vector<double> kernel_table_;        // kKernelSteps x kernel_width_
    std::vector<double> kernel_delta_;        // the next row minus this one
    double inv_step_ = 0.0, reach_steps_ = 0.0, inv_r_max_ = 0.0;
    double circle_cos_[kCircleSamples] = {}, circle_sin_[kCircleSamples] = {};
    double inverse_count_[kCircleSamples + 1] = {};  // 64 / count
    std::vector<std::pair<Vec3, Vec3>> polygon_edges_;  // every ring's edges, world coordinates
    Vec3 lo_;
    double inv_cell_ = 0.0;
    int nx_ = 1, ny_ = 1;
    std::vector<std::vector<std::vector<CellEntry>>> cells_;  // class -> cell -> entries
    std::vector<int> placed_;
};

}  // namespace tessera::pcf
