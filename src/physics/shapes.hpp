// Element collision shapes shared by the physics measure and the Bullet step:
// each element is a chain of capsules along its samples (a sphere when it has one
// sample), of one radius (physics.hpp, collision_radius). Private to the library.
#pragma once

#include <vector>

#include "tessera/exemplar.hpp"
#include "tessera/vec.hpp"

namespace tessera::physics {

struct ElementShape {
    int first = 0;      // samples [first, first + count) of the data
    int count = 1;
    double radius = 0;  // capsule / sphere radius, data units (> 0)
    Vec3 centroid;      // mean of the samples
    Vec3 lo, hi;        // bounding box of the shape (samples +- radius)
};

// One shape per element, in element order.
std::vector<ElementShape> element_shapes(const Exemplar& data);

// Closest points between segments [p0, p1] and [q0, q1] (either may be a point).
// Returns the squared distance and writes the two closest points.
double closest_points_segments(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1, Vec3& on_p,
                               Vec3& on_q);

// The unit direction of `gravity`, or -y (2D) / -z (3D) when it is (nearly) zero.
Vec3 gravity_direction(const Vec3& gravity, int dimension);

}  // namespace tessera::physics
