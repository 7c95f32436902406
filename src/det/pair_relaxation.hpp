// The pair correlation relaxation: a last solver step (section 5's "extra solver steps")
// for exemplars of single-sample elements that are not layers. Patch seams put elements at distances the
// exemplar's statistics do not have, and the least-squares assignment (Eq. 4) averages the
// predictions of several neighbourhoods, which draws distances towards the typical ones;
// on field data both left the output's pair correlation 4 to 5 times further from the
// exemplar's than a verbatim copy of the exemplar is. This step moves elements, one at a
// time, by small keyed random steps that bring the output's pair correlation per class
// pair (the standard estimator: Gaussian kernel, translation edge correction, up to five
// spacings) closer to the exemplar's, and keeps a step only when it does (greedy descent on
// sum_k (g_out(r_k) - g_ex(r_k))^2 over the class pairs, r_k >= the kernel width). Moves stay
// inside the domain, never closer to a neighbour than the exemplar's closest pair of their
// types, and below a quarter spacing per sweep; locked and held (floor)
// elements stay. The crowding repair and the hole filling run after it.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "core/interrupt.hpp"
#include "det/model.hpp"

namespace tessera::det {

class PairRelaxation {
public:
    // The exemplar's pair correlation curves on the relaxation's grid.
    PairRelaxation(const Exemplar& exemplar, const Params& params);

    // Whether the exemplar is one the relaxation applies to (single-sample elements).
    bool applies() const { return applies_; }
    // How far one sweep moves an element at most (its largest trial step).
    double max_step() const;

    struct Report {
        int moves = 0;          // steps kept
        double before = 0.0;    // sum of squared differences before and after
        double after = 0.0;
    };
    // Relaxes `out` for `sweeps` sweeps; held[e] != 0 (may be empty) keeps element e.
    // Deterministic for any thread count. `after_sweep(s)`, when given, is called after
    // sweep s (0-based), for progress; `interrupt`, when given, is checked every few
    // hundred elements (a sweep over a million elements takes seconds).
    Report relax(Arrangement& out, const Domain& domain, const std::vector<char>& held, int sweeps,
                 std::uint64_t seed, int threads, const std::function<void(int)>& after_sweep = {},
                 const core::Interrupt* interrupt = nullptr) const;

private:
    bool applies_ = false;
    int types_ = 0, bins_ = 0;
    double r_max_ = 0.0, bandwidth_ = 0.0, step_ = 0.0, spacing_ = 0.0;
    std::vector<double> target_;     // per unordered class pair (a <= b) and bin: the exemplar's g
    std::vector<double> hard_core_;  // per unordered class pair: the exemplar's closest pair
    int pair_index(int a, int b) const;
};

}  // namespace tessera::det
