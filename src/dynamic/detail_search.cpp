// dynamic/detail_search.cpp — the search step of all-frame detail synthesis (detail_field.hpp).
#include <algorithm>
#include <limits>

#include "core/parallel.hpp"
#include "core/rng.hpp"
#include "dynamic/cross_neighbours.hpp"
#include "dynamic/detail_field.hpp"

namespace tessera::dynamic {

double detail_distance(const DetailField& out, int f, int s, const DetailField& in, int g, int j,
                       const std::vector<GridOffset>& offsets, double cap2, double cutoff) {
    const Vec3 centre_out = out.at(f, s), centre_in = in.at(g, j);
    double sum = squared_norm(centre_out - centre_in) * offsets[0].kappa;
    for (size_t k = 1; k < offsets.size() && sum < cutoff; ++k) {
        const GridOffset& o = offsets[k];
        const int so = out.grid.step(s, o.dr, o.dc), si = in.grid.step(j, o.dr, o.dc);
        const bool has_out = out.valid(f + o.dt, so), has_in = in.valid(g + o.dt, si);
        if (has_out && has_in)
            sum += o.kappa * squared_norm((out.at(f + o.dt, so) - centre_out) - (in.at(g + o.dt, si) - centre_in));
        else if (has_out != has_in)
            sum += o.kappa * cap2;
    }
    return sum;
}

namespace {

struct Scratch {
    std::vector<int> candidates;
    CrossScratch cross;
};

// Candidates of k-coherence search (Tong et al. 2002) on the grid: a neighbour (s', f + dt)
// matched to (j', g') proposes (j' - (dr, dc), g' - dt), the input sample-frame whose own
// neighbour at the same offset is (j', g').
void coherent_candidates(const DetailField& in, const DetailField& out, int f, int s,
                         const std::vector<GridOffset>& offsets, const DetailMatches& previous,
                         std::vector<int>& candidates) {
    for (const GridOffset& o : offsets) {
        const int so = out.grid.step(s, o.dr, o.dc);
        if (!out.valid(f + o.dt, so)) continue;
        const int* m = previous.of((f + o.dt) * out.samples + so);
        for (int k = 0; k < previous.n && m[k] >= 0; ++k) {
            const int j = in.grid.step(m[k] % in.samples, -o.dr, -o.dc), g = m[k] / in.samples - o.dt;
            if (in.valid(g, j) && in.type[j] == out.type[s]) candidates.push_back(g * in.samples + j);
        }
    }
}

void random_candidates(const DetailField& in, const std::vector<int>& of_type, int f, int s,
                       const DetailSearch& settings, std::vector<int>& candidates) {
    if (of_type.empty()) return;
    // Keyed by the sample's place in the output (element, sample, frame) and the round.
    const core::KeyedRng rng(settings.seed, core::Purpose::dynamic_detail, static_cast<std::uint64_t>(s),
                             (static_cast<std::uint64_t>(settings.round) << 32) | static_cast<std::uint32_t>(f));
    for (int k = 0; k < settings.random_candidates; ++k) {
        const int j = of_type[rng.below(2 * k, of_type.size())];
        const int g = static_cast<int>(rng.below(2 * k + 1, static_cast<std::uint64_t>(in.frames)));
        candidates.push_back(g * in.samples + j);
    }
}

void all_candidates(const DetailField& in, const std::vector<int>& of_type, std::vector<int>& candidates) {
    for (int g = 0; g < in.frames; ++g)
        for (int j : of_type) candidates.push_back(g * in.samples + j);
}

// Keeps the n cheapest (cost, then id: no dependence on candidate order).
double search_one(const DetailField& in, const DetailField& out, const std::vector<int>& of_type, int f, int s,
                  const DetailSearch& settings, const DetailMatches& previous, DetailMatches& next, Scratch& scratch) {
    const int k = f * out.samples + s;
    const std::vector<GridOffset>& offsets = (*settings.offsets)[out.type[s]];
    std::vector<int>& cand = scratch.candidates;
    cand.clear();
    if (settings.exhaustive) {
        all_candidates(in, of_type, cand);
    } else {
        coherent_candidates(in, out, f, s, offsets, previous, cand);
        random_candidates(in, of_type, f, s, settings, cand);
    }
    std::sort(cand.begin(), cand.end());
    cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
    int* best = next.of(k);
    double* cost = next.cost_of(k);
    std::fill(best, best + next.n, -1);
    std::fill(cost, cost + next.n, std::numeric_limits<double>::infinity());
    const bool cross = settings.cross && settings.cross->active();
    for (int c : cand) {
        double d = detail_distance(out, f, s, in, c / in.samples, c % in.samples, offsets, settings.cap2,
                                   cost[next.n - 1]);
        if (cross && d < cost[next.n - 1])
            d += cross_distance(*settings.cross, out, f, s, in, c / in.samples, c % in.samples, settings.cap2,
                                scratch.cross);
        if (!(d < cost[next.n - 1])) continue;  // ids ascend, so an equal cost keeps the earlier id
        int slot = next.n - 1;
        for (; slot > 0 && d < cost[slot - 1]; --slot) best[slot] = best[slot - 1], cost[slot] = cost[slot - 1];
        best[slot] = c, cost[slot] = d;
    }
    if (cross)  // the pairs of the matches kept, for the assignment
        for (int q = 0; q < next.n; ++q) {
            int* partner = next.partners(k, q);
            std::fill(partner, partner + DetailMatches::kCross, -1);
            if (best[q] >= 0)
                cross_distance(*settings.cross, out, f, s, in, best[q] / in.samples, best[q] % in.samples,
                               settings.cap2, scratch.cross, partner);
        }
    return best[0] >= 0 ? cost[0] : 0.0;
}

}  // namespace

double search_details(const DetailField& in, const DetailField& out, const DetailSearch& settings,
                      const DetailMatches& previous, DetailMatches& next, int threads) {
    std::vector<std::vector<int>> of_type(settings.offsets->size());
    for (int j = 0; j < in.samples; ++j) of_type[in.type[j]].push_back(j);
    const int n = out.frames * out.samples;
    if (settings.cross && settings.cross->active()) next.partner.resize(next.id.size() * DetailMatches::kCross);
    std::vector<Scratch> scratch(core::resolve_threads(threads));
    std::vector<double> energy(n, 0.0);
    core::parallel_for(
        n, threads,
        [&](int begin, int end, int thread) {
            scratch[thread].candidates.reserve(settings.exhaustive ? of_type.size() * in.samples * in.frames : 512);
            for (int k = begin; k < end; ++k)
                energy[k] = search_one(in, out, of_type[out.type[k % out.samples]], k / out.samples,
                                       k % out.samples, settings, previous, next, scratch[thread]);
        },
        64);
    double sum = 0.0;
    for (double e : energy) sum += e;
    return n > 0 ? sum / n : 0.0;
}

}  // namespace tessera::dynamic
