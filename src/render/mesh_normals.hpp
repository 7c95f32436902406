// Per-corner normals of an element mesh for the mesh pictures: smooth across gentle
// bends, split at sharp edges (a crease angle), so spheres and tubes look round and
// boxes keep flat faces with crisp edges.
#pragma once

#include <vector>

#include "tessera/mesh.hpp"
#include "tessera/vec.hpp"

namespace tessera::render {

// Faces whose normals differ by more than this are not averaged together. 40 degrees
// keeps the default shapes smooth (a straight 10-sided tube turns 36 degrees from side
// to side; the faces around a vertex of an icosphere subdivided twice, the default,
// differ by at most 21 degrees) while the 90 degree edges of boxes, and most edges
// meant to be sharp, split.
inline constexpr double crease_angle_degrees = 40.0;

// normals[3 * t + k] is the normal at corner k of triangle t: the area-weighted average
// of the normals of the faces around that corner's vertex whose normal lies within
// `crease_degrees` of triangle t's own (t included), unit length. Zero for the corners
// of a triangle with no area, an index out of range or non-finite vertices.
//
// Mesh files do not always wind their faces consistently, and a face counted with the
// wrong sign would cancel its neighbours' normals (or, here, never be within the crease
// angle of them), so the faces of each edge-connected patch are first oriented like
// the patch's first face (flipping across shared edges traversed the same way). All
// three corner normals of a triangle lie on the side of its oriented face normal.
// Which side ends up outward is left open: the pictures light both sides.
std::vector<Vec3> corner_normals(const TriangleMesh& mesh, double crease_degrees = crease_angle_degrees);

}  // namespace tessera::render
