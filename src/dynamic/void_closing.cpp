// dynamic/void_closing.cpp — voids wider than the exemplar's closed from their rim.
#include "dynamic/void_closing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

// Whether samples within `reach` of p lie in every orthant round it (quadrant in 2D, octant
// in 3D): p is then inside the samples, not in a band along their edge.
bool surrounded(const core::SpatialGrid& grid, const std::vector<Vec3>& points, const Vec3& p, double reach,
                int dimension) {
    unsigned seen = 0;
    grid.for_each_within(p, reach, [&](int i, double) {
        unsigned orthant = 0;
        for (int k = 0; k < dimension; ++k)
            if (points[i][k] > p[k]) orthant |= 1u << k;
        seen |= 1u << orthant;
    });
    return seen == (1u << (1 << dimension)) - 1;
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
    double nn_sum = 0.0, nn_sum2 = 0.0;
    long nn_count = 0;
    for (int i = 0; i < measured; ++i) {
        const int f = measured == 1 ? 0 : static_cast<int>(static_cast<long>(i) * (frames - 1) / (measured - 1));
        const Vec3* first = &exemplar.at(f, 0);
        points.assign(first, first + exemplar.sample_count());
        grid.build(points, 1.5 * spacing, dimension_);
        for (int s = 0; s < exemplar.sample_count(); ++s) {
            double nearest2 = 4.0 * spacing * spacing;
            grid.for_each_within(points[s], 2.0 * spacing, [&](int o, double d2) {
                if (o != s) nearest2 = std::min(nearest2, d2);
            });
            nn_sum += std::sqrt(nearest2), nn_sum2 += nearest2, ++nn_count;
        }
        for (int k = 0; k < window_probes.size(); ++k) {
            if (!window_probes.inside(k)) continue;
            // Disks inside the window and surrounded by samples only: the window's sides are
            // where the exemplar was cut out, or where a drifting exemplar left its window
            // behind (drifting_lattice_2d: an empty band 1.03 wide, twice its voids), not walls.
            const Vec3 p = window_probes.point(k);
            const double wall = window.distance_to_boundary(p);
            if (wall <= exemplar_void_) continue;
            const double empty = std::min(wall, nearest_distance(grid, p, wall));
            if (empty > exemplar_void_ && surrounded(grid, points, p, empty + spacing, dimension_))
                exemplar_void_ = empty;
        }
    }
    // A move may not bring a sample nearer to another than one standard deviation under the
    // exemplar's mean nearest-neighbour distance: where the exemplar's spacing is that even
    // (a lattice), a void cannot close without crowding (the ring round a vacancy pressed
    // into itself and the lattice broke up round it), and it is left.
    const double mean = nn_count > 0 ? nn_sum / nn_count : spacing;
    const double variance = nn_count > 0 ? std::max(0.0, nn_sum2 / nn_count - mean * mean) : 0.0;
    closest_pair_ = mean - std::sqrt(variance);
    // A window too small to hold a probe away from its walls tells nothing: half a spacing.
    exemplar_void_ = std::max(exemplar_void_, 0.5 * spacing);
    // Probes a sixth of the widest void apart at most (a quarter in 3D), not finer than the
    // exemplar's: where its voids span spacings (clustered seedlings: redwood), a disk stamped
    // per sample a quarter spacing apart cost more than the synthesis (0.23 -> 0.48 s).
    probes_ = ProbeLattice(domain, std::max(step, exemplar_void_ / (dimension_ == 2 ? 6.0 : 4.0)), periodic.on);
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

// Whether moving image point i by `move` brings it closer than closest_pair_ to a sample it
// is approaching. Samples already moved count where they are.
bool VoidClosing::crowds(int i, const Vec3& move, const std::vector<Vec3>& positions) const {
    const int s = images_.sample[i];
    const Vec3 from = images_.points[i], to = from + move;
    const double close2 = closest_pair_ * closest_pair_;
    bool crowded = false;
    grid_.for_each_within(to, closest_pair_ + norm(move), [&](int j, double) {
        const int o = images_.sample[j];
        if (o == s || crowded) return;
        const Vec3 q = images_.points[j] + (positions[o] - built_[o]);
        const double after = squared_norm(q - to);
        crowded = after < close2 && after < squared_norm(q - from);
    });
    return crowded;
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
    built_ = positions;
    int moved = 0;
    for (const Probe& v : voids_) {
        const Vec3 centre = probes_.point(v.index);
        const double step = std::min(max_step * spacing_, v.empty - exemplar_void_);
        grid_.for_each_within(centre, v.empty + rim_width * spacing_, [&](int i, double d2) {
            const int s = images_.sample[i];
            if (claimed_[s] || !(d2 > 0.0)) return;
            claimed_[s] = 1;
            const Vec3 move = (centre - images_.points[i]) * (step / std::sqrt(d2));
            if (crowds(i, move, positions)) return;
            positions[s] += move;
            ++moved;
        });
    }
    return moved;
}

}  // namespace tessera::dynamic
