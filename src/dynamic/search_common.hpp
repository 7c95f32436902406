// Pieces the frame-by-frame search (frame_search.cpp) and the all-frame search
// (all_frames_solve.cpp) share: the world-cell key of random draws and the predictions a
// search leaves for the assignment. Output is OutputFrames or AllFrames: both index their
// matches, weights and predictions by one sample (or sample-frame) number.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include "core/rng.hpp"
#include "dynamic/frame_search.hpp"
#include "dynamic/input_frames.hpp"
#include "dynamic/st_metric.hpp"

namespace tessera::dynamic {

// A key of the world cell holding p (cells one spacing wide, anchored at the origin), so
// that random draws depend on where a sample is, not on its index in this run.
inline std::uint64_t world_cell_key(const Vec3& p, double spacing) {
    std::uint64_t key = 0;
    for (int k = 0; k < 3; ++k)
        key = core::mix64(key ^ static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(p[k] / spacing))));
    return key;
}

// Eq. 6 for every pair of the N matched neighbourhoods of output sample i (its
// neighbourhood in scratch.neighbourhood), weighted by omega_j (Eq. 12) and the pair's
// falloff (Eq. 9).
template <class Output>
void write_predictions(const InputFrames& input, Output& output, int i, const StParams& params,
                       SearchScratch& scratch) {
    const StNeighbourhood& nb = scratch.neighbourhood;
    int& count = output.prediction_count(i);
    count = 0;
    Prediction* out = output.predictions(i);
    for (int j = 0; j < output.matches(); ++j) {
        const int m = output.match(i)[j];
        if (m < 0 || output.omega(i)[j] <= 0.0) continue;
        scratch.partner.assign(nb.entries.size(), -1);
        st_distance(nb, input.entries(m), input.group_start(m), params, scratch.metric, scratch.partner.data(),
                    std::numeric_limits<double>::infinity());
        const StEntry* in = input.entries(m);
        for (int k = 0; k < nb.groups; ++k)
            for (int e = nb.start[k]; e < nb.start[k + 1]; ++e) {
                const int p = scratch.partner[e];
                if (p < 0 || count >= output.prediction_stride()) continue;
                const double w = output.omega(i)[j] * 0.5 * (nb.entries[e].kappa + in[p].kappa);
                out[count++] = Prediction{nb.entries[e].sample, k, nb.entries[e].offset - in[p].offset, w};
            }
    }
}

// The N best of scratch.candidates for the neighbourhood in scratch.neighbourhood, with
// their blend weights (Eq. 11-12), and the predictions of output sample i; returns the best
// distance (0 when no candidate). Each candidate's distance is cut off at the N-th best so far.
// `extra(id)` is added to each candidate's distance (the occupancy term near a wall).
template <class Output, class Extra>
double match_and_predict(const InputFrames& input, Output& output, int i, const StParams& params,
                         SearchScratch& scratch, const Extra& extra) {
    const int n = output.matches();
    int* best = output.match(i);
    double* dist = output.distance(i);
    int count = 0;
    for (int id : scratch.candidates) {
        const double bound = count < n ? std::numeric_limits<double>::infinity() : dist[n - 1];
        const double e = extra(id);
        if (e >= bound) continue;
        const double d = e + st_distance(scratch.neighbourhood, input.entries(id), input.group_start(id), params,
                                         scratch.metric, nullptr, bound - e);
        if (d < bound) keep_best(id, d, n, best, dist, count);
    }
    for (int j = count; j < n; ++j) best[j] = -1, dist[j] = 0.0;
    blend_weights(dist, count, output.omega(i));
    for (int j = count; j < n; ++j) output.omega(i)[j] = 0.0;
    write_predictions(input, output, i, params, scratch);
    return count > 0 ? dist[0] : 0.0;
}

template <class Output>
double match_and_predict(const InputFrames& input, Output& output, int i, const StParams& params,
                         SearchScratch& scratch) {
    return match_and_predict(input, output, i, params, scratch, [](int) { return 0.0; });
}

}  // namespace tessera::dynamic
