// Search step (section 4.2): for every output sample, the input sample whose
// neighbourhood is most similar under Eq. 1 plus the occupancy term lambda * Eq. 6.
#pragma once

#include "core/interrupt.hpp"
#include "det/model.hpp"

namespace tessera::det {

struct SearchSettings {
    SearchMode mode = SearchMode::kcoherence;
    int threads = 1;
    const core::Interrupt* interrupt = nullptr;  // checked every 64 output samples
};

// Fills state.match, state.cost and state.pairs; returns the energy E of Eq. 2
// (sum of the costs, reduced in sample order so it does not depend on threads).
// `element_radius_of_sample` etc. are derived from state.arrangement.
double search_step(OutputState& state, const InputIndex& index, const Domain& domain, const Params& params,
                   const SearchSettings& settings);

}  // namespace tessera::det
