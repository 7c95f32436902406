// A covered region thinned back to the exemplar's density (grow/thinning.hpp).
#include "grow/thinning.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <queue>

#include "core/parallel.hpp"
#include "grow/ball_lattice.hpp"
#include "grow/rare_types.hpp"
#include "grow/sample_index.hpp"
#include "grow/vacancies.hpp"
#include "tessera/metrics.hpp"

namespace tessera::grow {

namespace {

// The crowding disk (ball): this many mean spacings, as the count ceiling's.
constexpr double kRadius = 4.0;
// The surplus a region may keep: this share of its expected count plus kDeviations times
// the count's Poisson deviation (a pattern's own fluctuation at the region's size).
constexpr double kTolerance = 0.02;
constexpr double kDeviations = 2.0;
// A world's tile keeps less: its count is final once it is made (later tiles add to theirs
// only), and growth overfills an inhibited pattern in every tile (cells 1.15x, Swedish pines
// 1.13x, anemones 1.09x over a 4 x 4-tile world), which two deviations of a tile's count
// (13 for the cells' 42) let stand. With half a deviation: 1.03x, 1.00x, 1.00x.
constexpr double kTileDeviations = 0.5;
// Tiles of a clumped exemplar are not thinned: their counts vary more than a Poisson
// pattern's by nature, and thinning the crowded ones takes the clusters apart (the redwood
// world's PCF error 0.23 -> 0.36). Clumped: its elements have more neighbours within one
// mean spacing than a Poisson pattern of its density, by this factor (redwood 2.0; the
// other spatstat patterns 0.61 to 0.95).
constexpr double kClumped = 1.2;
// Points per axis of the lattice that measures the share of a disk inside the region.
constexpr int kLattice = 8;
// The pattern search for the hole a removal leaves: at most this many steps, until the step
// is under this share of the exemplar's largest hole.
constexpr int kSearchSteps = 40;
// Elements per chunk of the parallel test of each removal on its own.
constexpr int kTriedPerChunk = 32;
constexpr double kSearchEnd = 0.02;


// The elements whose centre lies in the region, flagged per element of g.out.
std::vector<int> elements_in(const Grower::Impl& g, const Domain& region, std::vector<char>& in_region) {
    const Box& b = region.bounds();
    Vec3 half = (b.hi - b.lo) * 0.5;
    if (g.metric.dimension == 2) half.z = 0.0;
    std::vector<int> near, inside;
    g.grid.query(
        b.center(), norm(half) + 1e-9, [&](int i) { return g.out[i].p; }, near);
    in_region.assign(g.out.size(), 0);
    for (const int i : near)
        if (region.inside(g.out[i].p)) in_region[i] = 1, inside.push_back(i);
    std::sort(inside.begin(), inside.end());
    return inside;
}

double rim_of(const Grower::Impl& g, int j) {
    const OutElement& o = g.out[j];
    return o.kept >= 0 ? g.existing.elements[o.kept].radius : g.exemplar.elements[o.source].radius;
}

// Climbs `clearance` from `start` by a pattern search (steps from `step`, halved when no
// neighbour of the point is clearer) until it passes `depth`; returns whether it did.
template <class Clearance>
bool climbs_past(const Clearance& clearance, Vec3 c, double step, double depth, int dimension) {
    const double end = step * 2.0 * kSearchEnd;
    double here = clearance(c);
    for (int k = 0; k < kSearchSteps && here <= depth && step > end; ++k) {
        Vec3 best_at = c;
        double best = here;
        for (int a = 0; a < (dimension == 2 ? 8 : 26); ++a) {
            Vec3 dir = dimension == 2 ? Vec3{std::cos(a * std::numbers::pi / 4), std::sin(a * std::numbers::pi / 4), 0.0}
                                      : Vec3{(a % 3) - 1.0, ((a / 3) % 3) - 1.0, (a / 9) - 1.0};
            if (dimension == 3) {
                if (a == 13) continue;  // the centre of the 3 x 3 x 3 block
                dir = dir * (1.0 / norm(dir));
            }
            const Vec3 q = c + dir * step;
            const double there = clearance(q);
            if (there > depth) return true;  // the climb would step there and stop
            if (there > best) best = there, best_at = q;
        }
        if (best > here)
            c = best_at, here = best;
        else
            step *= 0.5;
    }
    return here > depth;
}

// Whether removing element i (and those `gone` says) would open a hole the covered-hole fill
// (grow/vacancies.hpp) puts an element back in: from i's place, a pattern search climbs the
// rim-to-rim clearance to the centre of the hole i leaves, and that hole is deeper than
// kCoveredHoleDepth times the exemplar's largest. Removing an element of an even pattern's
// lattice opens one (cells: a hole 1.6x the exemplar's); one of a pair squeezed together
// does not.
template <class Gone>
bool opens_hole(const Grower::Impl& g, int i, double max_rim, const Gone& gone) {
    const double depth = kCoveredHoleDepth * g.hole_radius;
    auto clearance = [&](const Vec3& c) {
        double best = depth + 1.0;
        g.grid.for_each_within(
            c, depth + 1.0 + max_rim, [&](int j) { return g.out[j].p; }, [&](int j) {
                if (!gone(j)) best = std::min(best, norm(g.out[j].p - c) - rim_of(g, j));
            });
        return best;
    };
    return climbs_past(clearance, g.out[i].p, 0.5 * g.hole_radius, depth, g.metric.dimension);
}

// The removal test of multi-sample elements: removing one must not open a place farther
// than kCoveredHoleDepth times the exemplar's largest empty circle (over samples) from every
// remaining sample. The search starts from the removed element's sample (or centre) that is
// farthest from the others, and only when that one is already over half the limit: a
// surplus of hundreds of thousands of rods (B6) cannot pay a search each. Removing rods by
// the clearance at their own samples only left holes 1.44x the exemplar's (1.15x before).
class SampleClearance {
public:
    SampleClearance(const Grower::Impl& g, double hole)
        : g_(g), hole_(hole), limit_(kCoveredHoleDepth * hole), samples_(g, hole) {}
    // Capped just past the limit: whether a place passes it is all the search asks.
    template <class Gone>
    bool opens_hole(int i, const Gone& gone, std::vector<Vec3>& buffer) const {
        const double cap = limit_ * 1.01;
        const auto clearance = [&](const Vec3& q) {
            double best = cap;
            samples_.for_each_within(q, cap, [&](int s) {
                if (!gone(samples_.owner(s))) best = std::min(best, norm(samples_.at(s) - q));
            });
            return best;
        };
        samples_.samples_of(i, buffer);
        buffer.push_back(g_.out[i].p);
        Vec3 start = buffer.front();
        double deepest = -1.0;
        for (const Vec3& q : buffer)
            if (const double c = clearance(q); c > deepest) deepest = c, start = q;
        if (deepest > limit_) return true;
        if (deepest <= 0.5 * limit_) return false;
        return climbs_past(clearance, start, 0.5 * hole_, limit_, g_.metric.dimension);
    }

private:
    const Grower::Impl& g_;
    double hole_, limit_;
    SampleIndex samples_;
};

// The exemplar's mean count of neighbours within one mean spacing (its density's), over
// those elements whose ball of that radius lies in its bounds, against a Poisson pattern's.
double clumping(const Exemplar& ex, int dimension) {
    const double n = static_cast<double>(ex.elements.size());
    const double measure = ex.domain.measure();
    if (n < 2 || !(measure > 0.0)) return 1.0;
    const double rho = std::pow(measure / n, 1.0 / dimension);
    core::DynamicGrid grid(rho, dimension);
    for (size_t i = 0; i < ex.elements.size(); ++i) grid.insert(static_cast<int>(i), ex.elements[i].position);
    const Box b = ex.domain.bounds();
    double pairs = 0.0, counted = 0.0;
    for (size_t i = 0; i < ex.elements.size(); ++i) {
        const Vec3& p = ex.elements[i].position;
        bool inner = true;
        for (int k = 0; k < dimension; ++k) inner = inner && p[k] - b.lo[k] >= rho && b.hi[k] - p[k] >= rho;
        if (!inner) continue;
        counted += 1.0;
        grid.for_each_within(
            p, rho, [&](int j) { return ex.elements[j].position; }, [&](int j) { pairs += j != static_cast<int>(i); });
    }
    if (counted == 0.0) return 1.0;
    const double ball = dimension == 3 ? 4.0 / 3.0 * std::numbers::pi : std::numbers::pi;  // times rho^d = measure / n
    return (pairs / counted) / ball;
}

}  // namespace

int thin_to_density(Grower::Impl& g, int first, const Domain& region) {
    const bool by_samples = !g.fills_holes;  // multi-sample elements
    if (by_samples && !g.bounds.has_samples) return 0;
    if (g.open_region) {  // a world's tile: single-sample exemplars that do not clump
        if (by_samples) return 0;
        // A packing's count is its hard core's and its completion's (rare_types.hpp):
        // thinned, the 3D spheres' tiles crowded where the hole fill after it refilled them.
        for (int t = 0; t < static_cast<int>(g.exemplar.types.size()); ++t)
            if (packed(g, t)) return 0;
        if (!g.clumping) g.clumping = clumping(g.exemplar, g.metric.dimension);
        if (*g.clumping > kClumped) return 0;
    }
    double density = 0.0;
    for (const double d : g.metric.params.type_density) density += d;
    if (!(density > 0.0)) return 0;
    const double expected = density * region.measure();
    std::vector<char> in_region;
    const std::vector<int> inside = elements_in(g, region, in_region);
    const double deviations = g.open_region ? kTileDeviations : kDeviations;
    const double allowed = expected * (1.0 + kTolerance) + deviations * std::sqrt(expected);
    if (static_cast<double>(inside.size()) <= allowed) return 0;
    // Per type, the count the region asks for: what is left above it may go.
    const size_t types = g.exemplar.types.size();
    std::vector<double> keep(types, 0.0);
    for (const Element& e : g.exemplar.elements)
        keep[e.type] += std::round(expected) / static_cast<double>(g.exemplar.elements.size());
    std::vector<int> count(types, 0);
    for (const int i : inside) ++count[g.out[i].type];
    // Edge-corrected counts within R (the disk's share inside the region).
    const int d = g.metric.dimension;
    const double radius = kRadius * std::pow(density, -1.0 / d);
    const std::vector<Vec3> lattice = unit_ball_lattice(d, kLattice);
    std::vector<double> crowd(g.out.size(), 0.0), weight(g.out.size(), 0.0);
    for (const int i : inside) {
        g.interrupt.check(0);
        int points = 0;
        for (const Vec3& u : lattice) points += region.inside(g.out[i].p + u * radius) ? 1 : 0;
        weight[i] = static_cast<double>(lattice.size()) / std::max(1, points);
    }
    auto removable = [&](int i) { return i >= first && !g.out[i].locked; };
    std::priority_queue<std::pair<double, int>> most_crowded;  // ties: the lower index first
    for (const int i : inside) {
        g.grid.for_each_within(
            g.out[i].p, radius, [&](int j) { return g.out[j].p; },
            [&](int j) { crowd[i] += j != i && in_region[j] ? weight[i] : 0.0; });
        if (removable(i)) most_crowded.push({crowd[i], -i});
    }
    double max_rim = 0.0;
    for (const OutElement& o : g.out) max_rim = std::max(max_rim, rim_of(g, static_cast<int>(&o - g.out.data())));
    std::optional<SampleClearance> samples;
    if (by_samples) {
        const double hole = largest_empty_circle(g.exemplar, g.threads).radius;
        if (!(hole > 0.0)) return 0;
        samples.emplace(g, hole);
    }
    const auto opens = [&](int i, const auto& gone, std::vector<Vec3>& buffer) {
        return samples ? samples->opens_hole(i, gone, buffer) : opens_hole(g, i, max_rim, gone);
    };
    // Removing more elements only widens a hole, so one that removing i alone opens stays:
    // those i are found first, in parallel (most of the most crowded are such: 97% of the
    // rods tried), and skipped by the sequential loop below.
    std::vector<int> tried;
    for (const int i : inside)
        if (removable(i)) tried.push_back(i);
    std::vector<char> opens_alone(g.out.size(), 0);
    core::parallel_for(
        static_cast<int>(tried.size()), g.threads,
        [&](int begin, int end, int thread) {
            std::vector<Vec3> buffer;
            for (int k = begin; k < end; ++k) {
                g.interrupt.check(thread);
                const int i = tried[k];
                opens_alone[i] = opens(i, [i](int j) { return j == i; }, buffer) ? 1 : 0;
            }
        },
        kTriedPerChunk);
    std::vector<Vec3> buffer;
    std::vector<char> removed(g.out.size() - first, 0);
    const int surplus = static_cast<int>(inside.size() - std::lround(expected));
    int gone = 0;
    while (gone < surplus && !most_crowded.empty()) {
        const auto [c, minus_i] = most_crowded.top();
        most_crowded.pop();
        const int i = -minus_i;
        if (c != crowd[i] || removed[i - first] || !(count[g.out[i].type] > keep[g.out[i].type])) continue;
        if (opens_alone[i]) continue;
        const auto gone_after = [&](int j) { return j == i || (removable(j) && removed[j - first]); };
        if (opens(i, gone_after, buffer)) continue;
        removed[i - first] = 1;
        --count[g.out[i].type];
        ++gone;
        g.grid.for_each_within(
            g.out[i].p, radius, [&](int j) { return g.out[j].p; }, [&](int j) {
                if (j == i || !in_region[j] || (removable(j) && removed[j - first])) return;
                crowd[j] -= weight[j];
                if (removable(j)) most_crowded.push({crowd[j], -j});
            });
    }
    if (gone > 0) g.remove_and_renumber(first, removed);
    return gone;
}

}  // namespace tessera::grow
