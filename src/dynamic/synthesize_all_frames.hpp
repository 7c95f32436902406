// All-frame synthesis of particles and agents (section 4.1, all-frame sequencing; Figure 3
// bottom, Figure 4): synthesize_dynamic with DynamicOptions::sequencing = all.
#pragma once

#include "tessera/dynamic.hpp"

namespace tessera::dynamic {

// Initializes every frame by spatio-temporal patch copy (all_frames_init.hpp), then runs
// `iterations` rounds of search and Jacobi assignment over all sample-frames together with
// temporal-non-causal neighbourhoods of the compact shape reaching h = max(1, temporal_size
// / 2) frames each way. stats.energy: the energy of the initialization, then after each
// round. Throws as synthesize_dynamic does, and Error(option) for shape full (this path
// gathers the compact shape only) or an exemplar with fewer than 2 h + 1 frames.
AnimatedArrangement synthesize_all_frames(const Animation& given, const Domain& domain, const DynamicOptions& options,
                                          const Progress& progress);

}  // namespace tessera::dynamic
