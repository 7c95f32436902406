// dynamic/obstacle_flow.cpp — the potential flow round the domain's holes (obstacle_flow.hpp).
#include "dynamic/obstacle_flow.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>

#include "core/parallel.hpp"
#include "tessera/error.hpp"

namespace tessera::dynamic {

namespace {

// The face neighbours of a node: 4 in 2D, 6 in 3D.
constexpr std::array<std::array<int, 3>, 6> steps{{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};

}  // namespace

ObstacleFlow::ObstacleFlow(const Domain& domain, int threads, bool needed) : dimension_(domain.dimension()) {
    if (!needed) return;
    const Box& box = domain.bounds();
    const Vec3 size = box.size();
    const double longest = std::max({size.x, size.y, dimension_ == 3 ? size.z : 0.0});
    h_ = longest / ((dimension_ == 3 ? nodes_3d : nodes_2d) - 1);
    // One node of padding on every side: those lie outside the domain, so the flood fill of
    // the open outside starts from them.
    lo_ = box.lo - Vec3{h_, h_, dimension_ == 3 ? h_ : 0.0};
    for (int a = 0; a < dimension_; ++a) n_[a] = static_cast<int>(std::ceil(size[a] / h_)) + 3;
    classify(domain, threads);
    if (!uniform_) solve();
}

// Inside nodes, then the outside reached from the padding (open); the rest of the outside
// is enclosed by the domain: its holes (walls).
void ObstacleFlow::classify(const Domain& domain, int threads) {
    const int count = n_[0] * n_[1] * n_[2];
    std::vector<unsigned char> in(count, 0);
    core::parallel_for(count, threads, [&](int begin, int end, int) {
        for (int v = begin; v < end; ++v) {
            const int i = v % n_[0], j = (v / n_[0]) % n_[1], k = v / (n_[0] * n_[1]);
            in[v] = domain.inside(position(i, j, k)) ? 1 : 0;
        }
    }, 256);
    nodes_.assign(count, Node::wall);
    std::vector<int> stack;
    const auto visit = [&](int i, int j, int k) {
        const int v = index(i, j, k);
        if (in[v] || nodes_[v] != Node::wall) return;
        nodes_[v] = Node::open;
        stack.push_back(v);
    };
    visit(0, 0, 0);  // a padding corner: outside every domain
    while (!stack.empty()) {  // bounded: each node enters the stack at most once
        const int v = stack.back();
        stack.pop_back();
        const int i = v % n_[0], j = (v / n_[0]) % n_[1], k = v / (n_[0] * n_[1]);
        for (int s = 0; s < 2 * dimension_; ++s) {
            const int a = i + steps[s][0], b = j + steps[s][1], c = k + steps[s][2];
            if (a >= 0 && b >= 0 && c >= 0 && a < n_[0] && b < n_[1] && c < n_[2]) visit(a, b, c);
        }
    }
    uniform_ = true;
    for (int v = 0; v < count; ++v) {
        if (in[v]) nodes_[v] = Node::inside;
        else if (nodes_[v] == Node::wall) uniform_ = false;
    }
}

// Laplace(phi_k) = 0 on the inside nodes (the 5- or 7-point stencil), phi_k = x_k on open
// neighbours (Dirichlet), walls left out of the stencil (zero normal flux: Neumann). The
// matrix is the same for every axis k; only the right-hand side changes.
void ObstacleFlow::solve() {
    const int count = static_cast<int>(nodes_.size());
    std::vector<int> unknown(count, -1);
    int unknowns = 0;
    for (int v = 0; v < count; ++v)
        if (nodes_[v] == Node::inside) unknown[v] = unknowns++;
    std::vector<Eigen::Triplet<double>> triplets;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(unknowns, dimension_);
    for (int v = 0; v < count; ++v) {
        if (unknown[v] < 0) continue;
        const int i = v % n_[0], j = (v / n_[0]) % n_[1], k = v / (n_[0] * n_[1]);
        // A tiny diagonal keeps a pocket cut off from every opening solvable (its flow is 0).
        double diagonal = 1e-9;
        for (int s = 0; s < 2 * dimension_; ++s) {
            const int a = i + steps[s][0], b = j + steps[s][1], c = k + steps[s][2];
            const int w = index(a, b, c);  // inside nodes never touch the grid's edge (padding)
            if (nodes_[w] == Node::wall) continue;
            diagonal += 1.0;
            if (nodes_[w] == Node::inside) triplets.emplace_back(unknown[v], unknown[w], -1.0);
            else
                for (int axis = 0; axis < dimension_; ++axis) rhs(unknown[v], axis) += position(a, b, c)[axis] - lo_[axis];
        }
        triplets.emplace_back(unknown[v], unknown[v], diagonal);
    }
    Eigen::SparseMatrix<double> matrix(unknowns, unknowns);
    matrix.setFromTriplets(triplets.begin(), triplets.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> cholesky(matrix);
    if (cholesky.info() != Eigen::Success)
        throw Error(ErrorKind::domain, "the flow round the domain's obstacles could not be solved");
    const Eigen::MatrixXd phi = cholesky.solve(rhs);

    // grad(phi_k) by central differences; a wall neighbour mirrors the node (d(phi)/dn = 0).
    for (int axis = 0; axis < dimension_; ++axis) {
        std::vector<Vec3>& g = gradient_[axis];
        g.assign(count, Vec3{});
        const auto value = [&](int w, int v) {
            if (nodes_[w] == Node::inside) return phi(unknown[w], axis);
            if (nodes_[w] == Node::open) {
                const int a = w % n_[0], b = (w / n_[0]) % n_[1], c = w / (n_[0] * n_[1]);
                return position(a, b, c)[axis] - lo_[axis];
            }
            return phi(unknown[v], axis);
        };
        for (int v = 0; v < count; ++v) {
            if (nodes_[v] == Node::open) g[v][axis] = 1.0;  // the far flow itself
            if (nodes_[v] != Node::inside) continue;
            const int i = v % n_[0], j = (v / n_[0]) % n_[1], k = v / (n_[0] * n_[1]);
            for (int d = 0; d < dimension_; ++d) {
                const int plus = index(i + steps[2 * d][0], j + steps[2 * d][1], k + steps[2 * d][2]);
                const int minus = index(i + steps[2 * d + 1][0], j + steps[2 * d + 1][1], k + steps[2 * d + 1][2]);
                g[v][d] = (value(plus, v) - value(minus, v)) / (2.0 * h_);
            }
        }
    }
}

// Multilinear interpolation of sum_k U_k grad(phi_k) over the cell holding p, wall nodes left
// out (their weight goes to the other corners): the flow next to an obstacle is the flow of
// the nodes on the fluid side.
Vec3 ObstacleFlow::velocity(const Vec3& p, const Vec3& far) const {
    int cell[3] = {0, 0, 0};
    double t[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < dimension_; ++a) {
        const double x = std::clamp((p[a] - lo_[a]) / h_, 0.0, n_[a] - 1.000001);
        cell[a] = static_cast<int>(x);
        t[a] = x - cell[a];
    }
    Vec3 v;
    double total = 0.0;
    for (int corner = 0; corner < (1 << dimension_); ++corner) {
        int at[3] = {cell[0], cell[1], cell[2]};
        double weight = 1.0;
        for (int a = 0; a < dimension_; ++a) {
            const int up = (corner >> a) & 1;
            at[a] += up;
            weight *= up ? t[a] : 1.0 - t[a];
        }
        const int node = index(at[0], at[1], at[2]);
        if (nodes_[node] == Node::wall || weight == 0.0) continue;
        for (int k = 0; k < dimension_; ++k) v += gradient_[k][node] * (far[k] * weight);
        total += weight;
    }
    return total > 0.0 ? v / total : far;
}

Vec3 ObstacleFlow::displacement(const Vec3& p, const Vec3& step) const {
    if (uniform_) return step;
    // The midpoint rule: the velocity half a step along, so a particle meeting the obstacle's
    // front already turns within this frame.
    const Vec3 half = velocity(p, step) * 0.5;
    return velocity(p + half, step);
}

}  // namespace tessera::dynamic
