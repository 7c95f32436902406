#include "dynamic/element_contacts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/spatial_grid.hpp"

namespace tessera::dynamic {

namespace {

// How near the details may bring two elements: halfway from where the exemplar's or the
// coarse motion's spacing would put them. Wiggles may interleave; elements never touch or
// cross. (The whole spacing would straighten noodles that the coarse motion packs closer
// than the exemplar does: their kinks would have no room.)
constexpr double closest_share = 0.5;

std::vector<int> element_of_samples(const Exemplar& data) {
    std::vector<int> of(data.samples.size());
    for (size_t s = 0; s < of.size(); ++s) of[s] = data.samples[s].element;
    return of;
}

// One Jacobi sweep over one frame: every too-close pair found at the sweep's start moves
// apart half its shortfall each way (summed per sample, then applied), so the result does
// not depend on the order pairs are found in. Returns the largest shortfall found.
double sweep(Vec3* p, const Vec3* coarse, const std::vector<int>& element_of, int samples, int dimension,
             double distance, core::SpatialGrid& grid, std::vector<Vec3>& points, std::vector<Vec3>& push) {
    points.assign(p, p + samples);
    grid.build(points, distance, dimension);
    push.assign(samples, Vec3{});
    double worst = 0.0;
    for (int a = 0; a < samples; ++a)
        grid.for_each_within(points[a], distance, [&](int b, double d2) {
            if (b <= a || element_of[b] == element_of[a]) return;
            const double bound = closest_share * std::min(distance, norm(coarse[a] - coarse[b]));
            const double d = std::sqrt(d2);
            if (d >= bound || d < 1e-12) return;
            const double gap = bound - d;
            worst = std::max(worst, gap);
            const Vec3 u = (points[b] - points[a]) / d;
            push[a] -= u * (0.5 * gap);
            push[b] += u * (0.5 * gap);
        });
    for (int s = 0; s < samples; ++s) p[s] += push[s];
    return worst;
}

struct SweepScratch {
    core::SpatialGrid grid;
    std::vector<Vec3> points, push;
};

}  // namespace

double exemplar_contact_distance(const Animation& exemplar, double quantile) {
    const Exemplar& data = exemplar.structure;
    if (data.elements.size() < 2) return 0.0;
    const std::vector<int> of = element_of_samples(data);
    const int n = exemplar.sample_count();
    const Box box = data.domain.bounds();
    const double reach = std::max(norm(box.size()), 1e-9);  // covers every pair: a grid of few cells
    std::vector<double> nearest;
    core::SpatialGrid grid;
    for (int f = 0; f < exemplar.frame_count(); ++f) {
        const std::vector<Vec3> points(exemplar.positions.begin() + static_cast<long>(f) * n,
                                       exemplar.positions.begin() + static_cast<long>(f + 1) * n);
        grid.build(points, reach / 16.0, data.dimension);
        for (int a = 0; a < n; ++a) {
            double best = std::numeric_limits<double>::infinity();
            grid.for_each_within(points[a], reach, [&](int b, double d2) {
                if (of[b] != of[a]) best = std::min(best, d2);
            });
            if (std::isfinite(best)) nearest.push_back(std::sqrt(best));
        }
    }
    if (nearest.empty()) return 0.0;
    const size_t k = std::min(nearest.size() - 1, static_cast<size_t>(quantile * nearest.size()));
    std::nth_element(nearest.begin(), nearest.begin() + static_cast<std::ptrdiff_t>(k), nearest.end());
    return nearest[k];
}

ContactReport keep_apart(std::vector<Vec3>& positions, const std::vector<Vec3>& coarse,
                         const std::vector<int>& element_of, int frames, int samples, int dimension,
                         double distance, double tolerance, int max_sweeps, int threads) {
    if (!(distance > 0.0) || samples == 0) return {};
    return sweep_frames<SweepScratch>(frames, threads, tolerance * distance, max_sweeps, [&](int f, SweepScratch& s) {
        return sweep(positions.data() + static_cast<size_t>(f) * samples, coarse.data() + static_cast<size_t>(f) * samples,
                     element_of, samples, dimension, distance, s.grid, s.points, s.push);
    });
}

}  // namespace tessera::dynamic
