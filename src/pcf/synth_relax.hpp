// The pair correlation relaxation of PCF outputs (docs/pcf_synthesis.md, "Relaxation"): the
// method matches each class's PCF to its own and to its parents', one class at a time in
// dependency order, on the disk metric's normalised axis; the pair correlation of every
// class pair on the plain distance axis (what spatstat and B5 measure) is never matched
// as a whole, and clustered patterns keep errors several times a verbatim copy's. A last
// step runs det's pair relaxation (src/det/pair_relaxation.hpp) on the output: small keyed
// moves kept only when they bring every class pair's g(r) closer to the exemplar's,
// never closer than the exemplar's closest pair. For points only: for disks the plain
// distances' g(r) and the disk metric's PCFs disagree, and matching the first pulled the
// second out of its envelopes (toy forest: 89% of r-bins inside -> 69%). Private.
#pragma once

#include "tessera/exemplar.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera::pcf {

void relax_output(const Exemplar& exemplar, const Domain& domain, const PcfSynthOptions& options, Arrangement& out);

}  // namespace tessera::pcf
