// brush/surface.hpp — the surface of a surface canvas (the paper's Figure 1b): a triangle
// mesh on which elements sit, strokes are drawn and the element field is tangent. It answers
// the closest surface point and the smooth normal there (area-weighted vertex normals
// interpolated across the triangle, as the mesh-vertex fields of tessera/field.hpp do), and
// holds the band within a thickness of the surface on both sides, in which growth runs
// (the shell under the surface, Domain::shell, is the canvas's recorded domain).
// Immutable once built: queries may run from any number of threads.
#pragma once

#include <string>
#include <vector>

#include "core/spatial_grid.hpp"
#include "tessera/domain.hpp"
#include "tessera/field.hpp"
#include "tessera/mesh.hpp"

namespace tessera::brush {

struct SurfacePoint {
    Vec3 p;              // the closest point of the surface
    Vec3 normal;         // unit smooth normal there (the mesh's winding: counter-clockwise = outward)
    double distance = 0;  // from the query point
};

class Surface {
public:
    // Error(domain) naming `name` for a mesh without triangles or a thickness that is not > 0.
    Surface(const TriangleMesh& mesh, double thickness, const std::string& name);

    SurfacePoint closest(const Vec3& p) const;
    const TriangleMesh& mesh() const { return mesh_; }
    double thickness() const { return thickness_; }
    // The points within `thickness` of the surface, on both sides: where growth runs and what
    // the search counts as the canvas (a sample on the surface is at the edge of the shell).
    const Domain& band() const { return band_; }

private:
    TriangleMesh mesh_;
    double thickness_ = 0.0;
    std::vector<Vec3> vertex_normals_;  // area-weighted, unit (zero where undefined)
    std::vector<Vec3> face_normals_;    // unit
    std::vector<Vec3> centroids_;       // of the triangles, indexed by a grid
    core::SpatialGrid grid_;
    double reach_ = 0.0;                // the largest distance from a centroid to its triangle's corners
    Domain band_;
};

// d with its component along `normal` removed, unit; a tangent of the frame of Eq. 7's
// fields (frame_from_direction(d, normal)) when d is (nearly) normal.
Vec3 tangent_direction(const Vec3& d, const Vec3& normal);

// `field` as a mesh-vertex field on the surface (OrientationField::mesh_vertices): each
// vertex takes the field's direction there, made tangent; its frames have z = the surface
// normal, so that growth lays a layered exemplar into the tangent plane, as synthesis in a
// shell does (docs/det.md, "Layered exemplars"). No field: +x made tangent.
OrientationField surface_field(const Surface& surface, const OrientationField& field);

}  // namespace tessera::brush
