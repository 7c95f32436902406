// The topological constraint of threads and sheets during assignment: their samples stay
// at their rest distances along the grid (structural edges, and a sheet's diagonals so that
// its quads keep their shape and do not fold over). Least-squares assignment alone lets a
// thread stretch where the predictions of its neighbourhoods disagree; thread and sheet
// materials barely stretch, so after each assignment the edges are projected back to their
// rest lengths (position-based dynamics, Mueller et al. 2007).
#pragma once

#include <vector>

#include "dynamic/topology_grid.hpp"

namespace tessera::dynamic {

struct Edge {
    int a = 0, b = 0;
    double rest = 0.0;
};

// The edges of every element (grouped by element), their rest lengths the distances at
// `positions` (one frame of sample positions) times `stretch[type of the element]`.
std::vector<std::vector<Edge>> element_edges(const TopologyGrid& grid, const std::vector<int>& element_type,
                                             const Vec3* positions, const std::vector<double>& stretch);

struct LengthReport {
    int bound_hits = 0;         // element-frames whose projection stopped at max_sweeps
    double worst_strain = 0.0;  // largest |length / rest - 1| left
};

// Projects the edges of every element at every frame (positions frame-major, `samples`
// per frame) until no edge is more than `tolerance` off its rest length, at most
// `max_sweeps` sweeps (alternating direction, so that neither end is favoured).
LengthReport keep_lengths(std::vector<Vec3>& positions, int frames, int samples,
                          const std::vector<std::vector<Edge>>& edges, double tolerance, int max_sweeps, int threads);

}  // namespace tessera::dynamic
