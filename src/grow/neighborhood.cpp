// Output neighbourhoods and best matches for growth (grow/neighborhood.hpp).
#include "grow/neighborhood.hpp"

#include <algorithm>
#include <cmath>

namespace tessera::grow {

namespace {

// Pool elements tried when no neighbour gives a coherent candidate.
constexpr int kFallbackCandidates = 64;

}  // namespace

void gather_output(const Grower::Impl& g, const Vec3& p, const Quat& frame, int self, double radius,
                   Scratch& s) {
    s.entries.clear();
    const Quat inverse = frame.conjugate();
    // Unsorted: the entries are sorted below by distance, then index (a total order).
    g.grid.for_each_within(
        p, radius, [&](int i) { return g.out[i].p; },
        [&](int i) {
            if (i == self) return;
            det::NeighborEntry e;
            e.offset = inverse.rotate(g.out[i].p - p);
            if (g.metric.dimension == 2) e.offset.z = 0.0;
            e.sample = i;
            e.element = i;
            e.type = g.out[i].type;
            const int src = g.out[i].source;
            e.radius = src >= 0 ? g.exemplar.elements[src].radius : g.existing.elements[g.out[i].kept].radius;
            s.entries.push_back(e);
        });
    std::sort(s.entries.begin(), s.entries.end(),
              [](const det::NeighborEntry& a, const det::NeighborEntry& b) {
                  const double da = dot(a.offset, a.offset), db = dot(b.offset, b.offset);
                  return da != db ? da < db : a.element < b.element;
              });
}

int count_within(const Scratch& s, double r) {
    const double r2 = r * r;
    int m = 0;
    while (m < static_cast<int>(s.entries.size()) && dot(s.entries[m].offset, s.entries[m].offset) <= r2) ++m;
    return m;
}

Match best_match(const Grower::Impl& g, int type, int own, int shape_of, int m, Scratch& s) {
    const InputElements& in = g.input;
    s.candidates.clear();
    auto add_with_set = [&](int c) {
        if (c < 0) return;
        if (in.type[c] == type) s.candidates.push_back(c);
        for (int k = in.sim_start[c]; k < in.sim_start[c + 1]; ++k)
            if (in.type[in.sim[k]] == type) s.candidates.push_back(in.sim[k]);
    };
    const int mine = own >= 0 ? in.nearest_in_pool(type, in.centroid[own], g.metric.params.spacing) : -1;
    add_with_set(mine);
    // Where the element was copied from: coherent with its own layout even when its
    // neighbourhood is still one-sided (a frontier element, whose few neighbours fit
    // mirror places of the exemplar as well).
    const int from =
        shape_of >= 0 ? in.nearest_in_pool(type, in.centroid[shape_of], g.metric.params.spacing) : -1;
    add_with_set(from);
    for (int j = 0; j < m; ++j) {
        const int known = g.out[s.entries[j].element].match;
        if (known < 0) continue;
        // The neighbour sits at offset o from us and matched input element `known`, so we
        // correspond to the input point centroid(known) - o (k-coherence).
        add_with_set(
            in.nearest_in_pool(type, in.centroid[known] - s.entries[j].offset, g.metric.params.spacing));
    }
    std::sort(s.candidates.begin(), s.candidates.end());
    s.candidates.erase(std::unique(s.candidates.begin(), s.candidates.end()), s.candidates.end());
    if (s.candidates.empty() && type < static_cast<int>(in.pool.size())) {
        const std::vector<int>& pool = in.pool[type];
        const int stride = std::max<int>(1, static_cast<int>(pool.size()) / kFallbackCandidates);
        for (size_t k = 0; k < pool.size(); k += stride) s.candidates.push_back(pool[k]);
    }
    Match best;
    best.neighbors = m;
    double best_cost = 1e300;
    // The order candidates are tried in decides ties (the first wins) and how soon the bound
    // prunes. Without neighbours every cost ties: where the element was copied from wins.
    // With neighbours (no ties in practice) its last match goes first: it is usually still
    // the best, and its cost makes most others stop after a row or two.
    for (const int first : {from, m > 0 ? mine : -1}) {
        if (first < 0) continue;
        const auto it = std::find(s.candidates.begin(), s.candidates.end(), first);
        if (it != s.candidates.end()) std::rotate(s.candidates.begin(), it, it + 1);
    }
    for (const int c : s.candidates) {
        // The element's own shape against the candidate's, then its neighbourhood (Eq. 3).
        const double shape = in.shape_distance(shape_of, c);
        if (shape >= best_cost) continue;
        const double cost = shape + pair_greedy(s.entries.data(), m, in, c, in.metric_count[c],
                                                g.metric.params, s.pair, nullptr, best_cost - shape);
        if (cost < best_cost) best_cost = cost, best.input = c;
    }
    best.energy = best.input >= 0 ? best_cost : 0.0;
    return best;
}

}  // namespace tessera::grow
