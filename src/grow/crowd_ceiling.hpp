// The local count ceiling of growth (section IV's filters, extended): no element may have
// more neighbours within a few spacings than the exemplar's elements have there.
//
// Why: for a pattern whose closest pairs are far under its typical spacing (field data:
// pines, cells, anemones), the hard core does not regulate density. Patches copied at
// neighbouring horizon elements overlap, and their unpaired elements fill the gaps between
// elements already there as long as no pair comes closer than the hard core. Such outputs
// grew at 1.2x to 1.4x the exemplar's density. The ceiling bounds the count in a disk
// (ball) of radius R around every element, measured on the exemplar with an edge
// correction (count / share of the disk inside the window), so a synthesized
// neighbourhood is never more crowded than the exemplar's own crowded ones.
#pragma once

#include <limits>

#include "tessera/exemplar.hpp"

namespace tessera::grow {

struct CrowdCeiling {
    double radius = 0.0;  // R
    // Most neighbours an element may have within R (inactive: infinite).
    double limit = std::numeric_limits<double>::infinity();
    bool active() const { return limit < std::numeric_limits<double>::infinity(); }
    bool allows(int neighbours) const { return neighbours <= limit; }
};

// The ceiling of a single-sample exemplar: R = kRadius mean spacings of its density, limit
// = the kQuantile-th of its elements' edge-corrected neighbour counts within R. Inactive for
// exemplars of multi-sample elements (their samples' hard cores regulate them) or with too
// few elements whose disk lies mostly in the window.
CrowdCeiling exemplar_crowd_ceiling(const Exemplar& exemplar, double total_density);

}  // namespace tessera::grow
