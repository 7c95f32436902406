// core/triangle_tree.cpp — the bounding-box tree of triangle_tree.hpp: median splits on
// the longest axis down to leaves of a few triangles, traversed with a fixed stack.
#include "core/triangle_tree.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace tessera::core {
namespace {

constexpr int kLeafSize = 4;
constexpr int kMaxDepth = 64;  // median splits of at most 2^31 triangles stay far below

double box_distance_squared(const Vec3& p, const Vec3& lo, const Vec3& hi) {
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double e = std::max({lo[k] - p[k], 0.0, p[k] - hi[k]});
        d2 += e * e;
    }
    return d2;
}

bool segment_meets_box(const Vec3& a, const Vec3& b, const Vec3& lo, const Vec3& hi) {
    for (int k = 0; k < 3; ++k)
        if (std::max(a[k], b[k]) < lo[k] || std::min(a[k], b[k]) > hi[k]) return false;
    return true;
}

// Möller-Trumbore: does a + t (b - a), t in [0, 1), hit the triangle?
bool segment_hits(const Vec3& a, const Vec3& b, const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    const Vec3 d = b - a, e1 = p1 - p0, e2 = p2 - p0;
    const Vec3 h = cross(d, e2);
    const double det = dot(e1, h);
    if (det == 0.0) return false;  // parallel: a segment in the triangle's plane crosses nothing
    const double inv = 1.0 / det;
    const Vec3 s = a - p0;
    const double u = dot(s, h) * inv;
    if (u < 0.0 || u > 1.0) return false;
    const Vec3 q = cross(s, e1);
    const double v = dot(d, q) * inv;
    if (v < 0.0 || u + v > 1.0) return false;
    const double t = dot(e2, q) * inv;
    return t >= 0.0 && t < 1.0;
}

}  // namespace

// Squared distance from p to the triangle (Ericson, Real-Time Collision Detection 5.1.5).
double triangle_distance_squared(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return squared_norm(ap);
    const Vec3 bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return squared_norm(bp);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return squared_norm(ap - ab * (d1 / (d1 - d3)));
    const Vec3 cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return squared_norm(cp);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return squared_norm(ap - ac * (d2 / (d2 - d6)));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
        return squared_norm(bp - (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
    const double denom = 1.0 / (va + vb + vc);
    return squared_norm(ap - ab * (vb * denom) - ac * (vc * denom));
}

TriangleTree::TriangleTree(const TriangleMesh& mesh) {
    triangles_.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles)
        triangles_.push_back({mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]});
    if (triangles_.empty()) return;
    nodes_.reserve(2 * triangles_.size() / kLeafSize + 2);
    build(0, static_cast<int>(triangles_.size()));
}

int TriangleTree::build(int first, int count) {
    const int id = static_cast<int>(nodes_.size());
    nodes_.push_back({});
    Vec3 lo{INFINITY, INFINITY, INFINITY}, hi = -lo;
    for (int i = first; i < first + count; ++i)
        for (const Vec3* v : {&triangles_[i].a, &triangles_[i].b, &triangles_[i].c})
            for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], (*v)[k]), hi[k] = std::max(hi[k], (*v)[k]);
    nodes_[id].lo = lo, nodes_[id].hi = hi;
    if (count <= kLeafSize) {
        nodes_[id].first = first, nodes_[id].count = count;
        return id;
    }
    const Vec3 size = hi - lo;
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
    const auto centroid = [axis](const Triangle& t) { return t.a[axis] + t.b[axis] + t.c[axis]; };
    const int half = count / 2;
    std::nth_element(triangles_.begin() + first, triangles_.begin() + first + half, triangles_.begin() + first + count,
                     [&](const Triangle& x, const Triangle& y) { return centroid(x) < centroid(y); });
    build(first, half);
    const int right = build(first + half, count - half);
    nodes_[id].right = right;
    return id;
}

int TriangleTree::segment_crossings(const Vec3& a, const Vec3& b) const {
    if (nodes_.empty()) return 0;
    int stack[kMaxDepth], top = 0, crossings = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (!segment_meets_box(a, b, node.lo, node.hi)) continue;
        if (node.right < 0) {
            for (int i = node.first; i < node.first + node.count; ++i)
                crossings += segment_hits(a, b, triangles_[i].a, triangles_[i].b, triangles_[i].c);
            continue;
        }
        stack[top++] = node.right;
        stack[top++] = static_cast<int>(&node - nodes_.data()) + 1;
    }
    return crossings;
}

bool TriangleTree::any_within(const Vec3& p, double r) const {
    if (nodes_.empty()) return false;
    const double r2 = r * r;
    int stack[kMaxDepth], top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (box_distance_squared(p, node.lo, node.hi) > r2) continue;
        if (node.right < 0) {
            for (int i = node.first; i < node.first + node.count; ++i)
                if (triangle_distance_squared(p, triangles_[i].a, triangles_[i].b, triangles_[i].c) <= r2) return true;
            continue;
        }
        stack[top++] = node.right;
        stack[top++] = static_cast<int>(&node - nodes_.data()) + 1;
    }
    return false;
}

}  // namespace tessera::core
