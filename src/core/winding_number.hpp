// core/winding_number.hpp — generalized winding numbers of a triangle mesh at the
// centres of a regular grid (Jacobson et al. 2013), and unsigned distances near the
// surface; used to turn meshes into Domain::mesh / Domain::shell voxel grids.
#pragma once

#include <cstdint>
#include <vector>

#include "tessera/mesh.hpp"

namespace tessera::core {

struct CubeGrid {
    int n[3] = {1, 1, 1};
    Vec3 first;         // centre of cell (0, 0, 0)
    double cell = 1.0;  // cubic cells
    int64_t count() const { return int64_t(n[0]) * n[1] * n[2]; }
};

// The winding number at every cell centre. Three axis-aligned ray-crossing counts
// (exact for a closed mesh) are computed per cell; where they disagree (near cracks,
// holes or open parts) the exact generalized winding number, the sum of the
// triangles' solid angles / 4 pi, decides. `exact_cells` receives how many needed it.
std::vector<float> winding_numbers(const TriangleMesh& mesh, const CubeGrid& grid, int threads, int64_t* exact_cells);

// The generalized winding number at p: sum of the triangles' signed solid angles / 4 pi.
double generalized_winding_number(const TriangleMesh& mesh, const Vec3& p);

// Unsigned distance to the mesh surface for cells within `band` of it (+infinity elsewhere).
std::vector<float> surface_distance(const TriangleMesh& mesh, const CubeGrid& grid, double band, int threads);

}  // namespace tessera::core
