#include "det/vacancies.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

#include "core/empty_space.hpp"
#include "core/rng.hpp"
#include "det/layers.hpp"

namespace tessera::det {

namespace {

// Elements inserted per call at most, as a multiple of the count target (a bound that only
// a domain far emptier than its count can reach).
constexpr double kInsertionBound = 1.0;
// Exemplar elements tried at a hole before it is given up (a long element may not fit).
constexpr int kCopiesTried = 8;

}  // namespace

double vacancy_step(int dim, double spacing) { return spacing / (dim == 2 ? 4.0 : 3.0); }

std::vector<Vec3> vacancy_candidates(const Domain& domain, int dim, double spacing) {
    return core::lattice_inside(domain, dim, vacancy_step(dim, spacing));
}

namespace {

// The type to put into a hole at c: of the types whose hard core holds against the
// elements around c, the one furthest below its count (relative to it); when none holds,
// the one that comes closest to holding it.
int choose_type(const core::ObstacleGrid& grid, const core::CrowdingBounds& tails, const Vec3& c,
                const std::vector<long>& count, const std::vector<long>& target, double reach,
                std::vector<double>& nearest) {
    const int types = static_cast<int>(count.size());
    grid.nearest_by_tag(c, types, reach, nearest);
    int best = -1, closest = 0;
    double best_deficit = -INFINITY, best_fit = -INFINITY;
    for (int t = 0; t < types; ++t) {
        if (target[t] <= 0) continue;
        double fit = INFINITY;
        for (int b = 0; b < types; ++b) {
            const double core_distance = tails.hard_core(t, b);
            if (core_distance > 0.0) fit = std::min(fit, nearest[b] / core_distance);
        }
        const double deficit = static_cast<double>(target[t] - count[t]) / static_cast<double>(target[t]);
        if (fit >= 1.0 && deficit > best_deficit) best_deficit = deficit, best = t;
        if (fit > best_fit) best_fit = fit, closest = t;
    }
    return best >= 0 ? best : closest;
}

}  // namespace

double exemplar_hole_radius(const Exemplar& exemplar, double spacing, double radius) {
    if (exemplar.samples.empty() || !(spacing > 0.0)) return 0.0;
    // A layer (a 3D exemplar thin along one axis, in a box): its holes are in the layer, and the
    // walls of the thin axis must not bound their size, so they are measured in the plane of
    // the two other axes.
    const Box b = exemplar.domain.bounds();
    const LayerAxes layer = layer_axes(b, exemplar.dimension, radius);
    int thin = -1, thin_count = 0;
    for (int k = 0; k < exemplar.dimension; ++k)
        if (layer.thin[k]) thin = k, ++thin_count;
    const bool in_plane = exemplar.dimension == 3 && thin_count == 1 && exemplar.domain.kind() == Domain::Kind::box;
    int axes[3] = {0, 1, 2};
    if (in_plane) axes[0] = (thin + 1) % 3, axes[1] = (thin + 2) % 3;
    const int dim = in_plane ? 2 : exemplar.dimension;
    std::vector<Vec3> p;
    std::vector<double> rim;
    for (const Sample& s : exemplar.samples) {
        p.push_back(Vec3{s.p[axes[0]], s.p[axes[1]], dim == 3 ? s.p[axes[2]] : 0.0});
        rim.push_back(exemplar.elements[s.element].radius);
    }
    const Domain domain = in_plane ? Domain::box({b.lo[axes[0]], b.lo[axes[1]], 0}, {b.hi[axes[0]], b.hi[axes[1]], 0}, 2)
                                   : exemplar.domain;
    const double step = spacing / (dim == 2 ? 5.0 : 3.0);
    return core::largest_empty_ball(p, rim, domain, dim, step, 1).radius;
}

namespace {

// A key of the world lattice cell of side `step` that holds p.
std::uint64_t world_cell_key(const Vec3& p, double step) {
    std::uint64_t key = 0x9e3779b97f4a7c15ULL;
    for (int k = 0; k < 3; ++k)
        key = core::mix64(key ^ static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(p[k] / step))));
    return key;
}

// Constrained selection (section 5) for the elements holes receive: a copy of an exemplar
// floor element goes down or up to the source's own height above its floor (the assignment
// then holds that elevation, det/assign.cpp), and only where a floor is that near.
struct FloorCopies {
    bool active = false;
    Gravity gravity;
    double reach = 0.0;
    std::vector<double> height;  // per exemplar element: above its floor; infinity = not a floor element

    bool place(const Exemplar& ex, int source, const Quat& frame, const Domain& domain, Vec3& at) const {
        if (!active || !std::isfinite(height[source])) return true;
        const Element& src = ex.elements[source];
        const Vec3 low = frame.rotate(lowest_sample(ex, src, gravity) - src.position) + at;
        const double here = height_above_floor(domain, low, gravity, reach);
        if (!std::isfinite(here)) return false;  // no floor near: not a place for a floor element
        at += gravity.vector() * (here - height[source]);
        return true;
    }
};

FloorCopies floor_copies(const Exemplar& ex, const Params& params) {
    FloorCopies f;
    if (!params.floor_constraints) return f;
    f.active = true;
    f.gravity = params.gravity;
    f.reach = std::max(params.floor_distance, params.spacing) * 2.0;
    const std::vector<char> code = floor_elements(ex, ex.domain, params.gravity, params.floor_distance, params.boundary);
    f.height.assign(ex.elements.size(), INFINITY);
    for (size_t e = 0; e < ex.elements.size(); ++e) {
        if (!(code[e] & floor_bit)) continue;
        f.height[e] = height_above_floor(ex.domain, lowest_sample(ex, ex.elements[e], f.gravity), f.gravity, f.reach);
    }
    return f;
}

}  // namespace

VacancyReport fill_vacancies(Provenance into, const Exemplar& exemplar, const Domain& domain, const Params& params,
                             const core::CrowdingBounds& tails, const VacancySettings& settings) {
    VacancyReport report;
    Arrangement& out = into.out;
    const int dim = params.dimension;
    const int types = static_cast<int>(exemplar.types.size());
    const double spacing = params.spacing;
    if (!(spacing > 0.0) || exemplar.elements.empty()) return report;

    std::vector<long> count(types, 0), target(types, 0);
    long total_target = 0, total = static_cast<long>(out.elements.size());
    for (int t = 0; t < types; ++t) total_target += target[t] = std::lround(params.type_density[t] * domain.measure());
    for (const Element& e : out.elements) ++count[e.type];
    if (settings.hole_radius <= 0.0 && !(settings.reach_count && total < total_target)) return report;
    std::vector<std::vector<int>> of_type(types);
    for (size_t i = 0; i < exemplar.elements.size(); ++i) of_type[exemplar.elements[i].type].push_back(static_cast<int>(i));

    core::ObstacleGrid grid(domain.bounds(), spacing, dim);
    for (const Sample& s : out.samples) grid.add(s.p, out.elements[s.element].radius, out.elements[s.element].type);
    const bool count_fill = settings.reach_count && total < total_target;
    // Filling holes only, a lattice with a step of hole_radius / (2 sqrt(d)) has a point within
    // a quarter of the hole radius of every hole's centre, which the local search then finds
    // (a coarser one makes most of the pattern's interstices candidates).
    const double step = count_fill ? vacancy_step(dim, spacing)
                                   : std::max(vacancy_step(dim, spacing), 0.5 * settings.hole_radius / std::sqrt(double(dim)));
    const double lattice_slack = 0.5 * step * std::sqrt(static_cast<double>(dim));
    const std::vector<Vec3> candidates = core::lattice_inside(domain, dim, step);
    // Holes wider than `cap` rank equal. Filling holes only, the heap needs no lattice point
    // that cannot lie in one (the hole's centre is within lattice_slack of some point).
    const double cap = count_fill ? 2.0 * spacing : settings.hole_radius + 2.0 * lattice_slack;
    const double least = count_fill ? 0.0 : settings.hole_radius - lattice_slack;
    // A layered exemplar fills a domain as thin as itself (a shell): its holes lie in the
    // layer, and the walls of the thin axis must not bound their size.
    const bool layered = layer_axes(exemplar.domain.bounds(), dim, params.radius).any;
    const auto clearance = [&](const Vec3& c) {
        if (!layered) return core::ball_clearance(grid, domain, c, cap);
        return domain.inside(c) ? grid.clearance(c, cap) : -1.0;
    };
    std::priority_queue<std::pair<double, int>> heap;  // (clearance, -index): largest first, ties by index
    for (size_t i = 0; i < candidates.size(); ++i)
        if (const double d = clearance(candidates[i]); d > least) heap.emplace(d, -static_cast<int>(i));

    // Filling for the count stops at holes narrower than a quarter spacing: smaller ones
    // are not holes, and an element there would be a new defect.
    const double count_gap = 0.25 * spacing;
    const long bound = std::max<long>(16, std::lround(kInsertionBound * static_cast<double>(total_target)));
    const core::KeyedRng rng(settings.seed, core::Purpose::jitter, settings.round);
    const FloorCopies floor = floor_copies(exemplar, params);
    std::vector<double> nearest;
    while (!heap.empty()) {
        const auto [ranked, negative] = heap.top();
        heap.pop();
        const double fresh = clearance(candidates[-negative]);
        if (fresh < ranked) {  // an insertion came near since: re-rank
            heap.emplace(fresh, negative);
            continue;
        }
        // A lattice point can lie up to half a cell diagonal from the hole's centre: a hole
        // is judged, and filled, at the centre a local search finds from it.
        const bool short_of_count = settings.reach_count && total < total_target && fresh > count_gap;
        const bool maybe_hole = settings.hole_radius > 0.0 && fresh + lattice_slack > settings.hole_radius;
        if (!maybe_hole && !short_of_count) break;  // the largest remaining hole needs nothing
        double depth = fresh;
        const Vec3 c = maybe_hole ? core::hole_centre(candidates[-negative], dim, step, clearance, depth) : candidates[-negative];
        const bool hole = maybe_hole && depth > settings.hole_radius;
        if (!hole && !short_of_count) continue;
        if (report.added >= bound) {
            report.bound_hit = true;
            break;
        }
        const int type = choose_type(grid, tails, c, count, target, cap, nearest);
        if (of_type[type].empty()) continue;
        const bool over = static_cast<double>(count[type]) >= static_cast<double>(target[type]) * (1.0 + settings.count_allowance);
        if (over && !short_of_count && depth <= settings.must_fill_radius) continue;
        // A keyed random element of the type, keyed by the hole's place in the world (its
        // centre on a lattice of the candidates' step anchored at the origin, not an index
        // into this domain's lattice), turned by the field.
        const Quat frame = params.field.frame(c, dim);
        const std::uint64_t place = world_cell_key(c, step);
        int added = -1;
        for (int attempt = 0; attempt < kCopiesTried && added < 0; ++attempt) {
            const std::uint64_t key = place * kCopiesTried + static_cast<std::uint64_t>(attempt);
            const int source = of_type[type][rng.below(key, of_type[type].size())];
            const Element& src = exemplar.elements[source];
            Vec3 at = c;
            if (!floor.place(exemplar, source, frame, domain, at)) continue;
            // Inside, and no more than half its radius beyond the boundary: a hole between the
            // last row and a wall too narrow for an element is not filled with half an element.
            bool inside = true;
            for (int s = 0; s < src.sample_count && inside; ++s) {
                const Vec3 q = frame.rotate(exemplar.samples[src.first_sample + s].p - src.position) + at;
                inside = domain.inside(q) && (layered || domain.distance_to_boundary(q) >= 0.5 * src.radius);
            }
            if (inside) added = append_copy(into, exemplar, source, frame, at - frame.rotate(src.position), dim);
        }
        if (added < 0) continue;  // nothing fits here
        const Element& e = out.elements[added];
        for (int s = 0; s < e.sample_count; ++s) grid.add(out.samples[e.first_sample + s].p, e.radius, e.type);
        ++count[type], ++total, ++report.added;
    }
    return report;
}

}  // namespace tessera::det
