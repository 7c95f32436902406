// The search and assignment steps of all-frame synthesis (section 4.1 with 4.2's N best
// matches), over every sample-frame of the animation at once with temporal-non-causal
// neighbourhoods: a sample at frame f is matched and moved knowing frames f - h .. f + h.
// Each sample-frame writes only its own slots, so results do not depend on threads.
#pragma once

#include <vector>

#include "dynamic/all_frames.hpp"
#include "dynamic/frame_search.hpp"
#include "dynamic/input_frames.hpp"
#include "tessera/domain.hpp"

namespace tessera::dynamic {

// Finds the N best input matches of every sample-frame and the predictions of their pairs.
// Candidates (k-coherence, Tong et al. 2002, extended in time): the sample-frame's own prior
// matches and their similarity sets, the prior match of the same sample one frame before
// moved on one frame and of one frame after moved back one, its near neighbours' matches
// shifted by their offsets, and random input sample-frames. Returns the mean best distance
// over all sample-frames (the energy of Eq. 5).
double search_all_frames(const InputFrames& input, AllFrames& output, const StParams& params,
                         const SearchSettings& settings, std::vector<SearchScratch>& scratch, int threads);

// The Jacobi assignment (Eq. 6-7 with Eq. 11): every sample-frame moves to the weighted
// mean of where its own pairs and its neighbours' pairs put it, in space (neighbours at its
// frame) and in time (the same sample at the frames around it), the others held fixed.
void assign_all_frames(AllFrames& output, double radius, const StParams& params, int threads);

// Moves a position that left the domain back in: wrap re-enters it on the far side of the
// bounding box; whatever is still outside goes to the nearest point inside.
void keep_inside_domain(Vec3& p, const Domain& domain, bool wrap);

}  // namespace tessera::dynamic
