// The counterpart of fill_holes: where patches meet, both may fill the same place, and the
// copy can hold more elements than the exemplar's density asks for (up to 5-10% more on
// the real datasets of the shared data). Such seam pairs also break the exemplar's
// inhibition distance, which shows in the output's pair correlation at short range.
// While a type holds more than its count (its exemplar density where the elements are,
// det/density.hpp, times the output's measure), its most crowded element is removed if it is crowded at all (fill_holes then
// adds what the types below their counts lack): crowding =
// min over neighbours j of d_ij / (the distance from an element of type(i) to its nearest
// of type(j) that only one in ten exemplar elements undercuts). Elements at the
// exemplar's usual distances stay even when the count is still high: removing them
// would take members out of legitimate clusters (a clustered pattern's cores are
// "crowded" by any mean), which costs more than a few percent of density.
// Lazy re-ranking: a removal only makes other elements less crowded.
#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "core/spatial_grid.hpp"
#include "det/init.hpp"
#include "det/layers.hpp"

namespace tessera::det {
namespace {

constexpr double reach_in_spacings = 3.0;  // neighbours farther than this never crowd
constexpr double close_quantile = 0.1;
// An exemplar has an empty margin when no element comes nearer its boundary than this many spacings.
constexpr double kMarginSpacings = 0.25;
// Output elements nearer a side than this share of the exemplar's margin there are dropped.
constexpr double kMarginShare = 0.25;

// A low quantile (close_quantile) of the distances from elements of type a to their
// nearest element of type b (within the reach), per ordered pair (a, b) as
// [a * types + b]: closer than this, a pair is rarer in the exemplar than one in ten.
// Infinity where the exemplar never shows b that close to a.
std::vector<double> close_distance(const Exemplar& exemplar, int dimension, double reach) {
    const int types = static_cast<int>(exemplar.types.size());
    const std::vector<Vec3> p = element_centroids(exemplar.elements, dimension);
    core::SpatialGrid grid;
    grid.build(p, reach / 2.0, dimension);
    std::vector<std::vector<double>> distances(static_cast<size_t>(types) * types);
    std::vector<double> nearest(types);
    for (size_t i = 0; i < p.size(); ++i) {
        std::fill(nearest.begin(), nearest.end(), std::numeric_limits<double>::infinity());
        grid.for_each_within(p[i], reach, [&](int j, double d2) {
            if (static_cast<size_t>(j) == i) return;
            double& best = nearest[exemplar.elements[j].type];
            best = std::min(best, std::sqrt(d2));
        });
        const int a = exemplar.elements[i].type;
        for (int b = 0; b < types; ++b)
            if (std::isfinite(nearest[b])) distances[a * types + b].push_back(nearest[b]);
    }
    std::vector<double> result(distances.size(), std::numeric_limits<double>::infinity());
    for (size_t k = 0; k < distances.size(); ++k) {
        std::vector<double>& d = distances[k];
        if (d.empty()) continue;
        const size_t q = static_cast<size_t>(close_quantile * static_cast<double>(d.size() - 1));
        std::nth_element(d.begin(), d.begin() + static_cast<long>(q), d.end());
        if (d[q] > 0.0) result[k] = d[q];
    }
    return result;
}

}  // namespace

int thin_crowds(Provenance of, const Exemplar& exemplar, const Domain& domain, const Params& params,
                double hole_radius, double crowded_below, double allowance) {
    Arrangement& out = of.out;
    const int dim = params.dimension;
    const int types = static_cast<int>(exemplar.types.size());
    if (!(params.spacing > 0.0)) return 0;

    std::vector<long> count(types, 0), target(types, 0);
    for (int t = 0; t < types; ++t) target[t] = std::lround(params.type_density[t] * domain.measure() * (1.0 + allowance));
    for (const Element& e : out.elements) ++count[e.type];
    bool any_over = false;
    for (int t = 0; t < types; ++t) any_over = any_over || count[t] > target[t];
    if (!any_over) return 0;

    const double reach = reach_in_spacings * params.spacing;
    const std::vector<double> close = close_distance(exemplar, dim, reach);
    const std::vector<Vec3> p = element_centroids(out.elements, dim);
    core::SpatialGrid grid;
    grid.build(p, reach / 2.0, dim);
    std::vector<char> keep(out.elements.size(), 1);
    auto crowding = [&](int i) {
        double score = std::numeric_limits<double>::infinity();
        const int a = out.elements[i].type;
        grid.for_each_within(p[i], reach, [&](int j, double d2) {
            if (j == i || !keep[j]) return;
            const double ref = close[a * types + out.elements[j].type];
            if (std::isfinite(ref)) score = std::min(score, std::sqrt(d2) / ref);
        });
        return score;
    };

    // The hole an element leaves: the largest clearance among the elements kept, found by a
    // pattern search from its place (the hole's centre need not be the element's).
    // (For a layered exemplar the walls of the thin axis do not bound a hole: see vacancies.hpp.)
    const bool layered = layer_axes(exemplar.domain.bounds(), dim, params.radius).any;
    auto clearance_without = [&](int i, const Vec3& c) {
        double clearance = layered ? (domain.inside(c) ? reach : -1.0) : std::min(reach, domain.distance_to_boundary(c));
        grid.for_each_within(c, reach, [&](int j, double d2) {
            if (j != i && keep[j]) clearance = std::min(clearance, std::sqrt(d2) - out.elements[j].radius);
        });
        return clearance;
    };
    auto hole_left = [&](int i) {
        Vec3 c = p[i];
        double best = clearance_without(i, c);
        for (double h = 0.25 * params.spacing; h > params.spacing / 64.0; h *= 0.5)
            for (bool moved = true; moved;) {
                moved = false;
                for (int k = 0; k < dim; ++k)
                    for (double sign : {-1.0, 1.0}) {
                        Vec3 q = c;
                        q[k] += sign * h;
                        const double d = clearance_without(i, q);
                        if (d > best + 1e-12) best = d, c = q, moved = true;
                    }
            }
        return best;
    };

    // (crowding, -index): most crowded first; of a crowded pair the later copy (the seam
    // newcomer, or the later insertion) goes.
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
    for (size_t i = 0; i < out.elements.size(); ++i) {
        const int t = out.elements[i].type;
        if (count[t] > target[t] && !out.elements[i].locked) heap.emplace(crowding(static_cast<int>(i)), -static_cast<int>(i));
    }
    int removed = 0;
    while (!heap.empty()) {  // bounded: every element leaves the heap at most once per re-rank
        const auto [score, negative_index] = heap.top();
        if (score >= crowded_below) break;  // nobody crowded enough is left
        heap.pop();
        const int i = -negative_index;
        const int t = out.elements[i].type;
        if (count[t] <= target[t]) continue;  // its type is full: it stays (types only lose elements)
        const double fresh = crowding(i);
        if (fresh > score) {  // a neighbour was removed since: re-rank
            heap.emplace(fresh, -i);
            continue;
        }
        if (hole_radius > 0.0 && hole_left(i) > hole_radius) continue;  // it would leave a hole
        keep[i] = 0;
        --count[t];
        ++removed;
    }
    if (removed > 0) keep_only(of, keep);
    return removed;
}

int remove_unresolved_crowding(Provenance of, const Domain& domain, const Params& params,
                               const core::CrowdingBounds& tails, const core::CrowdingRepairOptions& options) {
    const std::vector<core::CrowdedPair> crowded = core::crowded_pairs(of.out, tails, options);
    if (crowded.empty()) return 0;
    const int types = static_cast<int>(of.out.types.size());
    std::vector<long> count(types, 0), target(types, 0);
    for (int t = 0; t < types; ++t) target[t] = std::lround(params.type_density[t] * domain.measure());
    for (const Element& e : of.out.elements) ++count[e.type];
    std::vector<char> keep(of.out.elements.size(), 1);
    int removed = 0;
    // The later element of a pair goes (a newer copy or insertion), its partner stays.
    for (auto it = crowded.rbegin(); it != crowded.rend(); ++it) {
        const int e = std::max(it->element, it->neighbour), other = std::min(it->element, it->neighbour);
        const int t = of.out.elements[e].type;
        if (!keep[e] || !keep[other] || count[t] <= target[t] || of.out.elements[e].locked) continue;
        keep[e] = 0;
        --count[t];
        ++removed;
    }
    if (removed > 0) keep_only(of, keep);
    return removed;
}

int drop_beyond_margin(Provenance of, const Exemplar& exemplar, const Domain& domain, const Params& params) {
    // Box windows and box outputs only (a margin is a distance to a side; other shapes answer
    // distances conservatively), not layers (their thin axis is all margin), not physical
    // boundaries (floor constraints: elements rest on them).
    if (params.floor_constraints || exemplar.elements.empty() || exemplar.domain.kind() != Domain::Kind::box ||
        domain.kind() != Domain::Kind::box || layer_axes(exemplar.domain.bounds(), params.dimension, params.radius).any)
        return 0;
    const Box in = exemplar.domain.bounds(), out = domain.bounds();
    double margin[3][2] = {{INFINITY, INFINITY}, {INFINITY, INFINITY}, {INFINITY, INFINITY}};
    for (const Element& e : exemplar.elements)
        for (int k = 0; k < params.dimension; ++k) {
            margin[k][0] = std::min(margin[k][0], e.position[k] - in.lo[k]);
            margin[k][1] = std::min(margin[k][1], in.hi[k] - e.position[k]);
        }
    const double least = kMarginSpacings * params.spacing;
    std::vector<char> keep(of.out.elements.size(), 1);
    int dropped = 0;
    for (size_t e = 0; e < keep.size(); ++e) {
        const Element& el = of.out.elements[e];
        if (el.locked) continue;
        bool near = false;
        for (int k = 0; k < params.dimension; ++k)
            near = near || (margin[k][0] > least && el.position[k] - out.lo[k] < kMarginShare * margin[k][0]) ||
                   (margin[k][1] > least && out.hi[k] - el.position[k] < kMarginShare * margin[k][1]);
        if (near) keep[e] = 0, ++dropped;
    }
    if (dropped > 0) keep_only(of, keep);
    return dropped;
}

}  // namespace tessera::det
