// Closing the holes of PCF outputs (synth_holes.hpp): a lattice over the domain ranks the
// empty disks by their clearance (rim to rim, inside the domain) in a lazily updated
// heap, as det's vacancy filling does; into each one wider than the bound goes an element
// taken from where its class crowds most (its nearest neighbour of the same class the
// closest), so the class counts are kept. A few passes, each on the moved result.
#include "pcf/synth_holes.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>
#include <string>

#include "core/crowding_repair.hpp"
#include "core/empty_space.hpp"
#include "core/nearest_by_type.hpp"
#include "tessera/metrics.hpp"

namespace tessera::pcf {
namespace {

constexpr double kHoleTolerance = 1.2;  // holes wider than this x the exemplar's largest
constexpr int kPasses = 3;
constexpr double kMoveShare = 0.05;     // elements moved per pass at most, as a share of all

struct Donors {
    std::vector<std::vector<int>> of_type;  // per type: elements, the most crowded first
    std::vector<size_t> next;               // per type: the next one to try
};

// Per type, its elements ordered by the distance to their nearest neighbour of the same
// type, closest first: taking one from there opens no hole.
Donors crowded_first(const Arrangement& out, double reach) {
    const int types = static_cast<int>(out.types.size());
    const std::vector<Vec3> p = core::centroids_of(out);
    core::SpatialGrid grid;
    grid.build(p, reach, 2);
    const std::vector<double> nearest = core::nearest_by_type(out, p, grid, reach);
    Donors d;
    d.of_type.resize(types);
    d.next.assign(types, 0);
    for (size_t i = 0; i < out.elements.size(); ++i) d.of_type[out.elements[i].type].push_back(static_cast<int>(i));
    for (int t = 0; t < types; ++t)
        std::stable_sort(d.of_type[t].begin(), d.of_type[t].end(),
                         [&](int a, int b) { return nearest[a * types + t] < nearest[b * types + t]; });
    return d;
}

// The type to move into a hole at c, of depth `depth`: of the types whose disks fit and
// whose closest exemplar distances to the elements around c hold, the most numerous (its
// elements are the smallest loss where they are taken from); -1 when none fits.
int choose_type(const core::ObstacleGrid& grid, const core::CrowdingBounds& bounds, const std::vector<int>& to_exemplar,
                const std::vector<double>& radius, const std::vector<long>& count, const Vec3& c, double depth,
                double reach, std::vector<double>& nearest) {
    const int types = static_cast<int>(count.size());
    grid.nearest_by_tag(c, types, reach, nearest);
    int best = -1;
    for (int t = 0; t < types; ++t) {
        if (to_exemplar[t] < 0 || count[t] < 2 || radius[t] > depth) continue;
        bool fits = true;
        for (int b = 0; b < types && fits; ++b)
            if (to_exemplar[b] >= 0) fits = nearest[b] >= bounds.hard_core(to_exemplar[t], to_exemplar[b]);
        if (fits && (best < 0 || count[t] > count[best])) best = t;
    }
    return best;
}

struct PassResult {
    int moved = 0;
    bool bound_hit = false;
};

PassResult close_pass(const core::CrowdingBounds& bounds, const std::vector<int>& to_exemplar, const Domain& domain,
                      double hole, Arrangement& out) {
    PassResult result;
    const int types = static_cast<int>(out.types.size());
    const double spacing = std::sqrt(domain.measure() / static_cast<double>(out.elements.size()));
    std::vector<long> count(types, 0);
    std::vector<double> radius(types, 0.0);
    for (const Element& e : out.elements) ++count[e.type], radius[e.type] += e.radius;
    for (int t = 0; t < types; ++t) radius[t] = count[t] > 0 ? radius[t] / count[t] : 0.0;

    core::ObstacleGrid grid(domain.bounds(), spacing, 2);
    for (const Element& e : out.elements) grid.add(e.position, e.radius, e.type);
    // A lattice with a step of hole / (2 sqrt 2) has a point within a quarter of the hole's
    // radius of its centre, which the local search then finds.
    const double step = std::max(spacing / 4.0, 0.5 * hole / std::sqrt(2.0));
    const double slack = 0.5 * step * std::sqrt(2.0), cap = hole + 2.0 * slack;
    const std::vector<Vec3> candidates = core::lattice_inside(domain, 2, step);
    const auto clearance = [&](const Vec3& c) { return core::ball_clearance(grid, domain, c, cap); };
    std::priority_queue<std::pair<double, int>> heap;  // (clearance, -index): largest first, ties by index
    for (size_t i = 0; i < candidates.size(); ++i)
        if (const double d = clearance(candidates[i]); d > hole - slack) heap.emplace(d, -static_cast<int>(i));

    Donors donors = crowded_first(out, 4.0 * spacing);
    std::vector<char> taken(out.elements.size(), 0);
    const int bound = std::max(8, static_cast<int>(kMoveShare * static_cast<double>(out.elements.size())));
    std::vector<double> nearest;
    while (!heap.empty()) {
        const auto [ranked, negative] = heap.top();
        heap.pop();
        const double fresh = clearance(candidates[-negative]);
        if (fresh < ranked) {  // a move came near since: re-rank
            heap.emplace(fresh, negative);
            continue;
        }
        if (fresh + slack <= hole) break;  // no hole left
        double depth = fresh;
        const Vec3 c = core::hole_centre(candidates[-negative], 2, step, clearance, depth);
        if (depth <= hole) continue;
        const int type = choose_type(grid, bounds, to_exemplar, radius, count, c, depth, cap, nearest);
        if (type < 0) continue;
        // The most crowded element of the type not taken yet and not beside this hole.
        int donor = -1;
        for (size_t& k = donors.next[type]; k < donors.of_type[type].size() && donor < 0; ++k) {
            const int e = donors.of_type[type][k];
            if (!taken[e] && !out.elements[e].locked && norm(out.elements[e].position - c) > 3.0 * depth) donor = e;
        }
        if (donor < 0) continue;
        if (result.moved >= bound) {
            result.bound_hit = true;
            break;
        }
        Element& e = out.elements[donor];
        out.samples[e.first_sample].p = c;
        e.position = c;
        taken[donor] = 1;
        grid.add(c, e.radius, e.type);  // its old place stays an obstacle until the next pass
        ++result.moved;
    }
    return result;
}

}  // namespace

void close_holes(const Exemplar& exemplar, const Domain& domain, const PcfSynthOptions& options, Arrangement& out) {
    if (out.dimension != 2 || out.elements.size() < 2 || exemplar.elements.size() < 2) return;
    for (const Element& e : out.elements)
        if (e.sample_count != 1) return;  // the PCF method places single-sample disks
    const double hole = kHoleTolerance * largest_empty_circle(exemplar, options.threads).radius;
    if (!(hole > 0.0)) return;
    const core::CrowdingBounds bounds(exemplar);
    std::vector<int> to_exemplar(out.types.size());
    for (size_t t = 0; t < out.types.size(); ++t) to_exemplar[t] = exemplar.find_type(out.types[t].name);
    int moved = 0, passes = 0;
    bool bound_hit = false;
    for (; passes < kPasses; ++passes) {
        const PassResult pass = close_pass(bounds, to_exemplar, domain, hole, out);
        moved += pass.moved;
        bound_hit = pass.bound_hit;
        if (pass.moved == 0) break;
    }
    if (moved > 0)
        out.stats.notes.push_back("holes: " + std::to_string(moved) + " elements moved from crowded places into " +
                                  "empty disks wider than " + std::to_string(kHoleTolerance).substr(0, 3) +
                                  "x the exemplar's largest");
    if (bound_hit || passes == kPasses) {
        ++out.stats.solver_bound_hits;
        out.stats.notes.push_back("holes: stopped at the bound of " + std::to_string(kPasses) + " passes of at most " +
                                  std::to_string(static_cast<int>(kMoveShare * 100)) + "% of the elements each");
    }
}

}  // namespace tessera::pcf
