// Holes in PCF outputs (docs/pcf_synthesis.md, "Holes"): the PCFs weigh each distance by
// the pairs at it, so an empty region a few disks wide costs the error little and the
// refinement does not close it (most visibly with radii spanning orders of magnitude).
// close_holes moves elements from the most crowded places into every empty disk larger
// than 1.2x the exemplar's largest (rim to rim, inside the domain), so the counts stay.
// Private to the library.
#pragma once

#include "tessera/exemplar.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera::pcf {

// Closes the holes of `out` (a synthesis of `exemplar` in `domain`) in place; notes in
// out.stats what it moved and whether it hit its bound.
void close_holes(const Exemplar& exemplar, const Domain& domain, const PcfSynthOptions& options, Arrangement& out);

}  // namespace tessera::pcf
