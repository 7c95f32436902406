// Adding and removing output elements while keeping track of where each came from: every
// output sample remembers the exemplar sample it copies (the search's previous match for
// k-coherence, the vote's attributes), every output element the exemplar element.
// Initialization (InitResult) and the iterations (OutputState) hold these side by side
// with the arrangement; a Provenance views either.
#pragma once

#include <cstdint>
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

// The id of an element a step has just made; the session numbers it before the call returns.
constexpr std::uint64_t kNewElementId = ~std::uint64_t{0};

// Keeps the elements with keep[e] (their samples, provenance and ids).
void keep_only(Provenance of, const std::vector<char>& keep);

// Element positions (centroids), z = 0 in 2D: the points of the grids over elements.
std::vector<Vec3> element_centroids(const std::vector<Element>& elements, int dimension);

}  // namespace tessera::det
