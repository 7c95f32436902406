// Greedy and exact pairing of neighbourhood samples (Eq. 1, section 3.2).
#include "det/matching.hpp"

#include <limits>

namespace tessera::det {

namespace {

// Best free input partner of output entry o, or -1 if none is cheaper than cap2.
inline int best_free_partner(const NeighborEntry& o, const NeighborEntry* in, int n, const Params& params,
                             const std::vector<char>& taken, double& cost) {
    int best = -1;
    cost = params.cap2;
    for (int i = 0; i < n; ++i) {
        if (taken[i] || in[i].match_key != o.match_key) continue;
        const double c = pair_cost(o, in[i], params);
        if (c < cost) cost = c, best = i;
    }
    return best;
}

}  // namespace

// The paper's greedy heuristic: take the globally cheapest remaining pair, remove
// both samples, repeat. Implemented lazily: each output entry caches its cheapest
// free partner; when the globally cheapest cached pair is still free it is the
// true cheapest remaining pair (costs only grow as inputs are taken), otherwise
// that entry alone is rescanned. Conflicts are rare, so this is ~m*n, not m*n*log.
double match_greedy(const NeighborEntry* out, int m, const NeighborEntry* in, int n, const Params& params,
                    MatchScratch& s, int* partner, double bound) {
    s.best_cost.resize(m);
    s.best_input.resize(m);
    s.taken.assign(n, 0);
    for (int o = 0; o < m; ++o) s.best_input[o] = best_free_partner(out[o], in, n, params, s.taken, s.best_cost[o]);
    double total = 0.0;
    int remaining = m;
    // Entries still to settle are [0, remaining) of this permutation.
    int order_buf[512];
    std::vector<int> order_heap;
    int* order = order_buf;
    if (m > 512) {
        order_heap.resize(m);
        order = order_heap.data();
    }
    for (int o = 0; o < m; ++o) order[o] = o;
    while (remaining > 0) {
        int pick = 0;
        for (int k = 1; k < remaining; ++k) {
            const int a = order[k], b = order[pick];
            if (s.best_cost[a] < s.best_cost[b] || (s.best_cost[a] == s.best_cost[b] && a < b)) pick = k;
        }
        const int o = order[pick];
        const int i = s.best_input[o];
        if (i >= 0 && s.taken[i]) {  // stale: its partner went to a cheaper pair
            s.best_input[o] = best_free_partner(out[o], in, n, params, s.taken, s.best_cost[o]);
            continue;
        }
        total += i >= 0 ? s.best_cost[o] : params.cap2;
        if (i >= 0) s.taken[i] = 1;
        if (partner) partner[o] = i;
        order[pick] = order[--remaining];
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
                v = in[c].match_key == out[o].match_key ? pair_cost(out[o], in[c], params) : inf;
                if (v > params.cap2) v = inf;  // never pair beyond the cap
            }
            s.matrix[static_cast<size_t>(o) * cols + c] = v;
        }
    // 1-based arrays as in the classic formulation; p[c] = row assigned to column c.
    s.u.assign(m + 1, 0.0);
    s.v.assign(cols + 1, 0.0);
    s.p.assign(cols + 1, 0);
    s.way.assign(cols + 1, 0);
    for (int row = 1; row <= m; ++row) {
        s.p[0] = row;
        int c0 = 0;
        s.way_cost.assign(cols + 1, inf);
        s.used.assign(cols + 1, 0);
        do {
            s.used[c0] = 1;
            const int r0 = s.p[c0];
            double delta = inf;
            int c1 = 0;
            for (int c = 1; c <= cols; ++c) {
                if (s.used[c]) continue;
                const double cur = s.matrix[static_cast<size_t>(r0 - 1) * cols + (c - 1)] - s.u[r0] - s.v[c];
                if (cur < s.way_cost[c]) s.way_cost[c] = cur, s.way[c] = c0;
                if (s.way_cost[c] < delta) delta = s.way_cost[c], c1 = c;
            }
            for (int c = 0; c <= cols; ++c) {
                if (s.used[c]) s.u[s.p[c]] += delta, s.v[c] -= delta;
                else s.way_cost[c] -= delta;
            }
            c0 = c1;
        } while (s.p[c0] != 0);
        do {
            const int c1 = s.way[c0];
            s.p[c0] = s.p[c1];
            c0 = c1;
        } while (c0);
    }
    double total = 0.0;
    if (partner)
        for (int o = 0; o < m; ++o) partner[o] = -1;
    for (int c = 1; c <= cols; ++c) {
        const int row = s.p[c];
        if (row == 0) continue;
        total += s.matrix[static_cast<size_t>(row - 1) * cols + (c - 1)];
        if (partner && c <= n) partner[row - 1] = c - 1;
    }
    return total;
}

double match_neighborhoods(const NeighborEntry* out, int m, const NeighborEntry* in, int n, const Params& params,
                           MatchScratch& scratch, int* partner, double bound) {
    if (params.matching == Matching::hungarian) return match_hungarian(out, m, in, n, params, scratch, partner);
    return match_greedy(out, m, in, n, params, scratch, partner, bound);
}

}  // namespace tessera::det
