// Initialization of all-frame detail synthesis (section 4.1, "Initialization"): spatio-
// temporal patches of whole elements copied from the exemplar, so that no element starts
// broken. Each output element takes the detail of one exemplar element of its type over a
// window of frames; the next window continues the same exemplar element when the exemplar
// has frames left, else starts where an exemplar element's frame best continues the detail
// just copied (the patch boundary compatibility of patch-based synthesis). Elements of
// different sample counts are mapped by their relative place along the grid.
#pragma once

#include "dynamic/detail_field.hpp"

namespace tessera::dynamic {

// Fills out.detail and makes every copied sample-frame's source its first match.
// `window`: frames per patch (the neighbourhood's temporal size, as the paper sets it).
void copy_patches(const DetailField& in, DetailField& out, DetailMatches& matches, int window, std::uint64_t seed,
                  int threads);

}  // namespace tessera::dynamic
