// Filling the rest of a region that growth did not reach (grow/uncovered.hpp).
#include "grow/uncovered.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/parallel.hpp"
#include "det/layers.hpp"
#include "det/vacancies.hpp"
#include "tessera/det_session.hpp"

namespace tessera::grow {

namespace {

// The probe lattice of the hole test, in uncovered distances: coarse enough to cost a small
// share of a round, fine enough that an empty place a little wider than the distance holds
// a probe point.
constexpr double kProbeStep = 0.5;
// The fill domain's cells, in spacings, and the most cells it may have (Domain::region
// allows 2^24).
constexpr double kFillCell = 0.5;
constexpr double kMaxFillCells = 1 << 22;
// New elements keep at least this share of the spacing from every element already there at
// initialization (the iterations then pull them to their matched distances).
constexpr double kEdge = 0.5;

// Points of a lattice of step `step` over the region's bounds that lie in the region.
std::vector<Vec3> probe_points(const Domain& region, double step, int dimension) {
    const Box b = region.bounds();
    const int nx = std::max(1, static_cast<int>(std::ceil((b.hi.x - b.lo.x) / step)));
    const int ny = std::max(1, static_cast<int>(std::ceil((b.hi.y - b.lo.y) / step)));
    const int nz = dimension == 3 ? std::max(1, static_cast<int>(std::ceil((b.hi.z - b.lo.z) / step))) : 1;
    std::vector<Vec3> points;
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                Vec3 p = b.lo + Vec3{(i + 0.5) * step, (j + 0.5) * step, (k + 0.5) * step};
                if (dimension == 2) p.z = b.lo.z;
                if (region.inside(p)) points.push_back(p);
            }
    return points;
}

// How distances are measured: in 3D, or in the plane of a layered exemplar (a membrane, rods
// on a floor: det/layers.hpp), whose thin axes a region thicker than the layer leaves empty
// above and below by design (the fill put a second, offset membrane there). `depth`: the
// region's largest extent along the thin axes, which a query must reach across.
struct Reach {
    bool thin[3] = {false, false, false};
    double depth = 0.0;
    double distance(Vec3 d) const {
        for (int k = 0; k < 3; ++k)
            if (thin[k]) d[k] = 0.0;
        return norm(d);
    }
    template <class PositionOf, class Visit>
    void for_each_within(const core::DynamicGrid& grid, const Vec3& p, double r, const PositionOf& position,
                         const Visit& visit) const {
        grid.for_each_within(
            p, std::sqrt(r * r + depth * depth), position,
            [&](int i) {
                if (distance(position(i) - p) <= r) visit(i);
            });
    }
};

bool any_element_within(const Grower::Impl& g, const Reach& reach, const Vec3& p, double distance) {
    bool found = false;
    reach.for_each_within(
        g.grid, p, distance, [&](int i) { return g.out[i].p; }, [&](int) { found = true; });
    return found;
}

// The probe points no element comes within `distance` of, in lattice order.
std::vector<Vec3> unreached_points(const Grower::Impl& g, const Reach& reach, const Domain& region,
                                   double distance) {
    const std::vector<Vec3> probes = probe_points(region, kProbeStep * distance, g.metric.dimension);
    std::vector<char> empty(probes.size(), 0);
    core::parallel_for(
        static_cast<int>(probes.size()), g.threads,
        [&](int begin, int end, int thread) {
            for (int k = begin; k < end; ++k) {
                g.interrupt.check(thread);
                empty[k] = !any_element_within(g, reach, probes[k], distance);
            }
        },
        256);
    std::vector<Vec3> out;
    for (size_t k = 0; k < probes.size(); ++k)
        if (empty[k]) out.push_back(probes[k]);
    return out;
}

// The part of the region to fill: within `distance` of an unreached point and at least
// kEdge spacings from every element.
Domain fill_domain(const Grower::Impl& g, const Reach& reach, const Domain& region,
                   const std::vector<Vec3>& unreached, double distance) {
    core::DynamicGrid near(distance, g.metric.dimension);
    for (size_t k = 0; k < unreached.size(); ++k) near.insert(static_cast<int>(k), unreached[k]);
    const double edge = kEdge * g.metric.params.spacing;
    const Box b = region.bounds();
    double cells = 1.0;
    for (int k = 0; k < g.metric.dimension; ++k) cells *= std::max(b.hi[k] - b.lo[k], 1e-12);
    double cell = kFillCell * g.metric.params.spacing;
    cell = std::max(cell, std::pow(cells / kMaxFillCells, 1.0 / g.metric.dimension));
    return Domain::region(
        region,
        [&](const Vec3& p) {
            bool close = false;
            reach.for_each_within(
                near, p, distance, [&](int k) { return unreached[k]; }, [&](int) { close = true; });
            return close && !any_element_within(g, reach, p, edge);
        },
        cell, "uncovered");
}

DetOptions det_options(const Grower::Impl& g) {
    DetOptions o;
    o.radius = g.metric.params.radius;
    o.k = std::max(1, std::min(g.options.k, 8));
    o.threads = g.threads;
    o.seed = g.options.seed;
    o.field = g.options.field;
    return o;
}

// Appends the session's unlocked elements (the fill) that lie in the region as growth
// counts it (every sample; the centre of an open region's) and on a registered layer to
// the grower as kept elements: fixed for later rounds, not locked for the caller. The
// session keeps centres in its domain, and a lipid at the region's side poked its tail
// out. Returns how many.
int adopt_unlocked(Grower::Impl& g, const Arrangement& filled, const Domain& region) {
    if (g.existing.types.empty()) {
        g.existing.dimension = g.exemplar.dimension;
        g.existing.types = g.exemplar.types;
        g.existing.attribute_names = g.exemplar.attribute_names;
    }
    int added = 0;
    for (const Element& e : filled.elements) {
        if (e.locked) continue;
        std::vector<Vec3> samples(e.sample_count);
        for (int s = 0; s < e.sample_count; ++s) samples[s] = filled.samples[e.first_sample + s].p;
        const Vec3 centre = element_centroid(filled, e);
        if (g.open_region ? !region.inside(centre)
                          : !std::all_of(samples.begin(), samples.end(), [&](const Vec3& p) { return region.inside(p); }))
            continue;
        if (!g.on_layer(e.type, centre)) continue;  // the session fills the region as a volume
        const int index = g.existing.add_element(e.type, samples, e.radius);
        Element& kept = g.existing.elements[index];
        kept.position = e.position;
        kept.orientation = e.orientation;
        kept.scale = e.scale;
        kept.attributes = e.attributes;
        OutElement o;
        o.p = element_centroid(g.existing, kept);
        o.type = e.type;
        o.kept = index;
        o.locked = true;
        o.filled = true;
        o.frame = e.orientation;
        o.born = g.round;
        o.id = g.next_id++;
        g.add(o);
        ++added;
    }
    return added;
}

}  // namespace

double uncovered_distance(const Grower::Impl& g) {
    const double hole = g.hole_radius > 0.0
                            ? g.hole_radius
                            : det::exemplar_hole_radius(g.exemplar, g.metric.params.spacing, g.metric.params.radius);
    return 2.0 * hole + g.metric.params.spacing;
}

int fill_uncovered(Grower::Impl& g, const Domain& region, const Arrangement& current) {
    if (g.out.empty()) return 0;
    const double distance = uncovered_distance(g);
    Reach reach;
    const det::LayerAxes layer =
        det::layer_axes(g.exemplar.domain.bounds(), g.metric.dimension, g.metric.params.radius);
    if (layer.any) {
        // A field turns the layer's normal from place to place: no one plane to measure in.
        if (g.options.field.active()) return 0;
        const Box b = region.bounds();
        for (int k = 0; k < 3; ++k)
            if (layer.thin[k]) reach.thin[k] = true, reach.depth = std::max(reach.depth, b.hi[k] - b.lo[k]);
    }
    if (g.layer_registered) {  // growth's own layer (Impl::layer): a membrane, thicker than r
        const Box b = region.bounds();
        for (int k = 0; k < 3; ++k)
            if (g.layer[k]) reach.thin[k] = true, reach.depth = std::max(reach.depth, b.hi[k] - b.lo[k]);
    }
    const std::vector<Vec3> unreached = unreached_points(g, reach, region, distance);
    if (unreached.empty()) return 0;
    const Domain fill = fill_domain(g, reach, region, unreached, distance);
    DetSession session(g.exemplar, det_options(g));
    session.set_progress([&g](const ProgressEvent& e) {
        ProgressEvent f = e;
        f.stage = "uncovered";
        f.fraction = 0.99;
        f.elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - g.t0).count();
        g.last_event = f;
        return !g.progress || g.progress(f);
    });
    Arrangement start = current;
    for (Element& e : start.elements) e.locked = true;
    session.set_arrangement(start);
    session.set_domain(region);
    if (session.initialize(fill) == 0) return 0;
    session.iterate(fill, DetOptions{}.iterations);
    return adopt_unlocked(g, session.arrangement(), region);
}

}  // namespace tessera::grow
