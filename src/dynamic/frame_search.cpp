// dynamic/frame_search.cpp — search (k-coherence or exhaustive, N best) and assignment.
#include "dynamic/frame_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel.hpp"
#include "core/rng.hpp"
#include "dynamic/search_common.hpp"

namespace tessera::dynamic {

namespace {

constexpr int coherent_neighbours = 8;  // nearest neighbours whose matches propose shifted candidates

void coherent_candidates(const InputFrames& input, const OutputFrames& output, int s, const StParams& params,
                         const SearchScratch& scratch, std::vector<int>& out) {
    const int type = output.type(s);
    for (int j = 0; j < output.matches(); ++j) {
        const int m = output.prior_match(s)[j];
        if (m < 0) continue;
        out.push_back(m);
        for (int c : input.similar(m)) out.push_back(c);
    }
    // Each near neighbour's best match, shifted by the offset between the two samples. Where
    // the shift lands near the sample's own best match (the two copy the same input patch,
    // the common case once synthesis is coherent) that match is the candidate already.
    const StNeighbourhood& nb = scratch.neighbourhood;
    const int own = output.prior_match(s)[0];
    const double same2 = 0.09 * params.spacing * params.spacing;
    const int end = std::min(nb.start[1], nb.start[0] + coherent_neighbours);
    for (int e = nb.start[0]; e < end; ++e) {
        const int o = nb.entries[e].sample;
        const int m = output.prior_match(o)[0];
        if (m < 0) continue;
        const Vec3 target = input.position(m) - nb.entries[e].offset;
        if (own >= 0 && input.frame(own) == input.frame(m) && squared_norm(input.position(own) - target) < same2)
            continue;
        const int c = input.nearest(input.frame(m), target, type, params.input_radius);
        if (c >= 0) out.push_back(c);
    }
}

void gather_candidates(const InputFrames& input, const OutputFrames& output, int s, const StParams& params,
                       const SearchSettings& settings, SearchScratch& scratch) {
    std::vector<int>& out = scratch.candidates;
    out.clear();
    const std::vector<int>& pool = input.of_type(output.type(s));
    if (settings.first_frame_only) {
        for (int id : pool) {
            if (input.frame(id) != input.first_frame()) break;  // pools are in id order: frame by frame
            out.push_back(id);
        }
    } else if (settings.mode == SearchMode::exhaustive) {
        out = pool;
        return;
    } else {
        coherent_candidates(input, output, s, params, scratch, out);
    }
    if (!pool.empty() && settings.random_candidates > 0) {
        const core::KeyedRng rng(settings.seed, core::Purpose::dynamic_candidate,
                                 static_cast<std::uint64_t>(output.frame()) * 64 + settings.round,
                                 world_cell_key(output.current()[s], params.spacing));
        for (int r = 0; r < settings.random_candidates; ++r) out.push_back(pool[rng.below(r, pool.size())]);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

// A point as the domain sees it: with `wrap`, folded into the bounding box first.
Vec3 folded(const Vec3& p, const SearchSettings& settings, int dimension) {
    if (!settings.wrap) return p;
    const Box& b = settings.domain->bounds();
    Vec3 q = p;
    for (int k = 0; k < dimension; ++k) {
        const double extent = b.hi[k] - b.lo[k];
        q[k] -= std::floor((q[k] - b.lo[k]) / extent) * extent;
    }
    return q;
}

// lambda * Eq. 6 for input candidate id at the output sample's place p: its spatial
// neighbours (within r) that would lie outside the domain, each costing 1 (boxes and
// polygons are sharp; masks and meshes give their occupancy).
double occupancy_cost(const InputFrames& input, int id, const Vec3& p, const StParams& params,
                      const SearchSettings& settings) {
    const StEntry* in = input.entries(id);
    const int* start = input.group_start(id);
    const double r2 = params.radius * params.radius;
    double sum = 0.0;
    for (int e = start[0]; e < start[1]; ++e) {
        if (squared_norm(in[e].offset) > r2) continue;
        const double c = settings.domain->occupancy(folded(p + in[e].offset, settings, params.dimension));
        sum += (1.0 - c) * (1.0 - c);
    }
    return settings.lambda * sum;
}

double search_sample(const InputFrames& input, OutputFrames& output, int s, const StParams& params,
                     const SearchSettings& settings, SearchScratch& scratch) {
    output.gather(s, scratch.neighbourhood);
    gather_candidates(input, output, s, params, settings, scratch);
    const Vec3 p = output.current()[s];
    // The term vanishes where the disk of radius r round the sample lies inside.
    const bool near_wall = settings.domain && settings.lambda > 0.0 &&
                           settings.domain->distance_to_boundary(folded(p, settings, params.dimension)) < params.radius;
    if (!near_wall) return match_and_predict(input, output, s, params, scratch);
    return match_and_predict(input, output, s, params, scratch,
                             [&](int id) { return occupancy_cost(input, id, p, params, settings); });
}

}  // namespace

void keep_best(int id, double d, int n, int* best, double* dist, int& count) {
    int at = count < n ? count : n;
    while (at > 0 && d < dist[at - 1]) --at;
    if (at >= n) return;
    for (int j = std::min(count, n - 1); j > at; --j) best[j] = best[j - 1], dist[j] = dist[j - 1];
    best[at] = id, dist[at] = d;
    count = std::min(count + 1, n);
}

// Eq. 12: omega_j = 1 - d_j / sum_k d_k (Eq. 11 normalises by their sum); equal weights when
// every distance is zero, and 1 for a single match.
void blend_weights(const double* dist, int count, double* omega) {
    double sum = 0.0;
    for (int j = 0; j < count; ++j) sum += dist[j];
    for (int j = 0; j < count; ++j) omega[j] = count == 1 ? 1.0 : sum > 0.0 ? 1.0 - dist[j] / sum : 1.0;
}

double search_frame(const InputFrames& input, OutputFrames& output, const StParams& params,
                    const SearchSettings& settings, std::vector<SearchScratch>& scratch, int threads) {
    const int n = output.size();
    output.snapshot_matches();
    std::vector<double> energy(n, 0.0);
    core::parallel_for(
        n, threads,
        [&](int begin, int end, int thread) {
            for (int s = begin; s < end; ++s)
                energy[s] = search_sample(input, output, s, params, settings, scratch[thread]);
        },
        16);
    double sum = 0.0;
    for (double e : energy) sum += e;
    return n > 0 ? sum / n : 0.0;
}

void assign_frame(OutputFrames& output, double radius, int threads) {
    const int n = output.size();
    std::vector<Vec3> next(n);
    core::parallel_for(
        n, threads,
        [&](int begin, int end, int) {
            for (int s = begin; s < end; ++s) {
                Vec3 sum;
                double weight = 0.0;
                const Prediction* own = output.predictions(s);
                const Vec3 here = output.current()[s];
                for (int i = 0; i < output.prediction_count(s); ++i) {
                    sum += (here + own[i].displacement) * own[i].weight;
                    weight += own[i].weight;
                }
                // The pairs of the neighbours' matches that hold s: where they put s (Eq. 7's
                // terms of n(s') with s' held fixed, the Jacobi form of section 4.1).
                output.for_each_neighbour(s, radius, [&](int o) {
                    const Prediction* theirs = output.predictions(o);
                    for (int t = 0; t < output.prediction_count(o); ++t)
                        if (theirs[t].sample == s && theirs[t].group == 0) {
                            sum += (here - theirs[t].displacement) * theirs[t].weight;
                            weight += theirs[t].weight;
                        }
                });
                next[s] = weight > 0.0 ? sum / weight : output.current()[s];
            }
        },
        16);
    output.current() = std::move(next);
}

}  // namespace tessera::dynamic

namespace tessera::dynamic {

void build_similarity(InputFrames& input, const StParams& params, int k, int scan, std::uint64_t seed, int threads) {
    const int n = input.size();
    std::vector<std::vector<int>> similar(n);
    std::vector<SearchScratch> scratch(core::resolve_threads(threads));
    core::parallel_for(
        n, threads,
        [&](int begin, int end, int thread) {
            SearchScratch& sc = scratch[thread];
            std::vector<int> best(k, -1);
            std::vector<double> dist(k, 0.0);
            for (int a = begin; a < end; ++a) {
                // Input a as if it were an output neighbourhood.
                StNeighbourhood& nb = sc.neighbourhood;
                const int* start = input.group_start(a);
                nb.entries.assign(input.entries(a), input.entries(a) + start[params.temporal]);
                std::copy(start, start + max_temporal + 1, nb.start.begin());
                nb.groups = params.temporal;
                const std::vector<int>& pool = input.of_type(input.type(a));
                const core::KeyedRng rng(seed, core::Purpose::dynamic_similarity, static_cast<std::uint64_t>(a));
                sc.candidates.clear();
                for (int r = 0; r < scan && !pool.empty(); ++r) {
                    const int c = pool[rng.below(r, pool.size())];
                    if (input.sample(c) != input.sample(a)) sc.candidates.push_back(c);
                }
                std::sort(sc.candidates.begin(), sc.candidates.end());
                sc.candidates.erase(std::unique(sc.candidates.begin(), sc.candidates.end()), sc.candidates.end());
                int count = 0;
                for (int c : sc.candidates) {
                    const double bound = count < k ? std::numeric_limits<double>::infinity() : dist[k - 1];
                    const double d = st_distance(nb, input.entries(c), input.group_start(c), params, sc.metric,
                                                 nullptr, bound);
                    if (d < bound) keep_best(c, d, k, best.data(), dist.data(), count);
                }
                similar[a].assign(best.begin(), best.begin() + count);
            }
        },
        16);
    input.set_similar(std::move(similar));
}

}  // namespace tessera::dynamic
