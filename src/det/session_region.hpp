// Iterations over a region of a held arrangement (DetSession::iterate(region, n)): the
// unlocked elements whose centre lies in the region move; the elements within two
// neighbourhood radii of them take part, fixed, so that the moving elements and their
// neighbours see complete neighbourhoods. The work is done on a sub-arrangement of just
// these elements, so a call costs what its region holds (plus one scan of the centres),
// not what the whole arrangement holds.
#pragma once

#include "det/session_state.hpp"

namespace tessera::det {

// Returns the energy (Eq. 2) of the last search over the sub-arrangement; 0 when the
// region holds no unlocked element.
double iterate_region(DetSession::Impl& s, const Domain& region, int iterations);

}  // namespace tessera::det
