// geometry/normals.cpp — smooth vertex normals for the glTF writer (viewers shade
// with them; OBJ and PLY leave them to the reader).
#include "geometry/geometry_internal.hpp"

namespace tessera::geometry {

std::vector<Vec3> vertex_normals(const TriangleMesh& mesh) {
    std::vector<Vec3> normals(mesh.vertices.size());
    for (const auto& t : mesh.triangles) {
        // The cross product's length is twice the area: larger triangles weigh more.
        const Vec3 n = cross(mesh.vertices[t[1]] - mesh.vertices[t[0]], mesh.vertices[t[2]] - mesh.vertices[t[0]]);
        for (int k = 0; k < 3; ++k) normals[t[k]] += n;
    }
    for (Vec3& n : normals) {
        const double length = norm(n);
        n = length > 0.0 && std::isfinite(length) ? n / length : Vec3{0, 0, 1};
    }
    return normals;
}

}  // namespace tessera::geometry
