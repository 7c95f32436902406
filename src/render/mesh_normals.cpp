// corner_normals: orient faces consistently per edge-connected patch, then average the
// faces around each vertex that lie within the crease angle of each corner's own face
// (mesh_normals.hpp).
#include "render/mesh_normals.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <tuple>

namespace tessera::render {
namespace {

// One directed use of an undirected edge (lo, hi) by a triangle.
struct EdgeUse {
    int lo = 0, hi = 0;
    int triangle = 0;
    bool forward = false;  // the triangle walks lo -> hi
};

}  // namespace

std::vector<Vec3> corner_normals(const TriangleMesh& mesh, double crease_degrees) {
    const int vertex_count = static_cast<int>(mesh.vertices.size());
    const int triangle_count = static_cast<int>(mesh.triangles.size());
    auto valid = [&](const std::array<int, 3>& t) {
        return std::all_of(t.begin(), t.end(), [&](int v) { return v >= 0 && v < vertex_count; });
    };

    // Edges sorted so that the uses of one edge are adjacent.
    std::vector<EdgeUse> uses;
    uses.reserve(static_cast<size_t>(triangle_count) * 3);
    for (int t = 0; t < triangle_count; ++t) {
        const auto& tri = mesh.triangles[t];
        if (!valid(tri)) continue;
        for (int k = 0; k < 3; ++k) {
            const int a = tri[k], b = tri[(k + 1) % 3];
            if (a != b) uses.push_back({std::min(a, b), std::max(a, b), t, a < b});
        }
    }
    std::sort(uses.begin(), uses.end(), [](const EdgeUse& u, const EdgeUse& v) {
        return std::tie(u.lo, u.hi, u.triangle) < std::tie(v.lo, v.hi, v.triangle);
    });

    // Neighbours across each edge, as compressed rows: consecutive uses of an edge are
    // linked (a non-manifold edge becomes a chain). `same` = both walk it the same way,
    // which is what a consistently wound pair never does.
    struct Link {
        int other;
        bool same;
    };
    std::vector<int> start(static_cast<size_t>(triangle_count) + 1, 0);
    for (size_t k = 0; k + 1 < uses.size(); ++k)
        if (uses[k].lo == uses[k + 1].lo && uses[k].hi == uses[k + 1].hi)
            ++start[uses[k].triangle + 1], ++start[uses[k + 1].triangle + 1];
    for (int t = 0; t < triangle_count; ++t) start[t + 1] += start[t];
    std::vector<Link> links(static_cast<size_t>(start[triangle_count]));
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (size_t k = 0; k + 1 < uses.size(); ++k) {
        const EdgeUse& u = uses[k];
        const EdgeUse& v = uses[k + 1];
        if (u.lo != v.lo || u.hi != v.hi) continue;
        const bool same = u.forward == v.forward;
        links[fill[u.triangle]++] = {v.triangle, same};
        links[fill[v.triangle]++] = {u.triangle, same};
    }

    // Breadth-first over each patch: flip[t] says whether t is wound against the patch.
    std::vector<std::int8_t> flip(static_cast<size_t>(triangle_count), -1);  // -1 = not reached
    std::vector<int> queue;
    queue.reserve(static_cast<size_t>(triangle_count));
    for (int seed = 0; seed < triangle_count; ++seed) {
        if (flip[seed] >= 0) continue;
        flip[seed] = 0;
        queue.assign(1, seed);
        for (size_t head = 0; head < queue.size(); ++head) {
            const int t = queue[head];
            for (int k = start[t]; k < start[t + 1]; ++k) {
                const Link& l = links[k];
                if (flip[l.other] >= 0) continue;  // first orientation wins (Moebius strips)
                flip[l.other] = static_cast<std::int8_t>(flip[t] ^ (l.same ? 1 : 0));
                queue.push_back(l.other);
            }
        }
    }

    // Oriented face normals (length twice the area) and their directions; zero for
    // faces without area, which take part in nothing.
    std::vector<Vec3> face(static_cast<size_t>(triangle_count)), unit(face.size());
    std::vector<int> first(static_cast<size_t>(vertex_count) + 1, 0);  // vertex -> its corners
    for (int t = 0; t < triangle_count; ++t) {
        const auto& tri = mesh.triangles[t];
        if (!valid(tri)) continue;
        const Vec3& a = mesh.vertices[tri[0]];
        const Vec3 n = cross(mesh.vertices[tri[1]] - a, mesh.vertices[tri[2]] - a);
        const double length = norm(n);
        if (!(length > 0.0) || !std::isfinite(length)) continue;  // also a repeated vertex
        face[t] = flip[t] ? -n : n;
        unit[t] = face[t] / length;
        for (const int v : tri) ++first[v + 1];
    }
    for (int v = 0; v < vertex_count; ++v) first[v + 1] += first[v];
    std::vector<int> corners(static_cast<size_t>(first[vertex_count]));  // 3 * triangle + k
    {
        std::vector<int> next(first.begin(), first.end() - 1);
        for (int t = 0; t < triangle_count; ++t)
            if (unit[t].x != 0.0 || unit[t].y != 0.0 || unit[t].z != 0.0)
                for (int k = 0; k < 3; ++k) corners[next[mesh.triangles[t][k]]++] = 3 * t + k;
    }

    // Per vertex, per corner: the faces around the vertex within the crease angle of the
    // corner's face. When every face there lies within half the angle of their mean,
    // any two lie within the angle, and all corners share the mean (smooth regions, flat
    // fans: linear in the faces). Otherwise every pair is compared (quadratic in the
    // faces of that vertex, which only vertices where sharp edges meet pay).
    const double cos_crease = std::cos(crease_degrees * std::numbers::pi / 180.0);
    const double cos_half = std::cos(crease_degrees * std::numbers::pi / 360.0);
    std::vector<Vec3> normals(static_cast<size_t>(triangle_count) * 3);
    for (int v = 0; v < vertex_count; ++v) {
        const int begin = first[v], end = first[v + 1];
        if (begin == end) continue;
        Vec3 sum;
        for (int i = begin; i < end; ++i) sum += face[corners[i] / 3];
        const double length = norm(sum);
        bool within_half = length > 0.0 && std::isfinite(length);
        const Vec3 mean = within_half ? sum / length : Vec3{};
        for (int i = begin; i < end && within_half; ++i)
            within_half = dot(unit[corners[i] / 3], mean) >= cos_half;
        if (within_half) {
            for (int i = begin; i < end; ++i) normals[corners[i]] = mean;
            continue;
        }
        for (int i = begin; i < end; ++i) {
            const Vec3& own = unit[corners[i] / 3];
            Vec3 near;
            for (int j = begin; j < end; ++j) {
                const int f = corners[j] / 3;
                if (j == i || dot(unit[f], own) >= cos_crease) near += face[f];
            }
            const double n = norm(near);
            // Only a crease angle beyond 90 degrees lets faces cancel.
            normals[corners[i]] = n > 0.0 && std::isfinite(n) ? near / n : own;
        }
    }
    return normals;
}

}  // namespace tessera::render
