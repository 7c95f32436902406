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

}  // namespace tessera::core
