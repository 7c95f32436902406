// The data behind file-based orientation fields (tessera/field.hpp): a grid of node
// vectors (field_grid.cpp) and a mesh or point cloud with vertex directions and its
// acceleration structure (field_mesh.cpp). Both are built once, held through
// std::shared_ptr<const ...> and queried read-only, so queries are thread-safe.
#pragma once

#include <string>

#include "tessera/vec.hpp"

namespace tessera::field_detail {

struct GridData;
struct MeshData;

// Below this norm a blended direction counts as zero (a degenerate point).
constexpr double degenerate_norm = 1e-12;

Vec3 grid_direction(const GridData& grid, const Vec3& p);
int grid_dimension(const GridData& grid);
std::string grid_describe(const GridData& grid);

Vec3 mesh_direction(const MeshData& mesh, const Vec3& p);
Quat mesh_frame(const MeshData& mesh, const Vec3& p, int dimension);
std::string mesh_describe(const MeshData& mesh);

}  // namespace tessera::field_detail
