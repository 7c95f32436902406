// A covered region thinned back to the exemplar's density (grow/thinning.cpp).
//
// Nothing in a round counts elements beyond one neighbourhood: the count ceiling
// (grow/crowd_ceiling.hpp) lets every element have as many neighbours as the exemplar's
// crowded ones (its 85% quantile), the hole fills look only at holes, and along the region's
// edge, where the ceiling's disk is half empty, nothing holds the count at all. Inhibited
// field data grew over their density: the cells at 1.15x (1.30x within 0.2 of the edge,
// 1.10x inside), the Swedish pines at 1.13x, the anemones at 1.08x, 3D rods at 1.18x. Once
// a region is covered, an output holding clearly more elements than the exemplar's density
// asks of the region loses the surplus where it is most crowded.
#pragma once

#include "grow/grow_state.hpp"

namespace tessera::grow {

// For a closed region (an open one, a world's tile,
// is left alone: its neighbours' elements are not all there yet): when the elements whose
// centre lies in `region` exceed the exemplar's density times its measure by more than
// twice its Poisson deviation plus 2%, removes unlocked elements of [first, end), of types
// not short of their share, down to that count. The most crowded go first: the largest
// count of elements within four spacings, over the share of that disk (ball) inside the
// region. Returns how many were removed (0: the region's count was within bounds).
int thin_to_density(Grower::Impl& g, int first, const Domain& region);

}  // namespace tessera::grow
