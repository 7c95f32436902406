// Holes behind the horizon (grow/vacancies.cpp): where two fronts meet, or where a large
// element was dropped by the overlap filter, candidates can leave an empty place that no
// later round reaches, since rounds only propose next to the horizon. Each round, once an
// earlier round's elements are enclosed by later ones, the empty balls next to them larger
// than the exemplar's own largest hole get an element (of the type most short of its share
// whose hard cores hold), as det's vacancy filling does for synthesize_det.
#pragma once

#include "grow/grow_state.hpp"

namespace tessera::grow {

// In a covered region only holes this many times deeper than the exemplar's largest are
// filled: a region many times the exemplar's size has larger holes of its own (the largest
// of a random pattern grows with the area), and filling every hole over the exemplar's
// made clustered and random patterns regular (the redwood seedlings' pair correlation error
// 0.14 -> 0.17). The thinning leaves no hole deeper than this either.
inline constexpr double kCoveredHoleDepth = 1.25;

// Looks for enclosed holes next to elements [first, end) and fills them; the new elements
// are appended (ids assigned, not on the horizon). A hole counts as enclosed when elements,
// or the outside of `region` (when given), surround it in every direction. Only for
// exemplars of single-sample elements (returns 0 otherwise). Returns how many were added.
int fill_enclosed_holes(Grower::Impl& g, int first, int end, const Domain* region);
// The same next to the elements `around` only (those a later pass moved: a hole it opened
// lies next to one of them).
int fill_enclosed_holes_around(Grower::Impl& g, const std::vector<int>& around, const Domain* region);

// The same for a region growth has covered, probed on a lattice: every hole in it deeper
// than 1.25x the exemplar's counts, enclosed or not. Where two holes run into each other (a
// gap along the region's edge, two misaligned patches' seam) neither is enclosed, and a
// random pattern's grown output kept holes 1.4x the exemplar's largest along its edge. In a
// world's tile (an open region) a hole counts only when elements close it in every
// direction out of the tile: one open toward a face whose tile is not grown yet is that
// tile's to fill (filled here, a 3D world of spheres crowded its seams). Adds the repair of
// the inserted elements' neighbours. Returns how many were added.
int fill_covered_holes(Grower::Impl& g, int first, int end, const Domain& region);

}  // namespace tessera::grow
