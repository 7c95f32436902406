// The pair-correlation relaxation of a grow(region) call's elements (grow/relax.hpp).
#include "grow/relax.hpp"

#include <algorithm>
#include <chrono>

#include "det/pair_relaxation.hpp"
#include "grow/repair.hpp"
#include "grow/vacancies.hpp"
#include "tessera/error.hpp"

namespace tessera::grow {

namespace {

// Whether element i has an element outside the region within `distance`.
bool near_outside(const Grower::Impl& g, int i, const Domain& region, double distance) {
    bool near = false;
    g.grid.for_each_within(
        g.out[i].p, distance, [&](int j) { return g.out[j].p; },
        [&](int j) { near = near || !region.inside(g.out[j].p); });
    return near;
}

}  // namespace

void relax_pair_correlation(Grower::Impl& g, const Domain& region, int first, GrowReport& out, int extra_sweeps) {
    if (!g.relaxation || !g.relaxation->applies()) return;
    // Outside elements are not in the relaxation's sums or its hard-core checks: an element
    // that could come within the largest hard core of one in its sweeps stays.
    const int sweeps = g.relax_sweeps + extra_sweeps;
    const double drift = sweeps * g.relaxation->max_step(), seam = drift + g.reach;
    const double edge_band = std::max(2.0 * drift, g.metric.params.spacing);
    Arrangement a;
    a.dimension = g.exemplar.dimension;
    a.types = g.exemplar.types;
    std::vector<int> index;
    std::vector<char> held;
    bool any_free = false;
    for (int i = 0; i < static_cast<int>(g.out.size()); ++i) {
        const OutElement& o = g.out[i];
        if (!region.inside(o.p)) continue;
        const double radius = o.kept >= 0 ? g.existing.elements[o.kept].radius : g.exemplar.elements[o.source].radius;
        a.add_element(o.type, {o.p}, radius);
        // The elements within a spacing (or twice the sweeps' reach) of the region's edge
        // stay too: the estimator's edge correction does not see a gap opening between them
        // and the edge (a lattice's border row drifted inward and left a hole 1.2x to 1.3x
        // the exemplar's).
        const bool stays = i < first || (o.locked && !o.filled) || region.distance_to_boundary(o.p) < edge_band ||
                           near_outside(g, i, region, seam);
        held.push_back(stays ? 1 : 0);
        index.push_back(i);
        any_free = any_free || !stays;
    }
    if (!any_free) return;
    const det::PairRelaxation::Report report =
        g.relaxation->relax(a, region, held, sweeps, g.options.seed, g.threads, [&](int sweep) {
            ProgressEvent e = g.last_event;
            e.stage = "relax";
            e.iteration = sweep;
            e.iterations = sweeps;
            e.elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - g.t0).count();
            g.last_event = e;
            if (g.progress && !g.progress(e)) throw Cancelled();
        }, &g.interrupt);
    std::vector<int> moved;
    for (size_t k = 0; k < index.size(); ++k)
        if (!held[k] && !(a.elements[k].position == g.out[index[k]].p)) {
            g.move(index[k], a.elements[k].position);
            moved.push_back(index[k]);
        }
    // As synthesize_det's final passes: the relaxation keeps the closest pair, not the
    // exemplar's share of close pairs (a crowding repair restores it), and may open a hole.
    out.relaxed += report.moves;
    if (moved.empty()) return;
    repair_round(g, moved, &region);
    const int filled = fill_enclosed_holes_around(g, moved, &region);
    out.filled += filled;
    out.added += filled;
}

}  // namespace tessera::grow
