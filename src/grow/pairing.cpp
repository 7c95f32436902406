// Greedy pairing for growth (grow/pairing.hpp).
#include "grow/pairing.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "grow/input_elements.hpp"

namespace tessera::grow {

namespace {

using Column = Eigen::Map<const Eigen::ArrayXd>;

// Row o of the cost matrix: DET's pair_cost (det/matching.hpp) for every input entry, the
// same operations in the same order, so the sums are identical to the entry-wise ones.
void cost_row(const det::NeighborEntry& o, const InputElements& in, int first, int n,
              const det::Params& params, double* row) {
    const InputElements::Columns& col = in.columns;
    Eigen::Map<Eigen::ArrayXd> r(row, n);
    const Column x(col.x.data() + first, n), y(col.y.data() + first, n), type(col.type.data() + first, n),
        radius(col.radius.data() + first, n);
    r = (x - o.offset.x).square() + (y - o.offset.y).square();
    if (params.dimension == 3) r += (Column(col.z.data() + first, n) - o.offset.z).square();
    // Attribute term: 1 for another type (types are whole numbers), plus the squared radius
    // difference in spacings; either is exactly 0 when the input has only the entry's type
    // (radius), and is then skipped.
    const bool same_type = col.one_type && o.type == col.the_type;
    const bool same_radius = col.one_radius && o.radius == col.the_radius;
    if (same_type && same_radius) return;
    if (same_radius)
        r += params.alpha * (type - o.type).abs().min(1.0);
    else
        r +=
            params.alpha * ((type - o.type).abs().min(1.0) + ((radius - o.radius) / params.spacing).square());
}

// Cheapest input entry of a fresh row (the first of equal costs), -1 if the row is empty:
// the minimum in vector registers, then the first entry that holds it (no chain of
// dependent comparisons).
int cheapest(const double* row, int n, double& cost) {
    if (n == 0) {
        cost = INFINITY;
        return -1;
    }
    cost = Eigen::Map<const Eigen::ArrayXd>(row, n).minCoeff();
    int i = 0;
    while (row[i] != cost) ++i;
    return i;
}

// Cheapest input entry of a row not yet taken (the first of equal costs), -1 if none.
int cheapest_free(const double* row, int n, const std::vector<char>& taken, double& cost) {
    int best = -1;
    cost = INFINITY;
    for (int i = 0; i < n; ++i) {
        if (taken[i]) continue;
        if (row[i] < cost) cost = row[i], best = i;
    }
    return best;
}

}  // namespace

double pair_greedy(const det::NeighborEntry* out, int m, const InputElements& in, int c, int n,
                   const det::Params& params, PairScratch& s, int* partner, double bound) {
    const int first = in.nb_start[c];
    s.rows.resize(static_cast<size_t>(m) * n);
    s.best_input.resize(m);
    s.taken.assign(n, 0);
    s.heap.clear();
    // Each entry's final cost is at least its first cheapest cost (costs only grow as input
    // entries are taken), so the running sum of those bounds the total from below.
    double lower_bound = 0.0;
    for (int o = 0; o < m; ++o) {
        double* row = s.rows.data() + static_cast<size_t>(o) * n;
        cost_row(out[o], in, first, n, params, row);
        double cost;
        s.best_input[o] = cheapest(row, n, cost);
        s.heap.emplace_back(cost, o);
        lower_bound += std::min(cost, params.cap2);
        if (lower_bound >= bound) return lower_bound;
    }
    // Lazy greedy: the heap's top is the cheapest remaining pair when its input entry is
    // still free; otherwise that row alone is rescanned and pushed back.
    const auto later = [](const std::pair<double, int>& a, const std::pair<double, int>& b) { return a > b; };
    std::make_heap(s.heap.begin(), s.heap.end(), later);
    double total = 0.0;
    while (!s.heap.empty()) {
        std::pop_heap(s.heap.begin(), s.heap.end(), later);
        const auto [cost, o] = s.heap.back();
        s.heap.pop_back();
        const int i = s.best_input[o];
        if (i >= 0 && s.taken[i]) {
            double fresh;
            s.best_input[o] = cheapest_free(s.rows.data() + static_cast<size_t>(o) * n, n, s.taken, fresh);
            s.heap.emplace_back(fresh, o);
            std::push_heap(s.heap.begin(), s.heap.end(), later);
            continue;
        }
        total += std::min(cost, params.cap2);
        if (i >= 0) s.taken[i] = 1;
        if (partner) partner[o] = i;
        if (total >= bound) return total;
    }
    return total;
}

}  // namespace tessera::grow
