// The search step of frame-by-frame synthesis (section 4.1; 4.2 for N best matches) and
// the assignment step (Eq. 6-7, Eq. 11-12), both over every sample of the frame being made,
// in parallel; each sample writes only its own slots, so results do not depend on threads.
#pragma once

#include <cstdint>
#include <vector>

#include "dynamic/input_frames.hpp"
#include "dynamic/output_frames.hpp"
#include "dynamic/st_metric.hpp"
#include "tessera/domain.hpp"

namespace tessera::dynamic {

struct SearchSettings {
    SearchMode mode = SearchMode::kcoherence;
    int random_candidates = 2;
    std::uint64_t seed = 1;
    int round = 0;                 // search round within the frame (a key of the random draws)
    bool first_frame_only = false; // candidates: the input's first usable frame, exhaustively
    // The occupancy term of the static method (Eq. 6 of Discrete Element Textures, lambda
    // times it) near the domain's walls, frame by frame: without it, a particle behind an
    // obstacle matched input neighbourhoods full on the wall's side as readily as any, and
    // the assignment emptied the obstacle's wake (0.64-0.74 of the density by the 48th
    // frame; advection alone kept 0.89-1.03). Off when `domain` is null; with `wrap` the
    // bounding box's sides are no walls.
    const Domain* domain = nullptr;
    bool wrap = false;
    double lambda = 0.0;
};

// Per-thread buffers of the search.
struct SearchScratch {
    StNeighbourhood neighbourhood;
    MetricScratch metric;
    std::vector<int> candidates, partner;
};

// Finds each sample's N best input matches (OutputFrames::match/distance/omega) and the
// predictions of their pairs. Returns the mean best distance (the frame's energy, Eq. 5).
double search_frame(const InputFrames& input, OutputFrames& output, const StParams& params,
                    const SearchSettings& settings, std::vector<SearchScratch>& scratch, int threads);

// The Jacobi assignment: each sample moves to the weighted mean of its predictions, the
// others held where they are (the caller then keeps it in the domain).
// `radius`: the output neighbourhood radius (whose neighbours' pairs may hold the sample).
void assign_frame(OutputFrames& output, double radius, int threads);

// Keeps the N best (distance, id) pairs in ascending order; equal distances keep the lower id
// (candidates arrive in id order and only a strictly better one displaces).
void keep_best(int id, double d, int n, int* best, double* dist, int& count);

// Eq. 12: the blending weights of `count` matches at distances `dist` (1 for a single match).
void blend_weights(const double* dist, int count, double* omega);

// k-coherence sets: for every input sample-frame, the k most similar among `scan` input
// sample-frames of its type drawn at random (keyed by the seed and the id), other samples
// only; the exemplar's sample-frames are too many for all pairs (Tong et al. 2002 build
// theirs from all pairs of a small texture).
void build_similarity(InputFrames& input, const StParams& params, int k, int scan, std::uint64_t seed, int threads);

}  // namespace tessera::dynamic
