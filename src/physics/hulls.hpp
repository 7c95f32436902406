// Convex-hull collision shapes for element types that carry a mesh (geometry.hpp): the
// interleaved physics simulates them as the convex hull of the mesh, and the measure
// (interpenetration, support) must use the same shapes, or it would report overlaps
// the simulation cannot see. Private to the library.
//
// The mesh is in the element's local frame (origin at the samples' centroid), so an
// element's hull in world space is  centroid + scale * orientation.rotate(v)  for the
// mesh vertices v.
#pragma once

#include <vector>

#include "physics/shapes.hpp"
#include "tessera/exemplar.hpp"

namespace tessera::physics {

struct TypeHulls {
    std::vector<std::vector<Vec3>> points;  // per type: the mesh's vertices (empty: no mesh)
    std::vector<double> volume;             // per type: enclosed volume of the mesh at scale 1
    bool any = false;                       // some type has a mesh

    // Reads every type's mesh once. Throws Error(io) for an unreadable file and
    // Error(input) naming the type for a mesh with no triangles.
    explicit TypeHulls(const Exemplar& data);
    bool has(const Element& e) const { return !points[e.type].empty(); }
};

// The element's hull points in world space (see above).
std::vector<Vec3> world_hull(const TypeHulls& hulls, const Element& e, const Vec3& centroid);

// Widens `shape`'s bounding box and sets its lowest point source to cover its hull.
void cover_hull(ElementShape& shape, const std::vector<Vec3>& world_points);

struct HullContact {
    double gap = 0;   // signed distance between the shapes; negative = penetration depth
    Vec3 on_a, on_b;  // witness points
};

// Signed distance between two elements, each either a hull (world points, non-empty)
// or a chain of capsules of radius r through its samples (GJK / EPA, Bullet).
HullContact hull_contact(const std::vector<Vec3>& hull_a, const Sample* samples_a, int count_a, double radius_a,
                         const std::vector<Vec3>& hull_b, const Sample* samples_b, int count_b, double radius_b);

}  // namespace tessera::physics
