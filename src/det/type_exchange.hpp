// Class counts by exchange. Patch windows sample an exemplar unevenly (its margins less
// than its middle), seams drop elements, and large elements lose more of both: a two-class
// exemplar of stones among pebbles came out with a quarter of its stones missing and its
// pebbles over their count, and no hole among pebbles is large enough for a stone. The
// exchange puts elements of the worst served type where the other poorly served types leave
// the most room, and takes out the elements of better served types (their shortfall against
// their counts 2% smaller or more) that are closer to it than the exemplar's closest
// distance for their pair of types (the hard core), one element at a time, while no
// yielding type ends up shorter than the type served, until the counts are met or no place
// has room. The classes' shortfalls are so balanced instead of one class carrying them all.
#pragma once

#include <cstdint>

#include "core/crowding_repair.hpp"
#include "det/model.hpp"
#include "det/provenance.hpp"

namespace tessera::det {

// Returns how many elements were exchanged (inserted; about as many were removed).
int exchange_types(Provenance of, const Exemplar& exemplar, const Domain& domain, const Params& params,
                   const core::CrowdingBounds& tails, std::uint64_t seed);

}  // namespace tessera::det
