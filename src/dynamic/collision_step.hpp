// The physics sub-step of frame-by-frame synthesis (paper section 4.4, "extra solver
// steps", Figure 5): after each frame's advection, the particles are handed to the Bullet
// rigid-body step tessera already has (tessera/physics.hpp) as spheres at rest, without
// gravity, so the only thing the step does is push apart particles closer than the
// exemplar allows and push out of the domain's walls and obstacles those that went into
// them. This is what keeps particles from colliding where the output has a boundary the
// exemplar never showed (an obstacle in the flow), which pure data-driven synthesis does not
// see. Optional (DynamicOptions::physics); the paper applies it to that one case only.
#pragma once

#include <vector>

#include "tessera/animation.hpp"
#include "tessera/domain.hpp"
#include "tessera/physics.hpp"
#include "tessera/vec.hpp"

namespace tessera::dynamic {

class CollisionStep {
public:
    // The collision radius is half the exemplar's closest-pair distance (a low quantile of
    // its samples' nearest-neighbour distances over every frame, so one stray pair does not
    // set it): two output particles collide when they are closer than the exemplar's
    // particles ever come. With `periodic` (--wrap) the domain's outer boundary is no wall
    // (only its holes and a mesh's surface are) and pairs across the wrap seam collide too.
    CollisionStep(const Animation& exemplar, const Domain& domain, bool periodic);

    // Resolves collisions among `positions` (one single-sample element each) and with the
    // domain's walls; returns the number of particles it moved. Bullet's own step has a
    // fixed number of substeps, so this is bounded; particles it could not keep in the
    // domain's bounds stay where they were (PhysicsReport::lost).
    int apply(std::vector<Vec3>& positions);

    double radius() const { return radius_; }
    // Fraction of the nearest-neighbour distances below the collision distance (2 radii).
    static constexpr double closest_quantile = 0.02;

private:
    void add_particle(const Vec3& p, bool image);
    void add_images(const std::vector<Vec3>& positions);

    const Domain& domain_;
    int dimension_ = 2;
    double radius_ = 0.0;
    PhysicsOptions options_;
    Arrangement scratch_;  // one sphere per particle, rebuilt in place every frame
};

// Half the `quantile` of the nearest-neighbour distances of the exemplar's particles, pooled
// over its frames (exemplar_contact_distance). 0 when the exemplar has one particle.
double exemplar_collision_radius(const Animation& exemplar, double quantile);

}  // namespace tessera::dynamic
