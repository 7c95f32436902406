// Single-player Monte-Carlo tree search over a round's candidates (grow/mcts.hpp).
//
// Tree: level d decides whether candidate d (in order of fit) joins the horizon; a
// candidate in conflict with one already taken is skipped without a node. A play-out takes
// the remaining free candidates in a random order (keyed by seed, round and play-out) until
// none is left, as the paper's play-outs run "until there are no candidates left".
//
// Score (Eq. 4): the neighbourhood energy of the chosen horizon, each candidate measured
// against its own input element e' with the existing elements and the other chosen
// candidates as its neighbourhood. We divide the sum by the number chosen: the plain sum
// prefers the smallest horizon (a hole costs nothing in Eq. 4). As the paper does, the
// search maximizes x = 2 e_max - score (e_max: the worst score seen), scaled to [0, 1].
#include "grow/mcts.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/rng.hpp"
#include "grow/neighborhood.hpp"

namespace tessera::grow {

namespace {

struct Node {
    int child[2] = {-1, -1};  // take, skip
    int visits = 0;
    double sum = 0.0, sum2 = 0.0;
};

struct Problem {
    std::vector<Candidate> c;
    std::vector<std::vector<int>> conflicts;             // closer than their hard core
    std::vector<std::vector<int>> near;                  // other candidates within r
    std::vector<std::vector<det::NeighborEntry>> fixed;  // existing elements within r
};

Problem build_problem(const Grower::Impl& g, std::vector<Candidate> candidates) {
    Problem p;
    p.c = std::move(candidates);
    const int n = static_cast<int>(p.c.size());
    p.conflicts.assign(n, {});
    p.near.assign(n, {});
    p.fixed.assign(n, {});
    const double r = g.metric.params.radius;
    core::DynamicGrid grid(r, g.metric.dimension);
    for (int i = 0; i < n; ++i) grid.insert(i, p.c[i].p);
    std::vector<int> ids;
    Scratch s;
    for (int i = 0; i < n; ++i) {
        grid.query(
            p.c[i].p, r, [&](int j) { return p.c[j].p; }, ids);
        for (const int j : ids) {
            if (j == i) continue;
            p.near[i].push_back(j);
            if (norm(p.c[j].p - p.c[i].p) < g.hard_core(p.c[i].type, p.c[j].type))
                p.conflicts[i].push_back(j);
        }
        gather_output(g, p.c[i].p, p.c[i].frame, -1, r, s);
        p.fixed[i] = s.entries;
    }
    return p;
}

// Eq. 4 per chosen candidate for the choice `taken` (a flag per candidate).
double score(const Grower::Impl& g, const Problem& p, const std::vector<char>& taken, Scratch& s) {
    double sum = 0.0;
    int count = 0;
    for (size_t i = 0; i < p.c.size(); ++i) {
        if (!taken[i]) continue;
        s.entries = p.fixed[i];
        const Quat inverse = p.c[i].frame.conjugate();
        for (const int j : p.near[i]) {
            if (!taken[j]) continue;
            det::NeighborEntry e;
            e.offset = inverse.rotate(p.c[j].p - p.c[i].p);
            e.type = p.c[j].type;
            e.element = -1;
            e.radius = g.exemplar.elements[p.c[j].source].radius;
            s.entries.push_back(e);
        }
        const int src = p.c[i].source;
        sum += det::match_greedy(s.entries.data(), static_cast<int>(s.entries.size()), g.input.neighbors(src),
                                 g.input.metric_count[src], g.metric.params, s.match, nullptr, 1e300);
        ++count;
    }
    return count > 0 ? sum / count : 0.0;
}

void take(const Problem& p, int i, std::vector<char>& taken, std::vector<char>& blocked) {
    taken[i] = 1;
    blocked[i] = 1;
    for (const int j : p.conflicts[i]) blocked[j] = 1;
}

// Eq. 5 (SP-MCTS): mean + explore * sqrt(ln n / n_i) + sqrt((sum x^2 - n_i mean^2 + D) / n_i).
double selection_value(const Node& child, int parent_visits, double explore, double exploit) {
    const double mean = child.sum / child.visits;
    const double variance = (child.sum2 - child.visits * mean * mean + exploit) / child.visits;
    return mean + explore * std::sqrt(std::log(static_cast<double>(parent_visits)) / child.visits) +
           std::sqrt(std::max(0.0, variance));
}

}  // namespace

SearchReport choose_by_tree_search(const Grower::Impl& g, std::vector<Candidate>& candidates) {
    SearchReport report;
    const Problem p = build_problem(g, std::move(candidates));
    const int n = static_cast<int>(p.c.size());
    std::vector<Node> tree(1);
    std::vector<char> best, taken, blocked;
    double best_score = 1e300, worst = 0.0;
    Scratch s;
    std::vector<int> path, order;
    const core::KeyedRng rng(g.options.seed, core::Purpose::grow_playout,
                             static_cast<std::uint64_t>(g.round));
    for (int playout = 0; playout < g.options.playouts; ++playout) {
        taken.assign(n, 0);
        blocked.assign(n, 0);
        path.assign(1, 0);
        int depth = 0, node = 0;
        // Selection and expansion: descend through decided levels.
        for (;;) {
            while (depth < n && blocked[depth]) ++depth;
            if (depth >= n) break;
            Node& here = tree[node];
            int branch;
            if (here.child[0] < 0 || here.child[1] < 0) {
                branch = here.child[0] < 0 ? 0 : 1;
                const int fresh = static_cast<int>(tree.size());
                tree[node].child[branch] = fresh;
                tree.emplace_back();
                if (branch == 0)
                    take(p, depth, taken, blocked);
                else
                    blocked[depth] = 1;
                path.push_back(fresh);
                break;
            }
            const double v0 =
                selection_value(tree[here.child[0]], here.visits, g.options.explore, g.options.exploit);
            const double v1 =
                selection_value(tree[here.child[1]], here.visits, g.options.explore, g.options.exploit);
            branch = v1 > v0 ? 1 : 0;
            if (branch == 0)
                take(p, depth, taken, blocked);
            else
                blocked[depth] = 1;
            node = tree[node].child[branch];
            path.push_back(node);
        }
        // Play-out: the free candidates in a random order, each taken if still free.
        order.clear();
        for (int i = 0; i < n; ++i)
            if (!blocked[i]) order.push_back(i);
        for (size_t k = order.size(); k > 1; --k)
            std::swap(order[k - 1], order[rng.below(static_cast<std::uint64_t>(playout) * 1000003u + k, k)]);
        for (const int i : order)
            if (!blocked[i]) take(p, i, taken, blocked);
        const double sc = score(g, p, taken, s);
        worst = std::max(worst, sc);
        if (sc < best_score) best_score = sc, best = taken;
        // Back-propagation of x = 2 e_max - score, scaled by 2 e_max.
        const double x = worst > 0.0 ? (2.0 * worst - sc) / (2.0 * worst) : 1.0;
        for (const int k : path) {
            tree[k].visits += 1;
            tree[k].sum += x;
            tree[k].sum2 += x * x;
        }
        ++report.playouts;
    }
    candidates.clear();
    for (int i = 0; i < n; ++i)
        if (!best.empty() && best[i]) candidates.push_back(p.c[i]);
    report.best_score = best_score < 1e300 ? best_score : 0.0;
    return report;
}

}  // namespace tessera::grow
