// tessera/mesh.hpp — a plain indexed triangle mesh and its OBJ / ASCII PLY readers.
// Shaped 3D domains (Domain::mesh, Domain::shell) are built from one; later,
// element geometry can share the same readers. Errors name the file and line.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "tessera/vec.hpp"

namespace tessera {

struct TriangleMesh {
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> triangles;  // indices into vertices, counter-clockwise = outward
};

// Reads a Wavefront OBJ (v and f lines; f accepts v, v/vt, v//vn, v/vt/vn and negative
// indices; polygons are fan-triangulated; other lines are ignored) or an ASCII PLY
// (element vertex with x, y, z; element face with a vertex_indices / vertex_index list),
// chosen by extension. Throws Error(io) if the file cannot be opened and Error(input)
// naming "file:line" for malformed content (bad numbers, indices out of range, binary PLY).
TriangleMesh read_triangle_mesh(const std::string& path);
TriangleMesh parse_obj(const std::string& text, const std::string& source);
TriangleMesh parse_ply_mesh(const std::string& text, const std::string& source);

}  // namespace tessera
