// Empty space between elements: how far a ball centred at a point can grow inside the
// domain before it touches an element (its centre, or its disk's rim for elements with a
// radius). The largest such ball is a hole a viewer sees; the metrics report it
// (largest_empty_circle) and det's vacancy filling puts elements into the holes it finds.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "tessera/domain.hpp"
#include "tessera/vec.hpp"

namespace tessera::core {

// Obstacles (points with a rim radius) in a uniform grid that grows as they are added.
class ObstacleGrid {
public:
    ObstacleGrid(const Box& box, double cell, int dimension);
    // An obstacle at p with a rim radius and a tag (an element type, say).
    void add(const Vec3& p, double rim, int tag = 0);
    // min over obstacles of |c - p| - rim, searched only up to `cap` (returns cap beyond it).
    double clearance(const Vec3& c, double cap) const;
    // Per tag 0..tags-1: the distance from c to the nearest obstacle centre with that tag,
    // up to `cap` (cap when none is nearer); `out` is resized to tags.
    void nearest_by_tag(const Vec3& c, int tags, double cap, std::vector<double>& out) const;

private:
    void coords(const Vec3& p, int* c) const;
    Vec3 lo_;
    double cell_;
    int dim_;
    int dims_[3] = {1, 1, 1};
    double max_rim_ = 0.0;
    struct Obstacle {
        Vec3 p;
        double rim = 0.0;
        int tag = 0;
    };
    template <class Fn>
    void for_each_near(const Vec3& at, double reach, Fn&& fn) const;
    std::vector<std::vector<Obstacle>> cells_;
};

// The clearance of a ball centred at c: to the obstacles and to the domain's boundary
// (the ball must lie inside the domain), at most `cap` (the search reaches no further);
// <= 0 outside the domain.
inline double ball_clearance(const ObstacleGrid& grid, const Domain& domain, const Vec3& c, double cap) {
    const double wall = domain.distance_to_boundary(c);
    if (!(wall > 0.0)) return wall;
    return grid.clearance(c, std::min(wall, cap));
}

struct EmptyBall {
    double radius = 0.0;
    Vec3 center;
};

// The largest empty ball among the points (with rims) inside `domain`: a lattice of
// candidate centres `step` apart, then a pattern search from the best one (ties: lowest
// lattice index, so any thread count gives the same ball). Throws Error(input) when the
// lattice would exceed 2e8 points.
EmptyBall largest_empty_ball(const std::vector<Vec3>& points, const std::vector<double>& rims, const Domain& domain,
                             int dimension, double step, int threads);

// The points of a lattice of `step` (cell centres over the domain's bounds) inside the domain.
std::vector<Vec3> lattice_inside(const Domain& domain, int dimension, double step);

// The centre of the hole around lattice point p: a pattern search (steps from half the
// lattice step down to a 32nd of it) for the largest clearance(q); `depth` is set to it.
template <class Clearance>
Vec3 hole_centre(const Vec3& p, int dims, double step, const Clearance& clearance, double& depth) {
    Vec3 best = p;
    depth = clearance(p);
    for (double h = 0.5 * step; h > step / 32.0; h *= 0.5) {
        bool moved = true;
        for (int guard = 0; moved && guard < 16; ++guard) {
            moved = false;
            for (int k = 0; k < dims; ++k)
                for (double sign : {-1.0, 1.0}) {
                    Vec3 q = best;
                    q[k] += sign * h;
                    const double d = clearance(q);
                    if (d > depth) depth = d, best = q, moved = true;
                }
        }
    }
    return best;
}

}  // namespace tessera::core
