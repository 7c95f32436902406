// brush/distribution.hpp — the search step of the brush solver: for every movable output
// sample, the input neighbourhood of its own exemplar (kappa, Eq. 2) that fits it best under
// Eq. 1 (offsets in the sample's local frame o(s), input offsets scaled by w_scale), with the
// greedy pairing of its neighbours.
#pragma once

#include <utility>
#include <vector>

#include "brush/brush_state.hpp"
#include "core/spatial_grid.hpp"

namespace tessera::brush {

struct NeighbourPair {
    int other = -1;     // output sample s'_o
    Vec3 target;        // w_scale p^(s'_i, s_i): the offset s'_o should have, in s_o's local frame
};

struct SampleMatch {
    int neighbourhood = -1;        // index into the entry's neighbourhoods; -1: none (no candidate)
    double cost = 0.0;             // d(N(s_o), N(s_i)) of Eq. 1, unpaired neighbours included
    std::vector<NeighbourPair> pairs;
};

// Output samples of other elements within the radius of s's exemplar, nearest first.
struct OutputNeighbours {
    core::SpatialGrid grid;
    std::vector<Vec3> points;
    double max_radius = 0.0;
    void build(const BrushCanvas::Impl& state);
    // `by_distance`: the caller's scratch, kept between calls.
    void gather(const BrushCanvas::Impl& state, int sample, double radius, std::vector<int>& out,
                std::vector<std::pair<double, int>>& by_distance) const;
};

// One match per sample of the arrangement (movable[s] false: left empty).
void search_matches(const BrushCanvas::Impl& state, const std::vector<char>& movable, std::vector<SampleMatch>& matches);

}  // namespace tessera::brush
