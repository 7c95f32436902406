// dynamic/sheet_sides.cpp — samples kept on their coarse side of every nearby sheet.
#include "dynamic/sheet_sides.hpp"

#include <algorithm>
#include <cmath>

#include "core/spatial_grid.hpp"

namespace tessera::dynamic {

namespace {

constexpr double keep_share = 0.5;  // of the coarse height (and of the contact distance)

struct Corners {
    Vec3 a, b, c;
};

// Barycentric weights of p's projection onto the triangle's plane; false when the projection
// falls outside the triangle (another triangle, or none, is the one p is over).
bool over_triangle(const Corners& t, const Vec3& normal, const Vec3& p, double w[3]) {
    const double area = dot(cross(t.b - t.a, t.c - t.a), normal);
    if (!(std::abs(area) > 0.0)) return false;
    w[0] = dot(cross(t.b - p, t.c - p), normal) / area;
    w[1] = dot(cross(t.c - p, t.a - p), normal) / area;
    w[2] = 1.0 - w[0] - w[1];
    return w[0] >= 0.0 && w[1] >= 0.0 && w[2] >= 0.0;
}

Vec3 unit_normal(const Corners& t) {
    const Vec3 n = cross(t.b - t.a, t.c - t.a);
    const double length = norm(n);
    return length > 0.0 ? n * (1.0 / length) : Vec3{};
}

struct Scratch {
    std::vector<Vec3> centres, push;
    core::SpatialGrid grid;
};

// One Jacobi sweep over one frame; returns the largest shortfall found.
double sweep(Vec3* p, const Vec3* coarse, const std::vector<std::array<int, 3>>& triangles,
             const std::vector<int>& element_of, int samples, double distance, Scratch& s) {
    s.centres.resize(triangles.size());
    double largest = 0.0;  // the widest triangle's reach from its centre
    for (size_t t = 0; t < triangles.size(); ++t) {
        const auto& [a, b, c] = triangles[t];
        s.centres[t] = (p[a] + p[b] + p[c]) * (1.0 / 3.0);
        for (int k : triangles[t]) largest = std::max(largest, norm(p[k] - s.centres[t]));
    }
    s.grid.build(s.centres, largest + distance, 3);
    s.push.assign(samples, Vec3{});
    double worst = 0.0;
    for (int i = 0; i < samples; ++i)
        s.grid.for_each_within(p[i], largest + distance, [&](int t, double) {
            const auto& [a, b, c] = triangles[t];
            if (element_of[a] == element_of[i]) return;
            const Corners now{p[a], p[b], p[c]}, was{coarse[a], coarse[b], coarse[c]};
            const Vec3 n = unit_normal(now), n0 = unit_normal(was);
            double w[3];
            if (!over_triangle(now, n, p[i], w)) return;
            const double height0 = dot(coarse[i] - was.a, n0);
            const double side = height0 >= 0.0 ? 1.0 : -1.0;
            const double keep = keep_share * std::min(distance, std::abs(height0));
            const double shortfall = keep - side * dot(p[i] - now.a, n);
            if (shortfall <= 0.0 || shortfall > distance + largest) return;  // far below: another layer
            worst = std::max(worst, shortfall);
            // Half the shortfall each: the sample along the normal, the triangle's point under it
            // against it (its corners by weight, scaled so that point moves the half).
            const Vec3 half = n * (0.5 * side * shortfall);
            s.push[i] += half;
            const double scale = 1.0 / (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
            s.push[a] -= half * (w[0] * scale);
            s.push[b] -= half * (w[1] * scale);
            s.push[c] -= half * (w[2] * scale);
        });
    for (int i = 0; i < samples; ++i) p[i] += s.push[i];
    return worst;
}

}  // namespace

std::vector<std::array<int, 3>> sheet_triangles(const TopologyGrid& grid) {
    std::vector<std::array<int, 3>> out;
    for (int e = 0; e < grid.element_count(); ++e) {
        if (grid.kind(e) != ElementTopology::sheet) continue;
        for (int r = 0; r + 1 < grid.rows(e); ++r)
            for (int c = 0; c + 1 < grid.cols(e); ++c) {
                const int s = grid.at(e, r, c), right = grid.at(e, r, c + 1), down = grid.at(e, r + 1, c),
                          across = grid.at(e, r + 1, c + 1);
                out.push_back({s, right, across});
                out.push_back({s, across, down});
            }
    }
    return out;
}

ContactReport keep_sides(std::vector<Vec3>& positions, const std::vector<Vec3>& coarse,
                         const std::vector<std::array<int, 3>>& triangles, const std::vector<int>& element_of,
                         int frames, int samples, double distance, double tolerance, int max_sweeps, int threads) {
    if (triangles.empty() || !(distance > 0.0)) return {};
    return sweep_frames<Scratch>(frames, threads, tolerance * distance, max_sweeps, [&](int f, Scratch& scratch) {
        return sweep(positions.data() + static_cast<size_t>(f) * samples, coarse.data() + static_cast<size_t>(f) * samples,
                     triangles, element_of, samples, distance, scratch);
    });
}

}  // namespace tessera::dynamic
