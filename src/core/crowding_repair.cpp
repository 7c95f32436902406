#include "core/crowding_repair.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>
#include <utility>

#include "core/parallel.hpp"
#include "core/rng.hpp"
#include "core/spatial_grid.hpp"

namespace tessera::core {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Points whose neighbour search is worth a thread: a growth round repairs parts of a few
// hundred elements many times, where starting threads would cost more than the search.
constexpr int kPointsPerThread = 2048;
// A pushed element lands this much beyond its bound, so rounding cannot leave it just short.
constexpr double kOvershoot = 1.02;
// The tail bounded per type pair holds at least this many of the exemplar's closest distances.
constexpr double kLeastOrder = 3.0;

// The inverse of the empirical distribution function (R's type 1): the smallest value with
// at least a share u of the values at or below it. A faithful copy of the exemplar then
// never breaks a bound: its k-th closest element is at or above the bound of rank k.
double lower_quantile(const std::vector<double>& sorted, double u) {
    if (sorted.empty()) return 0.0;
    const double position = std::ceil(std::clamp(u, 0.0, 1.0) * static_cast<double>(sorted.size())) - 1.0;
    return sorted[static_cast<size_t>(std::clamp(position, 0.0, static_cast<double>(sorted.size() - 1)))];
}

// The share of an ordered pair's distribution whose quantiles bound the output: `tail`,
// and at least three of the exemplar's distances beyond its closest ones and their ties.
double bounded_tail(const std::vector<double>& sorted, double tail) {
    if (sorted.empty()) return tail;
    const auto ties = std::upper_bound(sorted.begin(), sorted.end(), sorted.front()) - sorted.begin();
    return std::max(tail, (static_cast<double>(ties) + kLeastOrder) / static_cast<double>(sorted.size()));
}

// A sample closer to the nearest sample of another element of type b than its rank allows.
struct Violation {
    int sample = -1, neighbour = -1;  // sample indices
    double distance = 0.0, bound = 0.0;
};

// The points distances are measured between, and the element each belongs to.
struct PointView {
    std::vector<Vec3> p;
    std::vector<int> owner;
};

PointView points_of(const Exemplar& data, CrowdingLevel level) {
    PointView v;
    const auto flat = [&](Vec3 q) { return data.dimension == 2 ? Vec3{q.x, q.y, 0.0} : q; };
    if (level == CrowdingLevel::samples) {
        for (const Sample& s : data.samples) v.p.push_back(flat(s.p)), v.owner.push_back(s.element);
    } else {
        for (size_t e = 0; e < data.elements.size(); ++e)
            v.p.push_back(flat(data.elements[e].position)), v.owner.push_back(static_cast<int>(e));
    }
    return v;
}

// The violations of the current state: per ordered type pair, the points of a elements
// ranked by their distance to the nearest point of another b element, each against the
// exemplar quantile of its rank. Violations name points of `view`.
std::vector<Violation> find_violations(const Exemplar& data, const PointView& view,
                                       const NearestDistanceTails& tails, const CrowdingRepairOptions& o) {
    const int types = tails.types();
    const int n = static_cast<int>(view.p.size());
    std::vector<Violation> found;
    if (data.elements.size() < 2 || types == 0 || static_cast<int>(data.types.size()) != types) return found;
    const double reach = tails.reach(o.tail);
    if (!(reach > 0.0)) return found;
    SpatialGrid grid;
    grid.build(view.p, reach, data.dimension);
    const auto type_of = [&](int i) { return data.elements[view.owner[i]].type; };
    // Per point and type: the nearest point of another element of that type within reach.
    std::vector<int> nearest(static_cast<size_t>(n) * types, -1);
    std::vector<double> distance(static_cast<size_t>(n) * types, kInf);
    // Each point looks only as far as its own type's bounds reach: a violation is closer than
    // its pair's tail distance, and the points beyond it rank after every violation, so
    // leaving them out changes no rank (a rare big class no longer makes everyone look far).
    std::vector<double> type_reach(types);
    for (int a = 0; a < types; ++a) type_reach[a] = tails.reach(a, o.tail);
    parallel_for(
        n, resolve_threads(o.threads),
        [&](int begin, int end, int) {
            for (int i = begin; i < end; ++i)
                grid.for_each_within(view.p[i], type_reach[type_of(i)], [&](int j, double d2) {
                    if (view.owner[j] == view.owner[i]) return;
                    const size_t slot = static_cast<size_t>(i) * types + type_of(j);
                    const double d = std::sqrt(d2);
                    if (d < distance[slot] || (d == distance[slot] && j < nearest[slot]))
                        distance[slot] = d, nearest[slot] = j;
                });
        },
        kPointsPerThread);
    std::vector<long> count(types, 0);
    for (int i = 0; i < n; ++i) ++count[type_of(i)];
    // (distance, the pair's lower point, the point): the two ends of a mutual pair are
    // adjacent in the ranking, so a share of close pairs the exemplar allows stays whole.
    std::vector<std::tuple<double, int, int>> ranked;
    for (int a = 0; a < types; ++a)
        for (int b = 0; b < types; ++b) {
            if (tails.distances(a, b).empty() || count[a] == 0) continue;
            ranked.clear();
            for (int i = 0; i < n; ++i)
                if (type_of(i) == a && nearest[static_cast<size_t>(i) * types + b] >= 0)
                    ranked.emplace_back(distance[static_cast<size_t>(i) * types + b],
                                        std::min(i, nearest[static_cast<size_t>(i) * types + b]), i);
            std::sort(ranked.begin(), ranked.end());
            // The bounded tail: the `tail` share, and at least three of the exemplar's distances
            // beyond its closest ones and their ties (a small exemplar's lowest quantiles are its
            // few closest pairs; coincident pairs make many ties at 0).
            const double tail = bounded_tail(tails.distances(a, b), o.tail);
            // Beyond the tail's share every point must lie beyond the tail's distance.
            const double tail_distance = tails.quantile(a, b, tail);
            for (size_t k = 0; k < ranked.size(); ++k) {
                const double u = static_cast<double>(k + 1) / (static_cast<double>(count[a]) * o.slack);
                if (u > tail && std::get<0>(ranked[k]) >= tail_distance) break;
                const double bound = u > tail ? tail_distance : tails.quantile(a, b, u);
                const auto [d, lower, i] = ranked[k];
                if (d < bound * (1.0 - 1e-9))
                    found.push_back({i, nearest[static_cast<size_t>(i) * types + b], d, bound});
            }
        }
    return found;
}

Vec3 separation_direction(const Exemplar& data, int i, int j);

// The element moves that resolve `found` (points of `view`): each violating point is pushed
// away from its too-close neighbour (half when the violation is mutual), and an element
// moves by the mean of its points' pushes. Adds into shift/shifts.
void add_moves(const Exemplar& data, const PointView& view, const std::vector<Violation>& found,
               const CrowdingRepairOptions& o, std::vector<Vec3>& shift, std::vector<int>& shifts) {
    std::map<std::pair<int, int>, int> pairs;
    for (const Violation& v : found) ++pairs[{v.sample, v.neighbour}];
    for (const Violation& v : found) {
        const int e = view.owner[v.sample], other = view.owner[v.neighbour];
        if (data.elements[e].locked) continue;
        const bool shared = pairs.count({v.neighbour, v.sample}) > 0 && !data.elements[other].locked;
        Vec3 away = view.p[v.sample] - view.p[v.neighbour];
        const double length = norm(away);
        away = length > 1e-12 * v.bound ? away * (1.0 / length) : separation_direction(data, e, other);
        const double gap = (v.bound * kOvershoot - v.distance) * (shared ? 0.5 : 1.0);
        Vec3 move = away * gap;
        if (!o.held_level.empty() && o.held_level[e]) move -= o.level_axis * dot(move, o.level_axis);
        shift[e] += move;
        ++shifts[e];
    }
}

// A unit direction for a coincident pair, the same for any thread count; i and j get
// opposite ones.
Vec3 separation_direction(const Exemplar& data, int i, int j) {
    const KeyedRng rng(0x7e55e7a, Purpose::tie_break, static_cast<std::uint64_t>(std::min(i, j)),
                       static_cast<std::uint64_t>(std::max(i, j)));
    Vec3 v;
    if (data.dimension == 2) {
        const double angle = 2.0 * 3.14159265358979323846 * rng.uniform(0);
        v = {std::cos(angle), std::sin(angle), 0.0};
    } else {
        const double z = 2.0 * rng.uniform(0) - 1.0, angle = 2.0 * 3.14159265358979323846 * rng.uniform(1);
        const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
        v = {s * std::cos(angle), s * std::sin(angle), z};
    }
    return i < j ? v : -v;
}

// Moves element e by `shift` if all its samples stay inside; else by half of it; else not.
bool move_element(Exemplar& data, int e, const Vec3& shift, const Domain& domain) {
    Element& el = data.elements[e];
    for (double f : {1.0, 0.5}) {
        const Vec3 s = shift * f;
        bool inside = true;
        for (int k = 0; k < el.sample_count && inside; ++k)
            inside = domain.inside(data.samples[el.first_sample + k].p + s);
        if (!inside) continue;
        for (int k = 0; k < el.sample_count; ++k) data.samples[el.first_sample + k].p += s;
        el.position += s;
        return true;
    }
    return false;
}

}  // namespace

NearestDistanceTails::NearestDistanceTails(const Exemplar& exemplar, CrowdingLevel level)
    : level_(level), types_(static_cast<int>(exemplar.types.size())) {
    sorted_.assign(static_cast<size_t>(types_) * types_, {});
    if (exemplar.elements.size() < 2) return;
    const PointView view = points_of(exemplar, level);
    const std::vector<Vec3>& p = view.p;
    // Every distance, whatever its length: the exemplar is small.
    Vec3 lo = p[0], hi = p[0];
    for (const Vec3& q : p)
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], q[k]), hi[k] = std::max(hi[k], q[k]);
    const double diagonal = norm(hi - lo) * 1.001 + 1e-300;
    SpatialGrid grid;
    grid.build(p, std::max(diagonal / 32.0, 1e-300), exemplar.dimension);
    std::vector<double> nearest(types_);
    for (size_t i = 0; i < p.size(); ++i) {
        std::fill(nearest.begin(), nearest.end(), kInf);
        // The nearest point of each type by growing shells: most are found within a few cells.
        for (double r = diagonal / 32.0;; r *= 2.0) {
            grid.for_each_within(p[i], r, [&](int j, double d2) {
                if (view.owner[j] == view.owner[i]) return;
                double& best = nearest[exemplar.elements[view.owner[j]].type];
                best = std::min(best, std::sqrt(d2));
            });
            bool all = true;
            for (double d : nearest) all = all && d <= r;
            if (all || r >= diagonal) break;
        }
        const int a = exemplar.elements[view.owner[i]].type;
        for (int b = 0; b < types_; ++b)
            if (std::isfinite(nearest[b])) sorted_[a * types_ + b].push_back(nearest[b]);
    }
    for (auto& v : sorted_) std::sort(v.begin(), v.end());
}

CrowdingBounds::CrowdingBounds(const Exemplar& exemplar)
    : centroids(exemplar, CrowdingLevel::centroids), has_samples(exemplar.has_multi_sample_elements()) {
    if (has_samples) samples = NearestDistanceTails(exemplar, CrowdingLevel::samples);
}

double NearestDistanceTails::quantile(int a, int b, double u) const {
    return lower_quantile(distances(a, b), u);
}

double NearestDistanceTails::reach(double tail) const {
    double r = 0.0;
    for (const auto& v : sorted_)
        if (!v.empty()) r = std::max(r, lower_quantile(v, bounded_tail(v, tail)));
    return r;
}

double NearestDistanceTails::tail_distance(int a, int b, double tail) const {
    const std::vector<double>& v = distances(a, b);
    return v.empty() ? 0.0 : lower_quantile(v, bounded_tail(v, tail));
}

double NearestDistanceTails::reach(int a, double tail) const {
    double r = 0.0;
    for (int b = 0; b < types_; ++b)
        if (const auto& v = distances(a, b); !v.empty())
            r = std::max(r, lower_quantile(v, bounded_tail(v, tail)));
    return r;
}

double NearestDistanceTails::hard_core(int a, int b) const {
    const auto& ab = distances(a, b);
    const auto& ba = distances(b, a);
    if (ab.empty() && ba.empty()) return 0.0;
    return std::min(ab.empty() ? kInf : ab.front(), ba.empty() ? kInf : ba.front());
}

namespace {

// The violations of both levels, as (view, violations) pairs.
struct LevelViolations {
    PointView view;
    std::vector<Violation> found;
};

std::vector<LevelViolations> all_violations(const Exemplar& data, const CrowdingBounds& bounds,
                                            const CrowdingRepairOptions& o) {
    std::vector<LevelViolations> all;
    for (const NearestDistanceTails* tails :
         {&bounds.centroids, bounds.has_samples ? &bounds.samples : nullptr}) {
        if (tails == nullptr) continue;
        LevelViolations level;
        level.view = points_of(data, tails->level());
        level.found = find_violations(data, level.view, *tails, o);
        all.push_back(std::move(level));
    }
    return all;
}

int count_of(const std::vector<LevelViolations>& all) {
    int n = 0;
    for (const LevelViolations& l : all) n += static_cast<int>(l.found.size());
    return n;
}

}  // namespace

CrowdingRepairReport repair_crowding(Exemplar& data, const Domain& domain, const CrowdingBounds& bounds,
                                     const CrowdingRepairOptions& o) {
    CrowdingRepairReport report;
    data.update_positions();  // positions are the samples' centroids (a caller may have moved samples)
    if (data.dimension == 2)
        for (Element& e : data.elements) e.position.z = 0.0;
    for (int round = 0; round < o.rounds; ++round) {
        check(o.interrupt, 0);  // the caller's thread, between rounds
        const std::vector<LevelViolations> all = all_violations(data, bounds, o);
        report.remaining = count_of(all);
        if (report.remaining == 0) return report;
        ++report.rounds;
        std::vector<Vec3> shift(data.elements.size());
        std::vector<int> shifts(data.elements.size(), 0);
        for (const LevelViolations& level : all) add_moves(data, level.view, level.found, o, shift, shifts);
        for (size_t e = 0; e < data.elements.size(); ++e)
            if (shifts[e] > 0 &&
                move_element(data, static_cast<int>(e), shift[e] * (1.0 / shifts[e]), domain))
                ++report.moved;
    }
    report.remaining = count_of(all_violations(data, bounds, o));
    report.bound_hit = report.remaining > 0;
    return report;
}

std::vector<CrowdedPair> crowded_pairs(const Exemplar& data, const CrowdingBounds& bounds,
                                       const CrowdingRepairOptions& options) {
    std::vector<CrowdedPair> pairs;
    for (const LevelViolations& level : all_violations(data, bounds, options))
        for (const Violation& v : level.found)
            pairs.push_back({level.view.owner[v.sample], level.view.owner[v.neighbour]});
    std::sort(pairs.begin(), pairs.end(), [](const CrowdedPair& a, const CrowdedPair& b) {
        return a.element != b.element ? a.element < b.element : a.neighbour < b.neighbour;
    });
    pairs.erase(std::unique(pairs.begin(), pairs.end(),
                            [](const CrowdedPair& a, const CrowdedPair& b) {
                                return a.element == b.element && a.neighbour == b.neighbour;
                            }),
                pairs.end());
    return pairs;
}

}  // namespace tessera::core
