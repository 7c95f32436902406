// Threads kept from passing through one another in 3D, in an all-frame synthesis on a coarse
// motion: the 1D counterpart of sheet_sides.hpp. Two segments of different threads that the
// coarse motion keeps apart could cross between their samples while every pair of samples
// kept its contact distance (two threads crossing 0.02 apart: the wiggles took one through
// the other). Every pair of nearby segments keeps the side of each other that the coarse
// motion gives them along their common normal, at least half their coarse separation (at most
// half the contact distance), each segment's closest point moving half the shortfall (its
// ends by their weights), as rope and hair solvers keep edge-edge proximity.
#pragma once

#include <array>
#include <vector>

#include "dynamic/element_contacts.hpp"
#include "dynamic/topology_grid.hpp"

namespace tessera::dynamic {

// The segments of every thread of `grid`: consecutive samples.
std::vector<std::array<int, 2>> thread_segments(const TopologyGrid& grid);

// Pushes apart the nearby segments of different threads that are on the wrong side of each
// other, or nearer than 0.5 x min(distance, their coarse separation); Jacobi sweeps per frame
// (frames in parallel: the same result for any thread count), at most `max_sweeps`, until no
// shortfall exceeds `tolerance` x distance. Positions frame-major, as keep_apart.
ContactReport keep_thread_sides(std::vector<Vec3>& positions, const std::vector<Vec3>& coarse,
                                const std::vector<std::array<int, 2>>& segments, const std::vector<int>& element_of,
                                int frames, int samples, double distance, double tolerance, int max_sweeps,
                                int threads);

}  // namespace tessera::dynamic
