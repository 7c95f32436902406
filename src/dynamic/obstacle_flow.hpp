// The global flow round the domain's obstacles (paper section 4.4, "boundary conditions",
// Figures 5 and 8): a uniform flow far away that goes round the holes of the output domain
// instead of running into them. Without it a particle carried against an obstacle is only
// put back at the nearest point inside, so it piles up in front and leaves an empty wake
// behind; with it the streamlines part before the obstacle and close behind it.
//
// The flow is the potential flow v = grad(phi) with Laplace(phi) = 0 inside the domain,
// phi = U . x on the domain's outer boundary (the flow enters and leaves there freely) and
// d(phi)/dn = 0 on the holes (walls), solved once on a grid over the domain's bounds. phi is
// linear in the far flow U, so one solve per axis gives the flow for every U: a turning flow
// (flow_turn) costs nothing more.
#pragma once

#include <array>
#include <vector>

#include "tessera/domain.hpp"
#include "tessera/vec.hpp"

namespace tessera::dynamic {

class ObstacleFlow {
public:
    // Grids the bounds of `domain` (nodes_2d nodes along its longest side in 2D, nodes_3d in
    // 3D) and, when some nodes fall in holes (outside the domain yet not connected to the
    // outside of its bounds), solves the potential per axis (Eigen's sparse Cholesky).
    // Without holes the flow is uniform and nothing is solved; nor when `needed` is false
    // (no flow at all).
    ObstacleFlow(const Domain& domain, int threads, bool needed = true);

    // How far a particle at p moves over one frame when the far flow moves it by `step`:
    // the midpoint rule along the field (so it bends round an obstacle within one frame).
    Vec3 displacement(const Vec3& p, const Vec3& step) const;

    // True when the domain has no obstacle the grid resolves: displacement(p, step) = step.
    bool uniform() const { return uniform_; }

    static constexpr int nodes_2d = 128;
    static constexpr int nodes_3d = 40;

private:
    enum class Node : unsigned char { inside, open, wall };  // open = outside, reached from the bounds' outside

    Vec3 velocity(const Vec3& p, const Vec3& far) const;  // far flow U -> v(p)
    void classify(const Domain& domain, int threads);
    void solve();
    int index(int i, int j, int k) const { return (k * n_[1] + j) * n_[0] + i; }
    Vec3 position(int i, int j, int k) const { return lo_ + Vec3{i * h_, j * h_, k * h_}; }

    int dimension_ = 2;
    bool uniform_ = true;
    Vec3 lo_;
    double h_ = 1.0;
    std::array<int, 3> n_{1, 1, 1};
    std::vector<Node> nodes_;
    std::array<std::vector<Vec3>, 3> gradient_;  // grad(phi_k) at every node, k = axis of U
};

}  // namespace tessera::dynamic
