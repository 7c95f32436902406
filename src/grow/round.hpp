// One round of growth (section III): generation, the filters, the choice, optimization.
#pragma once

#include "grow/grow_state.hpp"

namespace tessera::grow {

struct RoundLimits {
    const Domain* region = nullptr;  // candidates outside it are discarded; moves stay inside
    int budget = -1;                 // at most this many new elements (-1 = no limit)
    Vec3 origin;                     // with a budget, the candidates nearest it are kept
};

// Runs one round; the new elements become the horizon (when the round adds none, the
// horizon is left as it was). Adds the round's counts to `report`; returns the net number of
// elements added (made less displaced).
int run_round(Grower::Impl& g, const RoundLimits& limits, GrowReport& report);

}  // namespace tessera::grow
