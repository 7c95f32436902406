// dynamic/void_closing.cpp — voids wider than the exemplar's closed from their rim.
#include "dynamic/void_closing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace tessera::dynamic {

namespace {

constexpr int measured_frames = 16;    // exemplar frames whose voids are measured
constexpr double max_step = 0.1;       // the most a rim sample moves in one application, in spacings
// Samples up to a spacing beyond a void's nearest one move with it: the rim and the ring behind
// it, so the deficit spreads (the rim alone was held back by the assignment: largest empty
// circle past the obstacle 1.4 at frame 71 against 1.0 so).
constexpr double rim_width = 1.0;
constexpr double largest_reach = 4.0;  // voids are measured up to this radius, in spacings
constexpr double wall_allowance = 0.5; // a void may reach this much of the exemplar's widest beyond a wall

double nearest_distance(const core::SpatialGrid& grid, const Vec3& p, double reach) {
    double best = reach * reach;
    grid.for_each_within(p, reach, [&](int, double d2) { best = std::min(best, d2); });
    return std::sqrt(best);
}

}  // namespace

VoidClosing::VoidClosing(const Animation& exemplar, const Domain& domain, double spacing, const Periodic& periodic)
    : domain_(&domain), periodic_(periodic), dimension_(domain.dimension()), spacing_(spacing) {
    const double step = spacing / (dimension_ == 2 ? 4.0 : 3.0);
    // The exemplar's voids: its frames spread evenly, each probed over its own domain.
    const Domain& window = exemplar.structure.domain;
    const ProbeLattice window_probes(window, step, false);
    const int frames = exemplar.frame_count();
    const int measured = std::min(frames, measured_frames);
    std::vector<Vec3> points;
    core::SpatialGrid grid;
    std::vector<std::pair<double, double>> seen;  // (nearest sample, wall) of every probe of every frame
    for (int i = 0; i < measured; ++i) {
        const int f = measured == 1 ? 0 : static_cast<int>(static_cast<long>(i) * (frames - 1) / (measured - 1));
        const Vec3* first = &exemplar.at(f, 0);
        points.assign(first, first + exemplar.sample_count());
        grid.build(points, 1.5 * spacing, dimension_);
        for (int k = 0; k < window_probes.size(); ++k)
            if (window_probes.inside(k)) {
                const Vec3 p = window_probes.point(k);
                seen.emplace_back(nearest_distance(grid, p, largest_reach * spacing), window.distance_to_boundary(p));
            }
    }
    // The widest void by the rule apply() follows (a void may reach beyond a wall by the
    // allowance, a share of the widest void itself), so that the exemplar's own frames are
    // left as they are: the fixed point, from the voids that stay off the window's sides.
    for (int round = 0; round < 8; ++round) {
        double widest = 0.0;
        for (const auto& [nearest, wall] : seen) widest = std::max(widest, std::min(nearest, wall + wall_allowance * exemplar_void_));
        if (widest <= exemplar_void_) break;
        exemplar_void_ = widest;
    }
    // A window too small to hold a probe away from its walls tells nothing: half a spacing.
    exemplar_void_ = std::max(exemplar_void_, 0.5 * spacing);
    probes_ = ProbeLattice(domain, step, periodic.on);
}

// The distance to a wall; with wrap the faces of the bounding box are seams, not walls (where
// the domain's nearest boundary may be such a face, there is taken to be none).
double VoidClosing::wall_distance(const Vec3& p) const {
    const double d = domain_->distance_to_boundary(p);
    if (!periodic_.on) return d;
    double face = std::numeric_limits<double>::infinity();
    for (int k = 0; k < dimension_; ++k)
        face = std::min({face, p[k] - periodic_.lo[k], periodic_.lo[k] + periodic_.extent[k] - p[k]});
    return d >= face - 1e-9 * spacing_ ? std::numeric_limits<double>::infinity() : d;
}

double VoidClosing::wall_bound(const Vec3& p) const {
    return wall_distance(p) + wall_allowance * exemplar_void_;
}

int VoidClosing::apply(std::vector<Vec3>& positions) {
    const int n = static_cast<int>(positions.size());
    // The probes farther than the exemplar's widest void from every sample and, less
    // wall_allowance of it, from the walls: a band along a wall is a void when it is that much
    // wider than the gap a wall leaves. (Bounded by the wall itself, the band behind the
    // obstacle held half the density within half a unit of its rim; not bounded at all, the
    // gap the static method leaves along a box's sides was pulled shut.)
    probes_.clear_stamps();
    for (const Vec3& p : positions) probes_.stamp(p, exemplar_void_);
    open_.clear();
    for (int i = 0; i < probes_.size(); ++i)
        if (probes_.inside(i) && !probes_.covered(i) && wall_bound(probes_.point(i)) > exemplar_void_)
            open_.push_back(i);
    if (open_.empty()) return 0;  // the common case: nothing more to do
    images_.build(positions.data(), n, periodic_, (largest_reach + rim_width) * spacing_, dimension_);
    grid_.build(images_.points, 1.5 * spacing_, dimension_);
    voids_.clear();
    for (int i : open_) {
        const Vec3 p = probes_.point(i);
        const double empty = std::min(nearest_distance(grid_, p, largest_reach * spacing_), wall_bound(p));
        if (empty > exemplar_void_) voids_.push_back(Probe{empty, i});
    }
    // The widest voids first; each sample follows the first void whose rim it is on.
    std::sort(voids_.begin(), voids_.end(),
              [](const Probe& a, const Probe& b) { return a.empty != b.empty ? a.empty > b.empty : a.index < b.index; });
    claimed_.assign(n, 0);
    int moved = 0;
    for (const Probe& v : voids_) {
        const Vec3 centre = probes_.point(v.index);
        const double step = std::min(max_step * spacing_, v.empty - exemplar_void_);
        grid_.for_each_within(centre, v.empty + rim_width * spacing_, [&](int i, double d2) {
            const int s = images_.sample[i];
            if (claimed_[s] || !(d2 > 0.0)) return;
            claimed_[s] = 1;
            positions[s] += (centre - images_.points[i]) * (step / std::sqrt(d2));
            ++moved;
        });
    }
    return moved;
}

}  // namespace tessera::dynamic
