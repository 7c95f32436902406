// The optimization of a growth round (grow/optimize.hpp).
#include "grow/optimize.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/parallel.hpp"
#include "grow/neighborhood.hpp"
#include "grow/repair.hpp"

namespace tessera::grow {

namespace {

// Damping at the horizon itself: Eq. 7 gives horizon elements weight 0, which leaves a
// component without fixed neighbours free to translate; this keeps the system positive
// definite without pulling measurably.
constexpr double kHorizonAnchor = 0.01;

// One prediction of Eq. 6 made by element v's neighbourhood: p(other) - p(v) = offset.
struct Prediction {
    int other = -1;  // output element
    int input = -1;  // input element e' paired with it
    Vec3 offset;     // o(v) (p(e') - p(e)), in world axes
    double weight = 1.0;
    bool assigned = false;  // within c: a vote in V.B
};

struct Unknowns {
    std::vector<int> element;             // sorted element indices
    std::vector<double> weight;           // Eq. 7's w: rises with the distance from the horizon
    std::unordered_map<int, int> column;  // element -> column
};

// The horizon and the unlocked elements within the lock distance of it, with their weights.
Unknowns collect_unknowns(const Grower::Impl& g) {
    const double lock = g.options.lock_distance * g.metric.params.radius;
    std::unordered_map<int, double> distance;
    for (const int h : g.horizon) distance[h] = 0.0;
    std::vector<int> near;
    for (const int h : g.horizon) {
        g.grid.query(
            g.out[h].p, lock, [&](int i) { return g.out[i].p; }, near);
        for (const int i : near) {
            if (g.out[i].locked) continue;
            const double d = norm(g.out[i].p - g.out[h].p);
            auto [it, fresh] = distance.emplace(i, d);
            if (!fresh) it->second = std::min(it->second, d);
        }
    }
    Unknowns u;
    for (const auto& [i, d] : distance) u.element.push_back(i);
    std::sort(u.element.begin(), u.element.end());
    for (size_t c = 0; c < u.element.size(); ++c) {
        u.column[u.element[c]] = static_cast<int>(c);
        const double d = distance[u.element[c]];
        u.weight.push_back(d == 0.0 ? kHorizonAnchor : kHorizonAnchor + g.options.band_weight * d / lock);
    }
    return u;
}

// Whether predict searches for each unknown's best match or pairs it again with the match
// the last search found (the assignment step alone, after a solve moved it).
enum class Search { fresh, keep };

// Each unknown's best match and the predictions its pairs make (Eq. 6), in parallel; with
// Search::keep, `mean_energy` stays the last search's.
void predict(Grower::Impl& g, const Unknowns& u, std::vector<std::vector<Prediction>>& predictions,
             std::vector<double>& mean_energy, Search search) {
    const int n = static_cast<int>(u.element.size());
    predictions.assign(n, {});
    if (search == Search::fresh) mean_energy.assign(n, 0.0);
    std::vector<int> matched(n, -1);
    core::parallel_for(
        n, g.threads,
        [&](int begin, int end, int thread) {
            Scratch s;
            for (int c = begin; c < end; ++c) {
                g.interrupt.check(thread);
                const int v = u.element[c];
                const OutElement& e = g.out[v];
                const Quat frame = g.frame_at(e.p);
                gather_output(g, e.p, frame, v, g.metric.params.radius, s);
                const int m = static_cast<int>(s.entries.size());
                Match best;
                if (search == Search::keep && e.match >= 0) {
                    best.input = e.match;
                } else {
                    best = best_match(g, e.type, e.match, e.source, m, s);
                    if (best.input < 0) continue;
                    matched[c] = best.input;
                    mean_energy[c] = best.mean();
                }
                s.partner.assign(m, -1);
                const det::NeighborEntry* in = g.input.neighbors(best.input);
                pair_greedy(s.entries.data(), m, g.input, best.input, g.input.metric_count[best.input],
                            g.metric.params, s.pair, s.partner.data(), 1e300);
                for (int o = 0; o < m; ++o) {
                    if (s.partner[o] < 0) continue;
                    const det::NeighborEntry& pi = in[s.partner[o]];
                    const Vec3 d = s.entries[o].offset - pi.offset;
                    const double cost = dot(d, d);
                    Prediction p;
                    p.other = s.entries[o].element;
                    p.input = pi.element;
                    p.offset = frame.rotate(pi.offset);
                    // Robust weight: a pair further off than the assignment threshold c is more
                    // likely a wrong pairing (an extra element paired with a free place a spacing
                    // away) than a displaced neighbour, and must not drag it onto another element.
                    p.weight = cost > g.metric.threshold2 ? std::pow(g.metric.threshold2 / cost, 2) : 1.0;
                    p.assigned = cost < g.metric.threshold2;
                    predictions[c].push_back(p);
                }
            }
        },
        kElementsPerThread);
    for (int c = 0; c < n; ++c)
        if (matched[c] >= 0) g.out[u.element[c]].match = matched[c];
}

// Eq. 6-7 as normal equations: sum_w |(x_v' - x_v) - offset|^2 + sum w_v |x_v - x0_v|^2,
// one sparse matrix for all coordinates, factored by Eigen's sparse Cholesky (LDL^T).
void solve(Grower::Impl& g, const Unknowns& u, const std::vector<std::vector<Prediction>>& predictions,
           const Domain* region) {
    const int n = static_cast<int>(u.element.size());
    const int dims = g.metric.dimension;
    std::vector<Eigen::Triplet<double>> triplets;
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(n, dims);
    for (int c = 0; c < n; ++c) {
        const Vec3 x0 = g.out[u.element[c]].p;
        triplets.emplace_back(c, c, u.weight[c]);
        for (int k = 0; k < dims; ++k) b(c, k) += u.weight[c] * x0[k];
        for (const Prediction& p : predictions[c]) {
            const auto it = u.column.find(p.other);
            triplets.emplace_back(c, c, p.weight);
            if (it != u.column.end()) {
                const int o = it->second;
                triplets.emplace_back(o, o, p.weight);
                triplets.emplace_back(c, o, -p.weight);
                triplets.emplace_back(o, c, -p.weight);
                for (int k = 0; k < dims; ++k)
                    b(c, k) -= p.weight * p.offset[k], b(o, k) += p.weight * p.offset[k];
            } else {  // a fixed neighbour: x_v = x_v' - offset
                const Vec3 fixed = g.out[p.other].p;
                for (int k = 0; k < dims; ++k) b(c, k) += p.weight * (fixed[k] - p.offset[k]);
            }
        }
    }
    Eigen::SparseMatrix<double> a(n, n);
    a.setFromTriplets(triplets.begin(), triplets.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> cholesky(a);
    if (cholesky.info() != Eigen::Success) return;  // cannot happen: a is diagonally dominant
    const Eigen::MatrixXd x = cholesky.solve(b);
    std::vector<Vec3> samples;
    for (int c = 0; c < n; ++c) {
        const int v = u.element[c];
        Vec3 p = g.out[v].p;
        for (int k = 0; k < dims; ++k) p[k] = x(c, k);
        g.keep_on_layer(g.out[v].p, p);
        if (!is_finite(p)) continue;
        if (region && !g.fits_region(*region, g.out[v].kept, g.out[v].source, g.out[v].frame, p, samples))
            continue;
        g.move(v, p);
    }
}

// No neighbour of element v closer than the hard core of its type with `type`.
bool fits_as(const Grower::Impl& g, int v, int type, std::vector<int>& near) {
    g.grid.query(
        g.out[v].p, g.reach, [&](int i) { return g.out[i].p; }, near);
    for (const int i : near)
        if (i != v && norm(g.out[i].p - g.out[v].p) < g.hard_core(type, g.out[i].type)) return false;
    return true;
}

void retype(Grower::Impl& g, int v, int type, int source) {
    g.set_type(v, type);
    OutElement& e = g.out[v];
    e.source = source;
    e.match = source;
}

// V.B: every assigned pair <v', e'> votes for q(e') on v'; v' takes the type with the most
// votes when it has at least GrowOptions::votes and more than its own type.
int reassign_by_votes(Grower::Impl& g, const Unknowns& u,
                      const std::vector<std::vector<Prediction>>& predictions) {
    struct Tally {
        int keep = 0;
        std::vector<int> votes, source;
    };
    const int types = static_cast<int>(g.exemplar.types.size());
    std::unordered_map<int, Tally> tally;
    for (size_t c = 0; c < predictions.size(); ++c)
        for (const Prediction& p : predictions[c]) {
            if (!p.assigned || !u.column.count(p.other)) continue;
            Tally& t = tally[p.other];
            if (t.votes.empty()) t.votes.assign(types, 0), t.source.assign(types, -1);
            const int q = g.input.type[p.input];
            if (q == g.out[p.other].type) {
                ++t.keep;
            } else {
                if (t.source[q] < 0) t.source[q] = p.input;
                ++t.votes[q];
            }
        }
    int changed = 0;
    std::vector<int> near;
    for (const int v : u.element) {
        const auto it = tally.find(v);
        if (it == tally.end() || g.out[v].locked) continue;
        const Tally& t = it->second;
        const int q = static_cast<int>(std::max_element(t.votes.begin(), t.votes.end()) - t.votes.begin());
        if (t.votes[q] < g.options.votes || t.votes[q] <= t.keep || !fits_as(g, v, q, near)) continue;
        retype(g, v, q, t.source[q]);
        ++changed;
    }
    return changed;
}

// V.C: a horizon element whose type is over-represented in its neighbourhood, against the
// histogram of its matching input neighbourhood, takes the most under-represented type.
int redistribute(Grower::Impl& g) {
    const int types = static_cast<int>(g.exemplar.types.size());
    if (types < 2) return 0;
    std::vector<double> have(types), want(types);
    std::vector<int> near;
    Scratch s;
    int changed = 0;
    for (const int h : g.horizon) {
        const OutElement& e = g.out[h];
        if (e.locked || e.match < 0) continue;
        gather_output(g, e.p, g.frame_at(e.p), h, g.metric.params.radius, s);
        std::fill(have.begin(), have.end(), 0.0);
        std::fill(want.begin(), want.end(), 0.0);
        have[e.type] += 1.0;
        for (const det::NeighborEntry& n : s.entries) have[n.type] += 1.0;
        const int m_in = g.input.within_r[e.match];
        want[g.input.type[e.match]] += 1.0;
        for (int i = 0; i < m_in; ++i) want[g.input.neighbors(e.match)[i].type] += 1.0;
        const double scale = (static_cast<double>(s.entries.size()) + 1.0) / (m_in + 1.0);
        for (double& w : want) w *= scale;
        if (have[e.type] - want[e.type] < 1.0) continue;
        int under = -1;
        for (int t = 0; t < types; ++t)
            if (t != e.type && want[t] - have[t] >= 1.0 &&
                (under < 0 || want[t] - have[t] > want[under] - have[under]))
                under = t;
        if (under < 0 || !fits_as(g, h, under, near)) continue;
        // The input element of that type nearest the match lends its layout.
        int source = -1;
        const det::NeighborEntry* nb = g.input.neighbors(e.match);
        for (int i = 0; i < g.input.nb_start[e.match + 1] - g.input.nb_start[e.match] && source < 0; ++i)
            if (nb[i].type == under) source = nb[i].element;
        if (source < 0) continue;
        retype(g, h, under, source);
        ++changed;
    }
    return changed;
}

}  // namespace

OptimizeReport optimize_round(Grower::Impl& g, const Domain* region) {
    OptimizeReport report;
    const Unknowns u = collect_unknowns(g);
    report.unknowns = static_cast<int>(u.element.size());
    if (u.element.empty()) return report;
    std::vector<std::vector<Prediction>> predictions;
    std::vector<double> energy;
    // One search, then `solves` assignments and solves: the first pairs the search's matches,
    // the later ones pair the same matches again at the moved positions. A search after
    // each solve (the matches rarely change: a solve moves elements a fraction of c) and
    // after the last one cost two thirds of the round and changed no measured quality
    // (docs/grow.md). The votes come from the last pairing, the reported energy from the search.
    predict(g, u, predictions, energy, Search::fresh);
    for (int k = 0; k < g.options.solves; ++k) {
        if (k > 0) predict(g, u, predictions, energy, Search::keep);
        solve(g, u, predictions, region);
    }
    if (g.options.solves > 0) report.crowded = repair_round(g, u.element, region);
    double sum = 0.0;
    int count = 0;
    for (size_t c = 0; c < u.element.size(); ++c)
        if (g.out[u.element[c]].born == g.round) sum += energy[c], ++count;
    report.energy = count > 0 ? sum / count : 0.0;
    report.reassigned = reassign_by_votes(g, u, predictions);
    report.redistributed = redistribute(g);
    return report;
}

}  // namespace tessera::grow
