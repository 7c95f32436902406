// The pair-correlation relaxation of a grow(region) call's elements (grow/relax.cpp).
//
// Growth places elements at copied exemplar offsets and solves their positions against
// their matches (Eq. 6-7); nothing in a round looks beyond one neighbourhood, and the pair
// correlation of a grown output drifts from the exemplar's at the scales no single
// neighbourhood fixes: field patterns grew with 2x to 7x synthesize_det's PCF error (grown
// Japanese pines 0.24, ganglia 0.16, amacrine 0.087; synthesize_det 0.03 to 0.04). The same
// final pass as synthesize_det's (det/pair_relaxation.hpp: keyed random steps kept where
// they bring the output's pair correlation closer to the exemplar's, never closer than its
// closest pair) brings them to 0.03 to 0.11.
#pragma once

#include "grow/grow_state.hpp"

namespace tessera::grow {

// Relaxes the unlocked elements the current call made (indices from `first`) whose centre
// lies in `region`, the pair correlation measured over the region's elements in the region
// as the window. Elements within reach of one outside the region (the seam with earlier
// calls or neighbouring tiles) stay, so that no move can come closer to an element the
// relaxation does not see than the exemplar allows. Single-sample exemplars only (as the
// relaxation). Then, as synthesize_det's final passes, a crowding repair of the moved
// elements (the relaxation keeps the closest pair, not the exemplar's share of close pairs)
// and the holes it opened filled. Adds the moves kept to report.relaxed, the holes filled
// to report.filled and report.added. `extra_sweeps` are added to the grower's sweeps (when it
// has any).
void relax_pair_correlation(Grower::Impl& g, const Domain& region, int first, GrowReport& report, int extra_sweeps = 0);

}  // namespace tessera::grow
