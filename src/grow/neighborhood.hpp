// Output neighbourhoods and the best-matching input element (Eq. 3), through the dynamic
// grid and the k-coherence sets only.
#pragma once

#include "grow/grow_state.hpp"

namespace tessera::grow {

// Elements within `radius` of p other than `self`, as entries relative to p in the local
// frame `frame` (nearest first, ties by index), into s.entries (element index in .element).
void gather_output(const Grower::Impl& g, const Vec3& p, const Quat& frame, int self, double radius,
                   Scratch& s);

struct Match {
    int input = -1;       // best input element, -1 when none of the type exists
    double energy = 0.0;  // |n(h) - n(e)|^2 of Eq. 3
    int neighbors = 0;    // output neighbours paired against (within r)
    double mean() const { return energy / (neighbors > 0 ? neighbors : 1); }
};

// Best input element of `type` for an output neighbourhood (the first `m` entries of
// s.entries, those within r): k-coherence candidates from the element's own last match
// (`own`, -1 if none) and from each neighbour's match shifted by its offset, with their
// similarity sets. With no candidate (no neighbour knows its match), a bounded stride of
// the type's pool is tried. `shape` is the input element whose layout the output element
// copies (-1 for none): a candidate's layout differing from it adds
// InputElements::shape_distance to the cost.
Match best_match(const Grower::Impl& g, int type, int own, int shape, int m, Scratch& s);

// Number of leading entries of s.entries within distance r.
int count_within(const Scratch& s, double r);

}  // namespace tessera::grow
