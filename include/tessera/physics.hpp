// tessera/physics.hpp — the interleaved physics solver of Discrete Element Textures
// (Ma, Wei and Tong 2011, section 5 "Interleaved physics solver", Figure 15): a few
// rigid-body sub-steps (Bullet) that push overlapping elements apart and let
// unsupported ones fall, run after each search/assign iteration; and the measure the
// paper's Figure 15 compares: interpenetrating pairs, their maximum depth, and
// floating elements.
//
// Collision shapes: a single-sample element is a sphere of the element radius; a
// multi-sample element is one rigid body made of capsules between consecutive
// samples, centred on the samples' centroid. The domain is a static collider. Every
// call builds its own Bullet world, so the functions hold no state, are thread-safe
// and give identical results for identical inputs. See docs/physics.md.
#pragma once

#include "tessera/domain.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/vec.hpp"

namespace tessera {

struct PhysicsOptions {
    int substeps = 5;                // fixed simulation steps per call (the paper runs 5 per iteration); 0..10000
    double time_step = 1.0 / 60.0;   // seconds per step; > 0
    Vec3 gravity{};                  // data units / s^2; zero = 9.81 m/s^2 along -y (2D) or -z (3D)
    bool no_gravity = false;         // true = no gravity at all: bodies at rest only push apart
                                     // where they overlap (the dynamic method's collision sub-step)
    bool periodic = false;           // the domain's bounding box wraps round: no walls on it nor on
                                     // a polygon's outer ring (holes and meshes stay walls)
    double units_per_metre = 1.0;    // data units in one metre: scales the default gravity; > 0
    double friction = 0.6;           // Coulomb friction of bodies and domain walls, >= 0
    double restitution = 0.0;        // bounciness, in [0, 1]
    double damping = 0.1;            // linear and angular velocity damping per second, in [0, 1]
    double overlap_correction = 0.6; // fraction of an overlap a step removes (Bullet's split-impulse erp2), (0, 1]
    int solver_iterations = 20;      // sequential-impulse iterations per step, 1..1000
    double tolerance = 0.05;         // contact tolerance of the returned report (see measure_physics)
};

struct PhysicsReport {
    int interpenetrating_pairs = 0;  // element pairs overlapping deeper than the tolerance
    double max_depth = 0.0;          // deepest overlap of any pair, data units (0 when none)
    int floating = 0;                // elements with nothing below them (neither domain nor element)
    int lost = 0;                    // measure: elements outside the domain; step: bodies that left
                                     // the domain (or diverged) and were put back where they started
    int elements = 0;                // elements measured
};

// The gravity a run uses: zero with no_gravity, else options.gravity, or 9.81 *
// units_per_metre along -y (2D) or -z (3D) when it is zero. Throws Error(option) for a non-finite gravity or
// units_per_metre <= 0.
Vec3 physics_gravity(const PhysicsOptions& options, int dimension);

// The collision radius of an element: its radius, or when 0, half the mean nearest-
// neighbour distance of the elements (single-sample) or 0.2 of it (multi-sample).
// `spacing` is mean_nearest_neighbor_distance(data); a floor of 1e-9 keeps it > 0.
double collision_radius(const Element& element, double spacing);

// Interpenetration and support of the element shapes of `data`, without moving them.
// - A pair interpenetrates when its overlap depth (r_a + r_b minus the distance between
//   the two shapes' axes) exceeds `tolerance` times the smaller radius.
// - An element floats when neither the domain (the point just past its lowest point
//   along gravity, within `tolerance` * its radius, is outside the domain) nor another
//   element touching it (gap <= tolerance * radius) at a point below its centroid
//   supports it. Only gravity's direction is used; zero = -y (2D) / -z (3D).
// - lost counts elements whose centroid is outside the domain or not finite.
// Throws Error(option) if tolerance is negative or not finite.
PhysicsReport measure_physics(const Exemplar& data, const Domain& domain, const Vec3& gravity,
                              double tolerance = 0.05);

// Runs options.substeps fixed steps of rigid-body simulation (every body starts at rest)
// on the elements of `data` inside `domain`, then writes back each element's samples
// (the rigid motion of its body about the samples' centroid), position and orientation
// (body rotation * previous orientation). Locked elements are static. 2D data stay in
// the plane (z = 0, rotation about z only). A body that leaves the domain's bounds or
// diverges is put back at its starting pose and counted in `lost`, so no element is
// ever lost. Returns measure_physics of the result (with options.tolerance).
// Throws Error(option) for invalid options, Error(input) for invalid data.
PhysicsReport step_physics(Arrangement& data, const Domain& domain, const PhysicsOptions& options = {});

}  // namespace tessera
