// core/winding_number.cpp — winding numbers and near-surface distances on a grid.
//
// Evaluating the generalized winding number (sum of solid angles) at all 128^3 cell
// centres would cost 2M x triangles; instead, rays along x, y and z through every
// row of cells count signed crossings (a triangle's contribution is -sign of its
// normal along the ray), which is the exact winding number for a closed mesh at
// O(rows x triangles per row). A crack makes one axis' rays through it miscount,
// but a cell is reached through the crack by at most one of the three axes, so the
// three counts disagree exactly where it matters; there the exact solid-angle sum
// decides. Ray positions are offset by an irrational fraction of a cell so that rays
// do not pass exactly through the edges and vertices of meshes with round coordinates.
#include "core/winding_number.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/parallel.hpp"

namespace tessera::core {
namespace {

// Ray-crossing winding counts along `axis` for every cell.
void ray_counts(const TriangleMesh& mesh, const CubeGrid& g, int axis, int threads, std::vector<int8_t>& out) {
    const int a = axis, b = (axis + 1) % 3, c = (axis + 2) % 3;
    const double eps_b = g.cell * 1e-6 * std::numbers::sqrt2, eps_c = g.cell * 1e-6 * std::numbers::sqrt3;
    auto range = [&](double lo, double hi, int k, double eps, int& i0, int& i1) {
        i0 = std::max(0, static_cast<int>(std::ceil((lo - g.first[k] - eps) / g.cell)));
        i1 = std::min(g.n[k] - 1, static_cast<int>(std::floor((hi - g.first[k] - eps) / g.cell)));
    };
    std::vector<std::vector<int>> buckets(g.n[c]);
    for (int t = 0; t < int(mesh.triangles.size()); ++t) {
        const auto& tri = mesh.triangles[t];
        double lo = INFINITY, hi = -INFINITY;
        for (int v : tri) lo = std::min(lo, mesh.vertices[v][c]), hi = std::max(hi, mesh.vertices[v][c]);
        int k0, k1;
        range(lo, hi, c, eps_c, k0, k1);
        for (int k = k0; k <= k1; ++k) buckets[k].push_back(t);
    }
    const int64_t stride[3] = {1, g.n[0], int64_t(g.n[0]) * g.n[1]};
    parallel_for(g.n[c], threads, [&](int begin, int end, int) {
        std::vector<std::vector<std::pair<double, int>>> rows(g.n[b]);
        for (int kc = begin; kc < end; ++kc) {
            for (auto& r : rows) r.clear();
            const double pc = g.first[c] + kc * g.cell + eps_c;
            for (int t : buckets[kc]) {
                const Vec3& A = mesh.vertices[mesh.triangles[t][0]];
                const Vec3& B = mesh.vertices[mesh.triangles[t][1]];
                const Vec3& C = mesh.vertices[mesh.triangles[t][2]];
                // Projected signed area = the normal's component along the ray.
                const double area = (B[b] - A[b]) * (C[c] - A[c]) - (B[c] - A[c]) * (C[b] - A[b]);
                if (area == 0.0) continue;
                int j0, j1;
                range(std::min({A[b], B[b], C[b]}), std::max({A[b], B[b], C[b]}), b, eps_b, j0, j1);
                for (int jb = j0; jb <= j1; ++jb) {
                    const double pb = g.first[b] + jb * g.cell + eps_b;
                    auto edge = [&](const Vec3& P, const Vec3& Q) { return (Q[b] - P[b]) * (pc - P[c]) - (Q[c] - P[c]) * (pb - P[b]); };
                    const double wa = edge(B, C), wb = edge(C, A), wc = edge(A, B);
                    if (!((wa >= 0 && wb >= 0 && wc >= 0) || (wa <= 0 && wb <= 0 && wc <= 0))) continue;
                    const double x = (wa * A[a] + wb * B[a] + wc * C[a]) / area;
                    rows[jb].push_back({x, area > 0.0 ? -1 : 1});
                }
            }
            for (int jb = 0; jb < g.n[b]; ++jb) {
                auto& r = rows[jb];
                std::sort(r.begin(), r.end());
                int w = 0;
                size_t next = 0;
                const int64_t base = int64_t(jb) * stride[b] + int64_t(kc) * stride[c];
                for (int ia = 0; ia < g.n[a]; ++ia) {
                    const double x = g.first[a] + ia * g.cell;
                    while (next < r.size() && r[next].first < x) w += r[next++].second;
                    out[base + ia * stride[a]] = static_cast<int8_t>(std::clamp(w, -127, 127));
                }
            }
        }
    });
}

// Generalized winding number: sum of signed solid angles / 4 pi (Van Oosterom and Strackee).
}  // namespace

double generalized_winding_number(const TriangleMesh& mesh, const Vec3& p) {
    double sum = 0.0;
    for (const auto& tri : mesh.triangles) {
        const Vec3 a = mesh.vertices[tri[0]] - p, b = mesh.vertices[tri[1]] - p, c = mesh.vertices[tri[2]] - p;
        const double la = norm(a), lb = norm(b), lc = norm(c);
        const double num = dot(a, cross(b, c));
        const double den = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
        sum += 2.0 * std::atan2(num, den);
    }
    return sum / (4.0 * std::numbers::pi);
}

namespace {

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection 5.1.5).
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const Vec3 bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
    const Vec3 cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double denom = 1.0 / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

}  // namespace

std::vector<float> winding_numbers(const TriangleMesh& mesh, const CubeGrid& grid, int threads, int64_t* exact_cells) {
    const int64_t total = grid.count();
    std::vector<int8_t> counts[3];
    for (int axis = 0; axis < 3; ++axis) {
        counts[axis].assign(total, 0);
        ray_counts(mesh, grid, axis, threads, counts[axis]);
    }
    std::vector<float> w(total);
    std::vector<int64_t> disputed;
    for (int64_t v = 0; v < total; ++v) {
        w[v] = counts[0][v];
        if (counts[0][v] != counts[1][v] || counts[0][v] != counts[2][v]) disputed.push_back(v);
    }
    parallel_for(static_cast<int>(disputed.size()), threads, [&](int begin, int end, int) {
        for (int e = begin; e < end; ++e) {
            const int64_t v = disputed[e];
            const int i = static_cast<int>(v % grid.n[0]), j = static_cast<int>(v / grid.n[0] % grid.n[1]);
            const int k = static_cast<int>(v / (int64_t(grid.n[0]) * grid.n[1]));
            const Vec3 p = grid.first + Vec3(i, j, k) * grid.cell;
            w[v] = static_cast<float>(generalized_winding_number(mesh, p));
        }
    });
    if (exact_cells) *exact_cells = static_cast<int64_t>(disputed.size());
    return w;
}

std::vector<float> surface_distance(const TriangleMesh& mesh, const CubeGrid& g, double band, int threads) {
    std::vector<float> dist(g.count(), std::numeric_limits<float>::infinity());
    // Bucket triangles by the z-slabs their band-expanded bounds reach, so that each
    // slab is updated by one thread only.
    std::vector<std::vector<int>> buckets(g.n[2]);
    auto cells = [&](double lo, double hi, int k, int& i0, int& i1) {
        i0 = std::max(0, static_cast<int>(std::ceil((lo - band - g.first[k]) / g.cell)));
        i1 = std::min(g.n[k] - 1, static_cast<int>(std::floor((hi + band - g.first[k]) / g.cell)));
    };
    auto bounds = [&](int t, int k, double& lo, double& hi) {
        lo = INFINITY, hi = -INFINITY;
        for (int v : mesh.triangles[t]) lo = std::min(lo, mesh.vertices[v][k]), hi = std::max(hi, mesh.vertices[v][k]);
    };
    for (int t = 0; t < int(mesh.triangles.size()); ++t) {
        double lo, hi;
        int k0, k1;
        bounds(t, 2, lo, hi);
        cells(lo, hi, 2, k0, k1);
        for (int k = k0; k <= k1; ++k) buckets[k].push_back(t);
    }
    parallel_for(g.n[2], threads, [&](int begin, int end, int) {
        for (int k = begin; k < end; ++k)
            for (int t : buckets[k]) {
                const auto& tri = mesh.triangles[t];
                int r[2][2];
                for (int axis = 0; axis < 2; ++axis) {
                    double lo, hi;
                    bounds(t, axis, lo, hi);
                    cells(lo, hi, axis, r[axis][0], r[axis][1]);
                }
                for (int j = r[1][0]; j <= r[1][1]; ++j)
                    for (int i = r[0][0]; i <= r[0][1]; ++i) {
                        const Vec3 p = g.first + Vec3(i, j, k) * g.cell;
                        const Vec3 q = closest_on_triangle(p, mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]);
                        float& d = dist[i + int64_t(g.n[0]) * (j + int64_t(g.n[1]) * k)];
                        d = std::min(d, static_cast<float>(norm(p - q)));
                    }
            }
    });
    return dist;
}

}  // namespace tessera::core
