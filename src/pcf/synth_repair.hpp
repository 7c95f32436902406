// The final passes of PCF synthesis from an exemplar (docs/pcf_synthesis.md, "Crowding"):
// the PCFs are blind to distances within a kernel width (sigma r_max), so the refinement
// may leave elements closer together than the exemplar ever shows them; the crowding
// repair of src/core/crowding_repair.hpp (the one det uses) pushes them apart until the
// lower tail of every ordered class pair's nearest-neighbour distances is the exemplar's.
// Private to the library.
#pragma once

#include "tessera/exemplar.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera::pcf {

// Repairs `out` (the synthesis of a model of `exemplar` in `domain`) in place; notes in
// out.stats what it did and whether it hit its round bound.
void repair_output(const Exemplar& exemplar, const Domain& domain, const PcfSynthOptions& options, Arrangement& out);

}  // namespace tessera::pcf
