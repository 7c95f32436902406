// Adding and removing output elements while keeping track of where each came from: every
// output sample remembers the exemplar sample it copies (the search's previous match for
// k-coherence, the vote's attributes), every output element the exemplar element.
// Initialization (InitResult) and the iterations (OutputState) hold these side by side
// with the arrangement; a Provenance views either.
#pragma once

#include <vector>

#include "tessera/exemplar.hpp"

namespace tessera::det {

struct Provenance {
    Arrangement& out;
    std::vector<int>& source_sample;   // per output sample
    std::vector<int>& source_element;  // per output element
};

// Appends a copy of exemplar element `source` moved by p -> rotation p + shift; returns
// the new element's index.
int append_copy(Provenance into, const Exemplar& exemplar, int source, const Quat& rotation, const Vec3& shift,
                int dimension);

// Keeps the elements with keep[e] (their samples and provenance), renumbering ids 0..n-1.
void keep_only(Provenance of, const std::vector<char>& keep);

// Element positions (centroids), z = 0 in 2D: the points of the grids over elements.
std::vector<Vec3> element_centroids(const std::vector<Element>& elements, int dimension);

}  // namespace tessera::det
