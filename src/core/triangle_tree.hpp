// core/triangle_tree.hpp — a bounding-box tree over the triangles of a mesh, for the
// exact inside tests of mesh and shell domains (domain_mesh.cpp): how many triangles a
// short segment crosses, and whether any triangle lies within a distance of a point.
// Written by hand because the Debian libraries that have one (CGAL's AABB tree, Embree)
// are large dependencies for these two queries; the tree is built once per domain and
// is immutable, so it may be queried from many threads.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "tessera/mesh.hpp"

namespace tessera::core {

// Squared distance from p to the triangle abc.
double triangle_distance_squared(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

class TriangleTree {
public:
    explicit TriangleTree(const TriangleMesh& mesh);

    // The number of triangles the segment a-b crosses (its interior or a; a hit at b
    // is not counted, so the counts of a-b and b-c add up to that of a-c).
    int segment_crossings(const Vec3& a, const Vec3& b) const;
    // Whether some point of some triangle is within distance r of p.
    bool any_within(const Vec3& p, double r) const;

private:
    struct Node {
        Vec3 lo, hi;
        int32_t first = 0, count = 0;  // leaf: triangles [first, first + count) of order_
        int32_t right = -1;            // inner node: left child is the next node
    };
    struct Triangle {
        Vec3 a, b, c;
    };
    int build(int first, int count);
    std::vector<Triangle> triangles_;  // in tree order
    std::vector<Node> nodes_;
};

}  // namespace tessera::core
