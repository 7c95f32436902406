// dynamic/local_frames.cpp — the orientation field of a coarse motion (local_frames.hpp).
#include "dynamic/local_frames.hpp"

#include <cmath>

namespace tessera::dynamic {

namespace {

Vec3 unit_or(const Vec3& v, const Vec3& fallback) {
    const double n = norm(v);
    return n > 1e-12 ? v / n : fallback;
}

// Central difference along the grid (one-sided at the edges).
Vec3 grid_tangent(const Animation& a, const TopologyGrid& g, int f, int s, int dr, int dc) {
    const int ahead = g.step(s, dr, dc), behind = g.step(s, -dr, -dc);
    return a.at(f, ahead >= 0 ? ahead : s) - a.at(f, behind >= 0 ? behind : s);
}

// The axis least aligned with v: a reference normal that is never parallel to it.
Vec3 least_aligned_axis(const Vec3& v, int dimension) {
    if (dimension == 2) return {0, 0, 1};
    const double ax = std::abs(v.x), ay = std::abs(v.y), az = std::abs(v.z);
    if (ax <= ay && ax <= az) return {1, 0, 0};
    return ay <= az ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
}

LocalFrame frame_from(const Vec3& tangent, const Vec3& normal_hint, int dimension) {
    LocalFrame fr;
    const Vec3 t = unit_or(tangent, {1, 0, 0});
    if (dimension == 2) {
        fr.axis[0] = {t.x, t.y, 0};
        fr.axis[1] = {-t.y, t.x, 0};
        fr.axis[2] = {0, 0, 1};
        return fr;
    }
    const Vec3 n = unit_or(normal_hint - t * dot(normal_hint, t), least_aligned_axis(t, 3));
    fr.axis[0] = t;
    fr.axis[1] = cross(n, t);
    fr.axis[2] = n;
    return fr;
}

// A thread at frame f: the normal starts at the axis least aligned with the element's first
// tangent at frame 0 (fixed over time) and is transported sample to sample.
void thread_frames(const Animation& a, const TopologyGrid& g, int e, int f, LocalFrame* out) {
    const int dim = a.structure.dimension;
    const int first = g.at(e, 0, 0);
    Vec3 normal = least_aligned_axis(grid_tangent(a, g, 0, first, 0, 1), dim);
    for (int c = 0; c < g.cols(e); ++c) {
        const int s = g.at(e, 0, c);
        out[s] = frame_from(grid_tangent(a, g, f, s, 0, 1), normal, dim);
        normal = out[s].axis[2];
    }
}

void sheet_frames(const Animation& a, const TopologyGrid& g, int e, int f, LocalFrame* out) {
    const int dim = a.structure.dimension;
    for (int r = 0; r < g.rows(e); ++r)
        for (int c = 0; c < g.cols(e); ++c) {
            const int s = g.at(e, r, c);
            const Vec3 u = grid_tangent(a, g, f, s, 0, 1), v = grid_tangent(a, g, f, s, 1, 0);
            out[s] = frame_from(u, cross(u, v), dim);
        }
}

}  // namespace

std::vector<LocalFrame> local_frames(const Animation& coarse, const TopologyGrid& grid) {
    const int samples = coarse.sample_count();
    std::vector<LocalFrame> frames(static_cast<size_t>(coarse.frame_count()) * samples);
    for (int f = 0; f < coarse.frame_count(); ++f) {
        LocalFrame* row = frames.data() + static_cast<size_t>(f) * samples;
        for (size_t e = 0; e < coarse.structure.elements.size(); ++e) {
            const int el = static_cast<int>(e);
            if (grid.kind(el) == ElementTopology::thread) thread_frames(coarse, grid, el, f, row);
            if (grid.kind(el) == ElementTopology::sheet) sheet_frames(coarse, grid, el, f, row);
        }
    }
    return frames;
}

}  // namespace tessera::dynamic
