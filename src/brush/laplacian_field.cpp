// Laplacian interpolation of stroke directions on a grid (brush/laplacian_field.hpp).
#include "brush/laplacian_field.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>

#include "brush/strokes.hpp"
#include "brush/surface.hpp"
#include "tessera/error.hpp"

namespace tessera::brush {

namespace {

constexpr int kMaxNodesPerAxis = 256;

FieldGrid grid_over(const Domain& canvas, double cell) {
    const int dim = canvas.dimension();
    const Box b = canvas.bounds();
    FieldGrid g;
    g.dimension = dim;
    g.origin = b.lo;
    for (int a = 0; a < 3; ++a) {
        if (a == 2 && dim == 2) {
            g.size[2] = 1;
            g.spacing.z = 1.0;
            continue;
        }
        const double extent = b.size()[a];
        const int n = std::clamp(static_cast<int>(std::ceil(extent / cell)) + 1, 2, kMaxNodesPerAxis);
        g.size[a] = n;
        g.spacing[a] = std::max(extent, 1e-9) / (n - 1);
    }
    return g;
}

// Which nodes take part: all of them, or on a surface those within reach of it (every corner
// of a cell that a surface point lies in is within a cell diagonal of that point).
std::vector<char> active_nodes(const FieldGrid& g, const Surface* surface) {
    const int nx = g.size[0], ny = g.size[1], nz = g.size[2];
    std::vector<char> active(static_cast<size_t>(nx) * ny * nz, 1);
    if (!surface) return active;
    const double reach = norm(g.spacing) * 1.01;
    for (int k = 0, v = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i, ++v)
                active[v] = surface->closest(g.origin + Vec3(i * g.spacing.x, j * g.spacing.y, k * g.spacing.z)).distance <= reach;
    return active;
}

}  // namespace

OrientationField interpolate_strokes(const Domain& canvas, const std::vector<Stroke>& strokes, double cell,
                                     double sigma, const Surface* surface) {
    if (strokes.empty()) return surface ? surface_field(*surface, {}) : OrientationField{};
    FieldGrid g = grid_over(canvas, cell);
    const int nx = g.size[0], ny = g.size[1], nz = g.size[2];
    const int n = nx * ny * nz;
    auto index = [&](int i, int j, int k) { return i + nx * (j + ny * k); };
    const std::vector<char> active = active_nodes(g, surface);
    std::vector<Eigen::Triplet<double>> triplets;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 3);
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                const int v = index(i, j, k);
                if (!active[v]) {  // left out: its own unknown, zero (+x below)
                    triplets.emplace_back(v, v, 1.0);
                    continue;
                }
                const Vec3 p = g.origin + Vec3(i * g.spacing.x, j * g.spacing.y, k * g.spacing.z);
                const StrokePoint s = closest_stroke_point(strokes, p);
                // Eq. 5's falloff; a tiny floor keeps the system definite far from strokes.
                const double a = std::isfinite(s.distance) ? std::exp(-s.distance * s.distance / (sigma * sigma)) : 0.0;
                triplets.emplace_back(v, v, a + 1e-9);
                for (int c = 0; c < 3; ++c) rhs(v, c) = a * s.tangent[c];
                const int next[3][3] = {{i + 1, j, k}, {i, j + 1, k}, {i, j, k + 1}};
                for (const auto& m : next) {
                    if (m[0] >= nx || m[1] >= ny || m[2] >= nz) continue;
                    const int w = index(m[0], m[1], m[2]);
                    if (!active[w]) continue;
                    triplets.emplace_back(v, v, 1.0);
                    triplets.emplace_back(w, w, 1.0);
                    triplets.emplace_back(v, w, -1.0);
                    triplets.emplace_back(w, v, -1.0);
                }
            }
    Eigen::SparseMatrix<double> system(n, n);
    system.setFromTriplets(triplets.begin(), triplets.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system);
    if (solver.info() != Eigen::Success) throw Error(ErrorKind::internal, "the stroke field's system is singular");
    const Eigen::MatrixXd u = solver.solve(rhs);
    g.vectors.resize(static_cast<size_t>(n));
    for (int v = 0; v < n; ++v) {
        Vec3 d{u(v, 0), u(v, 1), canvas.dimension() == 3 ? u(v, 2) : 0.0};
        const double len = norm(d);
        // A node where opposite strokes cancel exactly keeps +x (a grid needs non-zero vectors).
        g.vectors[static_cast<size_t>(v)] = len > 1e-12 ? d / len : Vec3{1, 0, 0};
    }
    const OrientationField field = OrientationField::grid(g, "stroke field");
    return surface ? surface_field(*surface, field) : field;
}

}  // namespace tessera::brush
