// Sheets kept from passing through one another (and anything through a sheet) in an
// all-frame synthesis on a coarse motion. The contacts of element_contacts.hpp hold samples
// apart, but a sheet is more than its samples: two sheets stacked closer than their flutter
// crossed between their samples (stacked 0.02 apart: 13 of 40 frames) while every pair of
// samples kept its distance. Here every sample stays on the side of each nearby sheet triangle
// that the coarse motion puts it on, at least half its coarse height above it (at most half
// the contact distance), the sample and the triangle's corners each moving half the shortfall
// along the triangle's normal (the corners by their barycentric weights), as cloth solvers
// keep point-triangle proximity. Where the coarse motion itself takes a sample through a
// sheet, the side follows it.
#pragma once

#include <array>
#include <vector>

#include "dynamic/element_contacts.hpp"
#include "dynamic/topology_grid.hpp"

namespace tessera::dynamic {

// The triangles of every sheet of `grid`: two per grid quad, corners as sample indices.
std::vector<std::array<int, 3>> sheet_triangles(const TopologyGrid& grid);

// Pushes samples and triangles apart where a sample is on the wrong side of a triangle of
// another element, or nearer it than 0.5 x min(distance, its coarse height); Jacobi sweeps
// per frame (frames in parallel: the same result for any thread count) until no shortfall
// exceeds `tolerance` x distance, at most `max_sweeps`. Positions frame-major, as keep_apart.
ContactReport keep_sides(std::vector<Vec3>& positions, const std::vector<Vec3>& coarse,
                         const std::vector<std::array<int, 3>>& triangles, const std::vector<int>& element_of,
                         int frames, int samples, double distance, double tolerance, int max_sweeps, int threads);

}  // namespace tessera::dynamic
