// brush/positions.hpp — the assignment step of the brush solver: the positions of the
// movable samples that best meet, in the least-squares sense, the distribution term's pairs
// (Eq. 1, the matches of the search), the conflict check (Eq. 3) and the graph similarity
// (Eq. 4), for the current orientations. Rigid elements are then put back to their exact
// shape, and elements whose centre left the canvas are moved back in. Returns true when the
// solve stopped at its iteration bound.
#pragma once

#include <vector>

#include "brush/distribution.hpp"

namespace tessera::brush {

bool assign_positions(BrushCanvas::Impl& state, const std::vector<char>& movable,
                      const std::vector<SampleMatch>& matches);

// Element poses from their samples: position = centroid, orientation = o(first sample)'s
// frame times the element's own rotation in it.
void update_element_poses(BrushCanvas::Impl& state, int first_element = 0);

// Conflicting pairs (Eq. 3): samples of different elements closer than the sum of their
// scaled weights; calls fn(a, b, summed_weight, distance) once per unordered pair.
template <class Fn>
void for_each_conflict(const BrushCanvas::Impl& state, const OutputNeighbours& nb, Fn&& fn);

}  // namespace tessera::brush

#include "brush/conflicts_impl.hpp"
