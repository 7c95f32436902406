// tessera/field.hpp — local orientation fields (section 5 of the Discrete Element
// Textures paper, Eq. 7): at every point of the output a local frame o(p) in
// which the exemplar's pattern is laid down. Synthesis measures neighbourhoods in
// the local frame (p^ = o(s)^-1 (p(s') - p(s))), rotates predictions and copied
// patches by it, and records each element's orientation relative to it.
//
// A field gives a direction d(p); the frame maps the exemplar's +x axis onto d(p)
// (in 3D with the least twist about it, keeping the frame's z as close to +z as
// possible). Where d(p) is (numerically) zero — the centre of a vortex — the frame
// is the identity; `degenerate_points()` of a sample set reports how often.
//
// Fields are procedural (constant, radial, vortex, polyline, trefoil) or read from
// files: a direction per node of a regular 2D/3D grid (JSON), or per vertex of a
// mesh or point cloud (PLY, OBJ). docs/fields.md documents every kind, the --field
// syntax and the file formats. A field is immutable once built and cheap to copy
// (file data is shared); every query is a pure function of the point, so it can be
// evaluated from any number of threads with identical results.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "tessera/mesh.hpp"
#include "tessera/vec.hpp"

namespace tessera {

// A direction per node of a regular grid: node (i, j, k) sits at
// origin + (i spacing.x, j spacing.y, k spacing.z); `vectors` is indexed
// i + size[0] * (j + size[1] * k) (x fastest). In 2D, size[2] is 1 and z is ignored.
struct FieldGrid {
    int dimension = 2;
    Vec3 origin;
    Vec3 spacing{1, 1, 1};
    std::array<int, 3> size{2, 2, 1};
    std::vector<Vec3> vectors;
};

// Reads a grid field file ({"format": "tessera-field", ...}, docs/fields.md). Throws
// Error(io) if the file cannot be opened and Error(input) naming the file and the
// offending key, vector index or node for malformed content.
FieldGrid read_field_grid(const std::string& path);
FieldGrid parse_field_grid(const std::string& text, const std::string& source);

namespace field_detail {
struct GridData;
struct MeshData;
}  // namespace field_detail

class OrientationField {
public:
    enum class Kind { none, constant, radial, vortex, polyline, grid, mesh };

    // No field: the global frame everywhere (the default).
    OrientationField() = default;
    // The same direction everywhere. Throws Error(option) for a zero or non-finite direction.
    static OrientationField constant(const Vec3& direction);
    // Directions pointing away from `center` (in 3D, away from the axis through center along `axis`).
    static OrientationField radial(const Vec3& center, const Vec3& axis = {0, 0, 1});
    // Directions circling `center` counter-clockwise about `axis` (2D: about +z).
    static OrientationField vortex(const Vec3& center, const Vec3& axis = {0, 0, 1});
    // The tangent of the nearest segment of a polyline (at least 2 points): a flow
    // along a curve. Throws Error(option) for fewer than 2 points, zero-length
    // segments or non-finite points.
    static OrientationField polyline(const std::vector<Vec3>& points);
    // The trefoil knot (the paper's Figure 10j) as a closed polyline of `samples`
    // points: (sin t + 2 sin 2t, cos t - 2 cos 2t, -sin 3t) * scale + center.
    static OrientationField trefoil(const Vec3& center, double scale, int samples = 360);
    // A vector field given at the nodes of a regular grid: the direction at p is the
    // bilinear (2D) / trilinear (3D) interpolation of the node vectors (each normalised
    // first), normalised; outside the grid, p is clamped to its border. It is a signed
    // vector field: neighbours pointing opposite ways cancel to a degenerate point.
    // Throws Error(input) naming `source` for an invalid grid (size < 2 along an axis,
    // non-positive or non-finite spacing, wrong vector count, zero or non-finite vectors).
    static OrientationField grid(const FieldGrid& grid, const std::string& source = "grid field");
    static OrientationField grid_file(const std::string& path);  // read_field_grid + grid
    // A direction per vertex of a mesh (mesh.vertices[i] has directions[i]). With faces,
    // the direction at p is found at the closest point of the surface: the barycentric
    // blend of the triangle's vertex directions projected onto its plane, and the 3D
    // frame has z = the surface normal there (interpolated from area-weighted vertex
    // normals of the consistently oriented faces) and x = the direction, so elements lie
    // in the tangent plane. Without faces (a point cloud): inverse-distance weighting of
    // the 8 nearest vertices, frame as frame_from_direction. Throws Error(input) naming
    // `source` for a count mismatch, an empty mesh, zero or non-finite directions.
    static OrientationField mesh_vertices(const TriangleMesh& mesh, const std::vector<Vec3>& directions,
                                          const std::string& source = "mesh field");
    // read_vertex_directions + mesh_vertices: an ASCII PLY with vertex x y z vx vy vz
    // (faces optional) or an OBJ whose vn lines give the directions in v order.
    static OrientationField mesh_file(const std::string& path);
    // Parses "constant:dx,dy[,dz]", "radial:cx,cy[,cz]", "vortex:cx,cy[,cz]",
    // "polyline:x1,y1[,z1],x2,y2[,z2],...", (3D) "trefoil:cx,cy,cz,scale",
    // "grid:FILE.json" (the file's dimension must be `dimension`) or (3D)
    // "mesh:FILE.ply|FILE.obj" (CLI --field). `parameter` names the option in errors.
    static OrientationField parse(const std::string& text, int dimension, const std::string& parameter);

    Kind kind() const { return kind_; }
    bool active() const { return kind_ != Kind::none; }
    // Unit direction at p, or the zero vector where the field is degenerate.
    Vec3 direction(const Vec3& p) const;
    // Local frame at p: a rotation taking the exemplar's axes to the local axes.
    Quat frame(const Vec3& p, int dimension) const;
    // Dimension of the field's data (2 or 3 for grids, 3 for meshes; 0 for procedural fields).
    int data_dimension() const;
    // E.g. "vortex about (15,15,0)", "grid f.json (31 x 31 nodes)", "mesh s.ply (642 vertices, 1280 triangles)".
    std::string describe() const;

private:
    Kind kind_ = Kind::none;
    Vec3 vector_;  // constant: the direction; radial/vortex: the centre
    Vec3 axis_{0, 0, 1};
    std::shared_ptr<const std::vector<Vec3>> points_;  // polyline
    std::shared_ptr<const field_detail::GridData> grid_;
    std::shared_ptr<const field_detail::MeshData> mesh_;
};

// Rotation taking +x onto the unit vector d (2D: about z; 3D: least twist, +z kept up).
Quat frame_from_direction(const Vec3& d, int dimension);
// 3D rotation with z = the unit `normal` and x = d projected into the plane normal to it.
// Where d is (numerically) zero or parallel to the normal, x is the image of +x under the
// least rotation taking +z onto the normal. A zero normal gives frame_from_direction(d, 3).
Quat frame_from_direction(const Vec3& d, const Vec3& normal);

}  // namespace tessera
