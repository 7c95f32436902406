// dynamic/path_blend.cpp — spline blending weights and Hungarian-paired neighbour tracks.
#include "dynamic/path_blend.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tessera::dynamic {

namespace {

// Control points c_0..c_n of the interpolating spline for data d: c_0 = d_0 and c_n = d_n
// (with the ghost points below, the natural ends), and c_{i-1} + 4 c_i + c_{i+1} = 6 d_i
// inside (the uniform cubic B-spline is (1, 4, 1) / 6 at the knots), solved by the Thomas
// algorithm; the system is diagonally dominant, so no pivoting.
std::vector<double> interpolating_controls(const std::vector<double>& d) {
    const int n = static_cast<int>(d.size()) - 1;
    std::vector<double> c(d.size(), 0.0);
    c[0] = d[0], c[n] = d[n];
    if (n < 2) return c;
    std::vector<double> diag(n, 4.0), rhs(n, 0.0);
    for (int i = 1; i < n; ++i) rhs[i] = 6.0 * d[i];
    rhs[1] -= c[0], rhs[n - 1] -= c[n];
    for (int i = 2; i < n; ++i) {
        const double m = 1.0 / diag[i - 1];
        diag[i] -= m;
        rhs[i] -= m * rhs[i - 1];
    }
    c[n - 1] = rhs[n - 1] / diag[n - 1];
    for (int i = n - 2; i >= 1; --i) c[i] = (rhs[i] - c[i + 1]) / diag[i];
    return c;
}

}  // namespace

SplineBlend::SplineBlend(int nodes) : nodes_(std::max(nodes, 1)) {
    const int n = nodes_ - 1;
    control_.assign(static_cast<size_t>(nodes_ + 2) * nodes_, 0.0);
    for (int j = 0; j < nodes_; ++j) {
        std::vector<double> unit(nodes_, 0.0);
        unit[j] = 1.0;
        const std::vector<double> c = interpolating_controls(unit);
        // Ghosts c_{-1} = 2 c_0 - c_1 and c_{n+1} = 2 c_n - c_{n-1}: zero second derivative.
        const double before = n > 0 ? 2.0 * c[0] - c[1] : c[0];
        const double after = n > 0 ? 2.0 * c[n] - c[n - 1] : c[n];
        control_[j] = before;
        for (int k = 0; k <= n; ++k) control_[static_cast<size_t>(k + 1) * nodes_ + j] = c[k];
        control_[static_cast<size_t>(n + 2) * nodes_ + j] = after;
    }
}

std::vector<SplineBlend> splines_up_to(int nodes) {
    std::vector<SplineBlend> splines;
    for (int k = 1; k <= nodes; ++k) splines.emplace_back(k);
    return splines;
}

void SplineBlend::weights(double u, double* w) const {
    const int n = nodes_ - 1;
    std::fill(w, w + nodes_, 0.0);
    if (n == 0) {
        w[0] = 1.0;
        return;
    }
    const int seg = std::clamp(static_cast<int>(std::floor(u)), 0, n - 1);
    const double t = std::clamp(u - seg, 0.0, 1.0);
    // The uniform cubic B-spline basis on one segment, for control points seg - 1 .. seg + 2.
    const double b[4] = {(1 - t) * (1 - t) * (1 - t) / 6.0, (3 * t * t * t - 6 * t * t + 4) / 6.0,
                         (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6.0, t * t * t / 6.0};
    for (int m = 0; m < 4; ++m) {
        const double* row = control_.data() + static_cast<size_t>(seg + m) * nodes_;  // c_{seg+m-1}
        for (int j = 0; j < nodes_; ++j) w[j] += b[m] * row[j];
    }
}

PathTracks path_tracks(const InputFrames& frames, const StNeighbourhood& own, const std::vector<int>& path,
                       const StParams& params, MetricScratch& scratch) {
    PathTracks tracks;
    tracks.nodes = static_cast<int>(path.size());
    const int count = static_cast<int>(own.entries.size());
    tracks.neighbour.resize(count);
    tracks.offset.resize(static_cast<size_t>(count) * tracks.nodes);
    for (int t = 0; t < count; ++t) {
        tracks.neighbour[t] = own.entries[t].sample;
        for (int i = 0; i < tracks.nodes; ++i) tracks.offset[static_cast<size_t>(t) * tracks.nodes + i] = own.entries[t].offset;
    }
    std::vector<int> partner(count, -1);
    for (int i = 1; i < tracks.nodes; ++i) {
        const int id = frames.id(path[i], 0);
        const StEntry* node = frames.entries(id);
        st_distance(own, node, frames.group_start(id), params, scratch, partner.data(),
                    std::numeric_limits<double>::infinity());
        for (int t = 0; t < count; ++t)
            if (partner[t] >= 0) tracks.offset[static_cast<size_t>(t) * tracks.nodes + i] = node[partner[t]].offset;
    }
    return tracks;
}

void blend_tracks(const PathTracks& tracks, const double* w, Vec3* out) {
    for (int t = 0; t < tracks.tracks(); ++t) {
        Vec3 sum;
        const Vec3* o = tracks.offset.data() + static_cast<size_t>(t) * tracks.nodes;
        for (int i = 0; i < tracks.nodes; ++i) sum += o[i] * w[i];
        out[t] = sum;
    }
}

}  // namespace tessera::dynamic
