// Pairing of two neighbourhoods for the metric of Eq. 1: each output neighbour
// s'_o gets at most one input partner s'_i of the same matching key; a pair
// costs |p^(s'_o) - p^(s'_i)|^2 + alpha |q(s'_o) - q(s'_i)|^2 truncated at cap2,
// and an output neighbour left without partner (none of its key remains) costs
// cap2. As in the paper, pairs are made however far apart (n(s_i) has "infinite"
// extent, here r + cap), so an extra output sample is still pushed toward a free
// input position; the truncation keeps one bad pair from dominating the metric.
// Greedy is the paper's heuristic (repeatedly take the cheapest remaining pair);
// Hungarian is the exact minimum-cost assignment, for comparison and small cases.
#pragma once

#include <utility>
#include <vector>

#include "core/hungarian.hpp"
#include "det/model.hpp"

namespace tessera::det {

// Reused buffers: matching runs in the innermost loop and must not allocate.
struct MatchScratch {
    std::vector<std::pair<double, int>> heap;  // greedy: (cost of cheapest free partner, output entry)
    std::vector<int> best_input;    // greedy: its input partner
    std::vector<char> taken;        // greedy: input entries already paired
    std::vector<int> range_lo, range_hi;  // greedy: input entries sharing each output entry's match key
    std::vector<double> matrix;  // Hungarian
    std::vector<int> column;
    core::HungarianScratch hungarian;
};

// Cost of pairing output neighbour o with input neighbour i (without the cap).
inline double pair_cost(const NeighborEntry& o, const NeighborEntry& i, const Params& params) {
    const Vec3 d = o.offset - i.offset;
    double c = squared_norm(d);
    if (o.key == 0) {  // single-sample elements: attribute term of Eq. 1
        double q = o.type != i.type ? 1.0 : 0.0;
        if (o.radius > 0.0 || i.radius > 0.0) {
            const double dr = (o.radius - i.radius) / params.spacing;
            q += dr * dr;
        }
        c += params.alpha * q;
    }
    return c;
}

// `out` and `in` must both be sorted by match_key (InputIndex and the search keep them so).
// Total pairing cost of `out` (m entries) against `in` (n entries) and, if
// `partner` is not null, the index into `in` paired with each output entry (-1 = none).
// `bound`: the caller's best cost so far; the greedy search stops early and returns
// a value >= bound once the partial sum reaches it.
double match_neighborhoods(const NeighborEntry* out, int m, const NeighborEntry* in, int n, const Params& params,
                           MatchScratch& scratch, int* partner, double bound);

double match_greedy(const NeighborEntry* out, int m, const NeighborEntry* in, int n, const Params& params,
                    MatchScratch& scratch, int* partner, double bound);
double match_hungarian(const NeighborEntry* out, int m, const NeighborEntry* in, int n, const Params& params,
                       MatchScratch& scratch, int* partner);

}  // namespace tessera::det
