// Smooth per-vertex normals of an element mesh for the mesh pictures.
#pragma once

#include <vector>

#include "tessera/mesh.hpp"
#include "tessera/vec.hpp"

namespace tessera::render {

// Area-weighted average of the normals of the faces around each vertex (not unit
// length; zero for a vertex of no face with area). Mesh files do not always wind
// their faces consistently, and a face counted with the wrong sign would cancel its
// neighbours' normals, so the faces of each edge-connected patch are first oriented
// like the patch's first face (flipping across shared edges traversed the same way).
// Which side ends up outward is left open: the pictures light both sides.
// Triangles with an index out of range are ignored.
std::vector<Vec3> vertex_normals(const TriangleMesh& mesh);

}  // namespace tessera::render
