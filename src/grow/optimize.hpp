// Optimization of a round (section V): the weighted least-squares position solve of
// Eq. 6-7 over the horizon and a band behind it, attribute reassignment by votes, and
// redistribution by local type histograms.
#pragma once

#include <vector>

#include "grow/grow_state.hpp"

namespace tessera::grow {

struct OptimizeReport {
    int unknowns = 0;       // elements whose position the last solve changed
    int reassigned = 0;     // types changed by votes (V.B)
    int redistributed = 0;  // types changed by the histograms (V.C)
    int crowded = 0;        // elements still crowding a neighbour after the repair
    double energy = 0.0;    // mean energy per neighbour of the horizon at the last search
};

// `region` (may be null) bounds the moves: an element whose samples would leave it stays.
OptimizeReport optimize_round(Grower::Impl& g, const Domain* region);

}  // namespace tessera::grow
