// dynamic/all_frames_solve.cpp — search and Jacobi assignment over all sample-frames.
#include "dynamic/all_frames_solve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel.hpp"
#include "core/rng.hpp"
#include "dynamic/search_common.hpp"

namespace tessera::dynamic {

namespace {

constexpr int coherent_neighbours = 8;  // near neighbours whose matches propose shifted candidates
// Keys the random draws of this search apart from the frame-by-frame search's.
constexpr std::uint64_t all_frames_key = std::uint64_t{1} << 40;

void push_with_similar(const InputFrames& input, int m, std::vector<int>& out) {
    if (m < 0) return;
    out.push_back(m);
    for (int c : input.similar(m)) out.push_back(c);
}

void coherent_candidates(const InputFrames& input, const AllFrames& output, int s, int f, const StParams& params,
                         const SearchScratch& scratch, std::vector<int>& out) {
    const int n = output.size();
    for (int j = 0; j < output.matches(); ++j) push_with_similar(input, output.prior_match(f * n + s)[j], out);
    // Temporal coherence both ways: the match one frame before, moved on; one after, moved back.
    if (f > 0) {
        const int m = output.prior_match((f - 1) * n + s)[0];
        if (m >= 0) push_with_similar(input, input.next(m), out);
    }
    if (f + 1 < output.frames()) {
        const int m = output.prior_match((f + 1) * n + s)[0];
        if (m >= 0) push_with_similar(input, input.previous(m), out);
    }
    // Near neighbours' best matches, shifted by the offset between the two samples.
    const StNeighbourhood& nb = scratch.neighbourhood;
    const int end = std::min(nb.start[1], nb.start[0] + coherent_neighbours);
    for (int e = nb.start[0]; e < end; ++e) {
        const int m = output.prior_match(f * n + nb.entries[e].sample)[0];
        if (m < 0) continue;
        const int c = input.nearest(input.frame(m), input.position(m) - nb.entries[e].offset, output.type(s),
                                    params.input_radius);
        if (c >= 0) out.push_back(c);
    }
}

void gather_candidates(const InputFrames& input, const AllFrames& output, int s, int f, const StParams& params,
                       const SearchSettings& settings, SearchScratch& scratch) {
    std::vector<int>& out = scratch.candidates;
    out.clear();
    const std::vector<int>& pool = input.of_type(output.type(s));
    if (settings.mode == SearchMode::exhaustive) {
        out = pool;
        return;
    }
    coherent_candidates(input, output, s, f, params, scratch, out);
    if (!pool.empty() && settings.random_candidates > 0) {
        const core::KeyedRng rng(settings.seed, core::Purpose::dynamic_candidate,
                                 all_frames_key + static_cast<std::uint64_t>(f) * 64 + settings.round,
                                 world_cell_key(output.at(f, s), params.spacing));
        for (int r = 0; r < settings.random_candidates; ++r) out.push_back(pool[rng.below(r, pool.size())]);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

double search_sample(const InputFrames& input, AllFrames& output, int s, int f, const StParams& params,
                     const SearchSettings& settings, SearchScratch& scratch) {
    const int i = output.index(s, f);
    output.gather(s, f, scratch.neighbourhood);
    gather_candidates(input, output, s, f, params, settings, scratch);
    return match_and_predict(input, output, i, params, scratch);
}

// The group of (s, f)'s neighbourhood at time offset -dt: the pair of the same sample at
// f + dt that points back at f.
int group_of_offset(int dt, const StParams& params) {
    for (int k = 1; k < params.temporal; ++k)
        if (time_offset(k, params) == dt) return k;
    return -1;
}

}  // namespace

double search_all_frames(const InputFrames& input, AllFrames& output, const StParams& params,
                         const SearchSettings& settings, std::vector<SearchScratch>& scratch, int threads) {
    const int n = output.size(), total = n * output.frames();
    output.snapshot_matches();
    std::vector<double> energy(total, 0.0);
    core::parallel_for(
        total, threads,
        [&](int begin, int end, int thread) {
            for (int i = begin; i < end; ++i)
                energy[i] = search_sample(input, output, i % n, i / n, params, settings, scratch[thread]);
        },
        16);
    double sum = 0.0;
    for (double e : energy) sum += e;
    return total > 0 ? sum / total : 0.0;
}

void assign_all_frames(AllFrames& output, double radius, const StParams& params, int threads) {
    const int n = output.size(), total = n * output.frames();
    std::vector<Vec3> next(total);
    core::parallel_for(
        total, threads,
        [&](int begin, int end, int) {
            for (int i = begin; i < end; ++i) {
                const int s = i % n, f = i / n;
                const Vec3 here = output.at(f, s);
                Vec3 sum;
                double weight = 0.0;
                const Prediction* own = output.predictions(i);
                for (int p = 0; p < output.prediction_count(i); ++p) {
                    sum += (here + own[p].displacement) * own[p].weight;
                    weight += own[p].weight;
                }
                // Eq. 7's terms of the other sample-frames' neighbourhoods that hold (s, f),
                // those held fixed (the Jacobi form of section 4.1): spatial neighbours at f ...
                const auto add_theirs = [&](int j, int sample, int group) {
                    const Prediction* theirs = output.predictions(j);
                    for (int t = 0; t < output.prediction_count(j); ++t)
                        if (theirs[t].sample == sample && theirs[t].group == group) {
                            sum += (here - theirs[t].displacement) * theirs[t].weight;
                            weight += theirs[t].weight;
                        }
                };
                output.for_each_neighbour(s, f, radius, [&](int o) { add_theirs(output.index(o, f), s, 0); });
                // ... and the same sample at the frames around f, whose trails reach back to f.
                for (int k = 1; k < params.temporal; ++k) {
                    const int g = f + time_offset(k, params);
                    const int back = group_of_offset(-time_offset(k, params), params);
                    if (g >= 0 && g < output.frames() && back > 0) add_theirs(output.index(s, g), s, back);
                }
                next[i] = weight > 0.0 ? sum / weight : here;
            }
        },
        16);
    output.positions() = std::move(next);
}

void keep_inside_domain(Vec3& p, const Domain& domain, bool wrap) {
    if (wrap) {
        const Box& box = domain.bounds();
        for (int k = 0; k < domain.dimension(); ++k) {
            const double extent = box.hi[k] - box.lo[k];
            p[k] -= std::floor((p[k] - box.lo[k]) / extent) * extent;
        }
    }
    if (!domain.inside(p)) p = domain.closest_inside(p);
}

}  // namespace tessera::dynamic
