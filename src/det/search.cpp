#include "det/search.hpp"

#include <algorithm>
#include <cmath>

#include "core/parallel.hpp"
#include "det/input_index.hpp"
#include "det/matching.hpp"

namespace tessera::det {

namespace {

// Per-thread buffers, reused for every sample of the step.
struct Scratch {
    std::vector<NeighborEntry> out_nb;
    std::vector<std::pair<double, int>> sort_buf;
    std::vector<int> candidates;
    std::vector<unsigned> stamp;  // stamp[i] == current: input i already a candidate
    unsigned current = 0;
    MatchScratch match;
    std::vector<int> partner, best_partner;
};

// lambda * Eq. 6: the input neighbourhood n(s_i), shifted to p(s_o), should lie in the domain.
double occupancy_term(const InputIndex& index, int i, const Vec3& center, const Quat& frame, bool rotate,
                      const Domain& domain, const Params& params) {
    const NeighborEntry* nb = index.neighbors(i);
    double sum = 0.0;
    const double r2 = params.radius * params.radius;
    for (int q = 0; q < index.neighbor_count(i); ++q) {
        if (squared_norm(nb[q].offset) > r2) continue;
        const double c = domain.occupancy(center + (rotate ? frame.rotate(nb[q].offset) : nb[q].offset));
        sum += (1.0 - c) * (1.0 - c);
    }
    return params.lambda * sum;
}

void add_candidate(Scratch& s, int i) {
    if (i < 0 || s.stamp[i] == s.current) return;
    s.stamp[i] = s.current;
    s.candidates.push_back(i);
}

void add_with_similarity_set(Scratch& s, const InputIndex& index, int i) {
    if (i < 0) return;
    add_candidate(s, i);
    for (int q = index.sim_start[i]; q < index.sim_start[i + 1]; ++q) add_candidate(s, index.sim[q]);
}

}  // namespace

double search_step(OutputState& state, const InputIndex& index, const Domain& domain, const Params& params,
                   const SearchSettings& settings) {
    const Arrangement& out = state.arrangement;
    const int n = static_cast<int>(out.samples.size());
    // Per-sample views of the output for neighbourhood gathering.
    std::vector<Vec3> positions(n);
    std::vector<int> type(n), element(n);
    std::vector<double> radius(n);
    for (int i = 0; i < n; ++i) {
        positions[i] = out.samples[i].p;
        if (params.dimension == 2) positions[i].z = 0.0;
        element[i] = out.samples[i].element;
        type[i] = out.elements[element[i]].type;
        radius[i] = out.elements[element[i]].radius;
    }
    core::SpatialGrid grid;
    grid.build(positions, params.radius, params.dimension);
    // Constrained selection: which output samples belong to floor elements now.
    state.floor.assign(n, 0);
    if (params.floor_constraints) {
        const std::vector<char> floor_element =
            floor_elements(out, domain, params.gravity, params.floor_distance, params.boundary);
        for (int i = 0; i < n; ++i) state.floor[i] = floor_element[element[i]];
    }
    const bool use_frames = params.field.active();
    state.frame.assign(n, Quat{});
    if (use_frames)
        for (int i = 0; i < n; ++i) state.frame[i] = params.field.frame(positions[i], params.dimension);

    const std::vector<int> previous = state.match;
    state.match.resize(n, -1);
    state.cost.resize(n, 0.0);
    state.pairs.resize(n);

    const int threads = core::resolve_threads(settings.threads);
    std::vector<Scratch> scratch(threads);
    for (auto& s : scratch) s.stamp.assign(index.size(), 0);

    core::parallel_for(n, threads, [&](int begin, int end, int t) {
        Scratch& s = scratch[t];
        for (int so = begin; so < end; ++so) {
            if ((so & 63) == 0) core::check(settings.interrupt, t);
            gather_neighbors(grid, positions, positions[so], so, params.radius, params.dimension, state.key, type,
                             element, radius, s.out_nb, s.sort_buf, max_neighbors);
            // Eq. 7: relative positions are measured in the local frame of the centre.
            if (use_frames) {
                const Quat inverse = state.frame[so].conjugate();
                for (auto& e : s.out_nb) e.offset = inverse.rotate(e.offset);
            }
            std::stable_sort(s.out_nb.begin(), s.out_nb.end(), [](const NeighborEntry& a, const NeighborEntry& b) {
                return a.match_key < b.match_key;
            });
            const int m = static_cast<int>(s.out_nb.size());
            const int key = state.key[so];

            // Candidate set.
            ++s.current;
            if (s.current == 0) {  // stamp wrapped: reset
                std::fill(s.stamp.begin(), s.stamp.end(), 0u);
                s.current = 1;
            }
            s.candidates.clear();
            if (settings.mode == SearchMode::exhaustive || previous.empty()) {
                for (int i : index.by_key[key]) add_candidate(s, i);
            } else {
                add_with_similarity_set(s, index, previous[so]);
                // Coherence: each neighbour s'_o matched to m(s'_o) suggests the input sample
                // at p(m(s'_o)) - (p(s'_o) - p(s_o)) for s_o (shifted as in [Han et al. 2006]).
                for (const auto& e : s.out_nb) {
                    const int mo = previous[e.sample];
                    // Samples of the centre's own element suggest (almost always) its own previous match.
                    if (mo < 0 || e.element == element[so]) continue;
                    const Vec3 predicted = index.positions[mo] - e.offset;
                    add_with_similarity_set(s, index, index.nearest_with_key(predicted, key, std::sqrt(params.cap2)));
                }
                if (s.candidates.empty())
                    for (int i : index.by_key[key]) add_candidate(s, i);
            }
            if (params.floor_constraints) {
                // Floor samples copy only input floor samples, the others only non-floor ones.
                const char want = state.floor[so];
                auto wrong = [&](int i) { return index.floor[i] != want; };
                s.candidates.erase(std::remove_if(s.candidates.begin(), s.candidates.end(), wrong), s.candidates.end());
                if (s.candidates.empty())
                    for (int i : index.by_key[key])
                        if (!wrong(i)) s.candidates.push_back(i);
                if (s.candidates.empty())  // the exemplar has no such sample: unconstrained
                    for (int i : index.by_key[key]) s.candidates.push_back(i);
            }
            // Deterministic order whatever produced them; the previous match goes first
            // so that its cost bounds (and cuts short) the evaluation of the others.
            std::sort(s.candidates.begin(), s.candidates.end());
            if (!previous.empty() && previous[so] >= 0) {
                auto it = std::find(s.candidates.begin(), s.candidates.end(), previous[so]);
                if (it != s.candidates.end()) std::rotate(s.candidates.begin(), it, it + 1);
            }

            // Evaluate Eq. 1 (+ lambda Eq. 6) for each candidate; keep the best.
            s.partner.resize(m);
            s.best_partner.assign(m, -1);
            double best = INFINITY;
            int best_i = -1;
            const auto& self_element = out.elements[element[so]];
            // Eq. 6 vanishes for every candidate when the whole disk of radius r lies inside.
            const bool near_boundary =
                params.lambda > 0.0 && domain.distance_to_boundary(positions[so]) < params.radius;
            for (int i : s.candidates) {
                double c = 0.0;
                if (key == 0) {  // the centre's own attribute term
                    double q = index.type[i] != self_element.type ? 1.0 : 0.0;
                    if (self_element.radius > 0.0 || index.radius[i] > 0.0) {
                        const double dr = (self_element.radius - index.radius[i]) / params.spacing;
                        q += dr * dr;
                    }
                    c += params.alpha * q;
                }
                if (near_boundary)
                    c += occupancy_term(index, i, positions[so], state.frame[so], use_frames, domain, params);
                if (c >= best) continue;
                c += match_neighborhoods(s.out_nb.data(), m, index.neighbors(i), index.neighbor_count(i), params,
                                         s.match, s.partner.data(), best - c);
                if (c < best) {
                    best = c;
                    best_i = i;
                    std::copy(s.partner.begin(), s.partner.end(), s.best_partner.begin());
                }
            }
            state.match[so] = best_i;
            state.cost[so] = best_i >= 0 ? best : 0.0;
            auto& pairs = state.pairs[so];
            pairs.clear();
            if (best_i < 0) continue;
            const NeighborEntry* in_nb = index.neighbors(best_i);
            for (int q = 0; q < m; ++q) {
                const int pi = s.best_partner[q];
                if (pi < 0) continue;
                const double c = pair_cost(s.out_nb[q], in_nb[pi], params);
                const double w = c <= params.cap2 ? 1.0 : params.cap2 / c;
                // Eq. 3 in the output frame: the input offset turned by the centre's local frame.
                const Vec3 predicted = use_frames ? state.frame[so].rotate(in_nb[pi].offset) : in_nb[pi].offset;
                pairs.push_back(Pair{s.out_nb[q].sample, in_nb[pi].sample, predicted, w});
            }
        }
    });
    double energy = 0.0;
    for (int i = 0; i < n; ++i) energy += state.cost[i];
    return energy;
}

}  // namespace tessera::det
