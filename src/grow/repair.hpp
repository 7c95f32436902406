// Crowding repair of a round's elements (core/crowding_repair.hpp): the least-squares solve
// ignores element sizes, so it can bring two elements closer than the exemplar ever shows
// them; the repair pushes such pairs apart. It works on a small arrangement of the round's
// unknowns with their fixed neighbours (locked), so its cost is the round's.
#pragma once

#include <vector>

#include "grow/grow_state.hpp"

namespace tessera::grow {

// `movable`: sorted element indices that may move. Returns the report's remaining count.
int repair_round(Grower::Impl& g, const std::vector<int>& movable, const Domain* region);

}  // namespace tessera::grow
