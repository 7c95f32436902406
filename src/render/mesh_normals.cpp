// vertex_normals: orient faces consistently per edge-connected patch, then average
// (mesh_normals.hpp).
#include "render/mesh_normals.hpp"

#include <algorithm>
#include <cstdint>
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

std::vector<Vec3> vertex_normals(const TriangleMesh& mesh) {
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

    std::vector<Vec3> normals(mesh.vertices.size());
    for (int t = 0; t < triangle_count; ++t) {
        const auto& tri = mesh.triangles[t];
        if (!valid(tri)) continue;
        const Vec3& a = mesh.vertices[tri[0]];
        Vec3 n = cross(mesh.vertices[tri[1]] - a, mesh.vertices[tri[2]] - a);  // twice the area
        if (!is_finite(n)) continue;
        if (flip[t]) n = -n;
        for (const int v : tri) normals[v] += n;
    }
    return normals;
}

}  // namespace tessera::render
