// Exemplars whose coordinates were rounded when they were recorded.
//
// Field data often comes rounded: the Japanese pines to 0.01 of their unit window, the
// Swedish pines and the anemones to whole units, at a sixth to a seventh of their spacing.
// A method that copies exemplar offsets exactly (growth: p(h) + (p(e') - p(e))) then puts
// every element on the rounding lattice, and the output shows rows of equally spaced
// elements and none of the exemplar's close pairs (grown Japanese pines had no pair under
// 0.03, the exemplar 6% of its elements). Rounding to q means the true position lay
// anywhere within q/2 of the recorded one, so such an exemplar is copied with each element
// moved by a uniform draw within that cell: the lattice is gone, the statistics at scales
// above q are those of the data.
#pragma once

#include <cstdint>

#include "tessera/exemplar.hpp"

namespace tessera::core {

// The largest q of the form {1, 2, 5} x 10^k of which every sample coordinate is a whole
// multiple (to 1e-6 of q), or 0 when there is none above 1e-9 of the exemplar's extent.
double coordinate_resolution(const Exemplar& exemplar);

// Whether the exemplar counts as rounded: its resolution lies between kNegligible and
// kLattice of its mean nearest-neighbour distance `spacing` (finer rounding changes
// nothing one can see; coarser is the pattern's own lattice, kept exact).
bool is_rounded(double resolution, double spacing);

// A copy of the exemplar with every element (all its samples together) moved by a uniform
// draw in [-q/2, q/2) along each axis, keyed by (seed, element index), when it is rounded
// (is_rounded); an unchanged copy otherwise. A draw that would bring the element's centre
// closer to another than the data's closest pair of their types is drawn again (at most
// kAttempts times, then the element keeps its place). O(n^2) in the exemplar's elements.
Exemplar dequantized(const Exemplar& exemplar, double spacing, std::uint64_t seed);

}  // namespace tessera::core
