// dynamic/thread_sides.cpp — segments of different threads kept on their coarse sides.
#include "dynamic/thread_sides.hpp"

#include <algorithm>
#include <cmath>

#include "core/spatial_grid.hpp"

namespace tessera::dynamic {

namespace {

constexpr double keep_share = 0.5;  // of the coarse separation (and of the contact distance)

// Parameters (s, t) of the closest points of segments p0p1 and q0q1 when both fall strictly
// inside their segments (the segments pass each other there); false otherwise (an end is
// nearest: the sample contacts cover it) or when they are parallel.
bool passing_points(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1, double& s, double& t) {
    const Vec3 u = p1 - p0, v = q1 - q0, w = p0 - q0;
    const double a = dot(u, u), b = dot(u, v), c = dot(v, v), d = dot(u, w), e = dot(v, w);
    const double det = a * c - b * b;
    if (!(det > 1e-12 * a * c)) return false;
    s = (b * e - c * d) / det;
    t = (a * e - b * d) / det;
    return s > 0.0 && s < 1.0 && t > 0.0 && t < 1.0;
}

struct Scratch {
    std::vector<Vec3> centres, push;
    core::SpatialGrid grid;
};

// One Jacobi sweep over one frame; returns the largest shortfall found.
double sweep(Vec3* p, const Vec3* coarse, const std::vector<std::array<int, 2>>& segments,
             const std::vector<int>& element_of, int samples, double distance, Scratch& sc) {
    sc.centres.resize(segments.size());
    double longest = 0.0;
    for (size_t k = 0; k < segments.size(); ++k) {
        const auto& [a, b] = segments[k];
        sc.centres[k] = (p[a] + p[b]) * 0.5;
        longest = std::max(longest, norm(p[b] - p[a]));
    }
    const double reach = longest + distance;
    sc.grid.build(sc.centres, reach, 3);
    sc.push.assign(samples, Vec3{});
    double worst = 0.0;
    for (size_t i = 0; i < segments.size(); ++i)
        sc.grid.for_each_within(sc.centres[i], reach, [&](int j, double) {
            if (static_cast<size_t>(j) <= i) return;
            const auto& [a, b] = segments[i];
            const auto& [c, d] = segments[j];
            if (element_of[a] == element_of[c]) return;
            double s = 0.0, t = 0.0;
            if (!passing_points(p[a], p[b], p[c], p[d], s, t)) return;
            const Vec3 n0 = cross(coarse[b] - coarse[a], coarse[d] - coarse[c]);
            const Vec3 n = cross(p[b] - p[a], p[d] - p[c]);
            const double l0 = norm(n0), l = norm(n);
            if (!(l0 > 0.0) || !(l > 0.0)) return;
            // The coarse side along the coarse common normal, carried to the output's normal.
            const Vec3 gap0 = (coarse[a] + (coarse[b] - coarse[a]) * s) - (coarse[c] + (coarse[d] - coarse[c]) * t);
            const double height0 = dot(gap0, n0) / l0;
            const Vec3 unit = n * ((dot(n, n0) >= 0.0 ? 1.0 : -1.0) / l);
            const double side = height0 >= 0.0 ? 1.0 : -1.0;
            const Vec3 gap = (p[a] + (p[b] - p[a]) * s) - (p[c] + (p[d] - p[c]) * t);
            const double shortfall = keep_share * std::min(distance, std::abs(height0)) - side * dot(gap, unit);
            if (shortfall <= 0.0 || shortfall > reach) return;
            worst = std::max(worst, shortfall);
            // Half each way; a segment's ends by their weights, scaled so its point moves the half.
            const Vec3 half = unit * (0.5 * side * shortfall);
            const double ps = 1.0 / ((1 - s) * (1 - s) + s * s), qs = 1.0 / ((1 - t) * (1 - t) + t * t);
            sc.push[a] += half * ((1 - s) * ps);
            sc.push[b] += half * (s * ps);
            sc.push[c] -= half * ((1 - t) * qs);
            sc.push[d] -= half * (t * qs);
        });
    for (int k = 0; k < samples; ++k) p[k] += sc.push[k];
    return worst;
}

}  // namespace

std::vector<std::array<int, 2>> thread_segments(const TopologyGrid& grid) {
    std::vector<std::array<int, 2>> out;
    for (int e = 0; e < grid.element_count(); ++e) {
        if (grid.kind(e) != ElementTopology::thread) continue;
        for (int c = 0; c + 1 < grid.cols(e); ++c) out.push_back({grid.at(e, 0, c), grid.at(e, 0, c + 1)});
    }
    return out;
}

ContactReport keep_thread_sides(std::vector<Vec3>& positions, const std::vector<Vec3>& coarse,
                                const std::vector<std::array<int, 2>>& segments, const std::vector<int>& element_of,
                                int frames, int samples, double distance, double tolerance, int max_sweeps,
                                int threads) {
    if (segments.empty() || !(distance > 0.0)) return {};
    return sweep_frames<Scratch>(frames, threads, tolerance * distance, max_sweeps, [&](int f, Scratch& scratch) {
        return sweep(positions.data() + static_cast<size_t>(f) * samples, coarse.data() + static_cast<size_t>(f) * samples,
                     segments, element_of, samples, distance, scratch);
    });
}

}  // namespace tessera::dynamic
