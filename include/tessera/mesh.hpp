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

// A mesh (or, without faces, a point cloud) with one direction per vertex: the input of
// a mesh-vertex orientation field (tessera/field.hpp).
struct VertexDirectionMesh {
    TriangleMesh mesh;
    std::vector<Vec3> directions;  // directions[i] belongs to mesh.vertices[i]
};

// Reads an ASCII PLY whose vertex element has x, y, z and the direction vx, vy, vz (faces
// optional), or an OBJ whose vn lines give the directions in the order of its v lines (as
// many vn as v lines; face normal references are ignored), chosen by extension. Errors as
// read_triangle_mesh; a missing direction property or a v / vn count mismatch is Error(input).
VertexDirectionMesh read_vertex_directions(const std::string& path);
VertexDirectionMesh parse_obj_vertex_directions(const std::string& text, const std::string& source);
VertexDirectionMesh parse_ply_vertex_directions(const std::string& text, const std::string& source);

}  // namespace tessera
