// Greedy and exact pairing of neighbourhood samples (Eq. 1, section 3.2).
#include "det/matching.hpp"

#include <algorithm>
#include <limits>

namespace tessera::det {

namespace {

// Cheapest free input partner of output entry o among in[lo, hi) (its match
// key's range), or -1 if there is none. The first scan of a matching has no taken
// entries (check_taken = false); samples of multi-sample elements (key != 0) have
// no attribute term, so their loop is a plain squared distance.
template <bool check_taken>
inline int best_free_partner(const NeighborEntry& o, const NeighborEntry* in, int lo, int hi, const Params& params,
                             const std::vector<char>& taken, double& cost) {
    int best = -1;
    cost = INFINITY;
    if (o.key != 0) {
        const double ox = o.offset.x, oy = o.offset.y, oz = o.offset.z;
        for (int i = lo; i < hi; ++i) {
            if (check_taken && taken[i]) continue;
            const double dx = ox - in[i].offset.x, dy = oy - in[i].offset.y, dz = oz - in[i].offset.z;
            const double c = dx * dx + dy * dy + dz * dz;
            if (c < cost) cost = c, best = i;
        }
        return best;
    }
    for (int i = lo; i < hi; ++i) {
        if (check_taken && taken[i]) continue;
        const double c = pair_cost(o, in[i], params);
        if (c < cost) cost = c, best = i;
    }
    return best;
}

}  // namespace

// The paper's greedy heuristic: take the globally cheapest remaining pair, remove
// both samples, repeat. Implemented lazily: each output entry caches its cheapest
// free partner in a min-heap; when the top's partner is still free it is the true
// cheapest remaining pair (costs only grow as inputs are taken), otherwise that
// entry alone is rescanned and pushed back. Conflicts are rare, so the cost is
// about one scan of each output entry's key range plus m log m heap operations.
double match_greedy(const NeighborEntry* out, int m, const NeighborEntry* in, int n, const Params& params,
                    MatchScratch& s, int* partner, double bound) {
    s.best_input.resize(m);
    s.taken.assign(n, 0);
    s.range_lo.resize(m);
    s.range_hi.resize(m);
    s.heap.clear();
    // Both lists are sorted by match key: one merge walk finds every output
    // entry's range of possible partners.
    // Each entry's final cost is at least its first cheapest-free cost (costs only
    // grow as inputs are taken), so the running sum of those is a lower bound.
    double lower_bound = 0.0;
    int lo = 0;
    for (int o = 0; o < m; ++o) {
        const int key = out[o].match_key;
        if (o > 0 && key == out[o - 1].match_key) {
            s.range_lo[o] = s.range_lo[o - 1];
            s.range_hi[o] = s.range_hi[o - 1];
        } else {
            while (lo < n && in[lo].match_key < key) ++lo;
            int hi = lo;
            while (hi < n && in[hi].match_key == key) ++hi;
            s.range_lo[o] = lo;
            s.range_hi[o] = hi;
            lo = hi;
        }
        double cost;
        s.best_input[o] = best_free_partner<false>(out[o], in, s.range_lo[o], s.range_hi[o], params, s.taken, cost);
        s.heap.emplace_back(cost, o);
        lower_bound += std::min(cost, params.cap2);
        if (lower_bound >= bound) return lower_bound;  // cannot beat the caller's best
    }
    const auto later = [](const std::pair<double, int>& a, const std::pair<double, int>& b) { return a > b; };
    std::make_heap(s.heap.begin(), s.heap.end(), later);
    double total = 0.0;
    while (!s.heap.empty()) {
        std::pop_heap(s.heap.begin(), s.heap.end(), later);
        const auto [cost, o] = s.heap.back();
        s.heap.pop_back();
        const int i = s.best_input[o];
        if (i >= 0 && s.taken[i]) {  // stale: its partner went to a cheaper pair
            double fresh;
            s.best_input[o] = best_free_partner<true>(out[o], in, s.range_lo[o], s.range_hi[o], params, s.taken, fresh);
            s.heap.emplace_back(fresh, o);
            std::push_heap(s.heap.begin(), s.heap.end(), later);
            continue;
        }
        total += std::min(cost, params.cap2);  // truncated: one bad pair costs at most cap2
        if (i >= 0) s.taken[i] = 1;
        if (partner) partner[o] = i;
        if (total >= bound) return total;  // cannot beat the caller's best
    }
    return total;
}

// Exact minimum-cost assignment (Kuhn-Munkres with potentials, O(m^2 (n + m))).
// Rows: output entries; columns: input entries plus m "unpaired" columns of cost
// cap2, so every row can be assigned and pairs costlier than cap2 are never chosen.
double match_hungarian(const NeighborEntry* out, int m, const NeighborEntry* in, int n, const Params& params,
                       MatchScratch& s, int* partner) {
    if (m == 0) return 0.0;
    const int cols = n + m;
    const double inf = std::numeric_limits<double>::infinity();
    s.matrix.resize(static_cast<size_t>(m) * cols);
    for (int o = 0; o < m; ++o)
        for (int c = 0; c < cols; ++c) {
            double v = params.cap2;
            if (c < n) {
                v = in[c].match_key == out[o].match_key ? std::min(pair_cost(out[o], in[c], params), params.cap2)
                                                         : inf;
            }
            s.matrix[static_cast<size_t>(o) * cols + c] = v;
        }
    s.column.resize(m);
    const double total = core::hungarian(s.matrix.data(), m, cols, s.hungarian, s.column.data());
    if (partner)
        for (int o = 0; o < m; ++o) partner[o] = s.column[o] < n ? s.column[o] : -1;
    return total;
}

double match_neighborhoods(const NeighborEntry* out, int m, const NeighborEntry* in, int n, const Params& params,
                           MatchScratch& scratch, int* partner, double bound) {
    if (params.matching == Matching::hungarian) return match_hungarian(out, m, in, n, params, scratch, partner);
    return match_greedy(out, m, in, n, params, scratch, partner, bound);
}

}  // namespace tessera::det
