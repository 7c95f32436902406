#include "det/type_exchange.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

#include "core/empty_space.hpp"
#include "core/rng.hpp"
#include "core/spatial_grid.hpp"
#include "det/vacancies.hpp"

namespace tessera::det {

namespace {

// The lattice keying the choice of the input element copied into a place, in spacings.
constexpr double kKeyCellSpacings = 1.0 / 1024.0;

// A count is met within max(1, 1%).
long slack_of(long target) { return std::max<long>(1, std::lround(0.01 * static_cast<double>(target))); }

// Types yield elements to the worst served one while their shortfall is this much smaller.
constexpr double kYieldMargin = 0.02;

}  // namespace

int exchange_types(Provenance of, const Exemplar& exemplar, const Domain& domain, const Params& params,
                   const core::CrowdingBounds& tails, std::uint64_t seed) {
    Arrangement& out = of.out;
    const int types = static_cast<int>(exemplar.types.size());
    const int dim = params.dimension;
    if (types < 2 || !(params.spacing > 0.0)) return 0;
    std::vector<long> count(types, 0), target(types, 0);
    for (int t = 0; t < types; ++t) target[t] = std::lround(params.type_density[t] * domain.measure());
    for (const Element& e : out.elements) ++count[e.type];
    // A type's relative shortfall against its count (negative above it).
    const auto shortfall = [&](const std::vector<long>& c, int t) {
        return static_cast<double>(target[t] - c[t]) / static_cast<double>(std::max<long>(1, target[t]));
    };
    // The types that may yield elements: those better served than the worst served by more
    // than kYieldMargin (over their counts, or less short than it).
    double worst = 0.0;
    for (int t = 0; t < types; ++t)
        if (count[t] < target[t] - slack_of(target[t])) worst = std::max(worst, shortfall(count, t));
    std::vector<char> over(types, 0);
    bool any_over = false;
    for (int t = 0; t < types; ++t) {
        over[t] = shortfall(count, t) < worst - kYieldMargin;
        any_over = any_over || over[t];
    }
    if (!any_over || !(worst > 0.0)) return 0;

    // Room is measured among the elements of types not over their count; the others are
    // what an exchange may take out.
    core::ObstacleGrid room(domain.bounds(), params.spacing, dim);
    for (const Sample& s : out.samples) {
        const Element& e = out.elements[s.element];
        if (!over[e.type] || e.locked) room.add(s.p, e.radius, e.type);
    }
    const std::vector<Vec3> centroids = element_centroids(out.elements, dim);
    core::SpatialGrid removable;
    removable.build(centroids, params.spacing, dim);
    std::vector<char> removed(out.elements.size(), 0);
    double reach = 0.0;
    for (int a = 0; a < types; ++a)
        for (int b = 0; b < types; ++b) reach = std::max(reach, tails.hard_core(a, b));

    const std::vector<Vec3> candidates = vacancy_candidates(domain, dim, params.spacing);
    const double cap = 4.0 * params.spacing;
    std::priority_queue<std::pair<double, int>> heap;  // (room, -index)
    for (size_t i = 0; i < candidates.size(); ++i)
        heap.emplace(core::ball_clearance(room, domain, candidates[i], cap), -static_cast<int>(i));
    std::vector<std::vector<int>> of_type(types);
    for (size_t i = 0; i < exemplar.elements.size(); ++i) of_type[exemplar.elements[i].type].push_back(static_cast<int>(i));
    const core::KeyedRng rng(seed, core::Purpose::jitter, 0x7e);
    std::vector<double> nearest;
    std::vector<int> victims;
    int exchanged = 0;
    const long bound = static_cast<long>(out.elements.size());
    while (!heap.empty() && exchanged < bound) {
        // The type furthest below its count.
        int type = -1;
        double worst = 0.0;
        for (int t = 0; t < types; ++t) {
            const double d = static_cast<double>(target[t] - count[t] - slack_of(target[t])) / std::max<long>(1, target[t]);
            if (d > worst && !of_type[t].empty()) worst = d, type = t;
        }
        if (type < 0) break;
        const auto [ranked, negative] = heap.top();
        heap.pop();
        const Vec3& c = candidates[-negative];
        const double fresh = core::ball_clearance(room, domain, c, cap);
        if (fresh < ranked) {
            heap.emplace(fresh, negative);
            continue;
        }
        // The hard core towards the elements that stay must hold.
        room.nearest_by_tag(c, types, cap, nearest);
        bool fits = true;
        for (int b = 0; b < types; ++b) fits = fits && nearest[b] >= tails.hard_core(type, b);
        if (!fits) continue;
        // The over-count elements inside the hard core go, while their types stay at their counts.
        victims.clear();
        removable.for_each_within(c, reach, [&](int e, double d2) {
            const int b = out.elements[e].type;
            if (!removed[e] && over[b] && !out.elements[e].locked && std::sqrt(d2) < tails.hard_core(type, b))
                victims.push_back(e);
        });
        std::vector<long> after = count;
        for (int e : victims) --after[out.elements[e].type];
        ++after[type];
        // The exchange must narrow the gap: no yielding type ends up shorter than the type served.
        bool keeps = true;
        for (int b = 0; b < types; ++b)
            keeps = keeps && (after[b] == count[b] || b == type || shortfall(after, b) < shortfall(after, type));
        if (!keeps) continue;
        --after[type];
        const Quat frame = params.field.frame(c, dim);
        // Keyed by the place (a lattice anchored at the world origin), not the candidate's
        // index in this domain's lattice.
        const std::uint64_t place = core::lattice_key(c.x, c.y, c.z, kKeyCellSpacings * params.spacing);
        const int source = of_type[type][rng.below(place, of_type[type].size())];
        const Element& src = exemplar.elements[source];
        const int index = append_copy(of, exemplar, source, frame, c - frame.rotate(src.position), dim);
        removed.push_back(0);
        for (int e : victims) removed[e] = 1;
        count = after;
        ++count[type];
        for (int s = 0; s < src.sample_count; ++s)
            room.add(out.samples[out.elements[index].first_sample + s].p, src.radius, type);

        ++exchanged;
    }
    if (exchanged > 0) {
        std::vector<char> keep(removed.size());
        for (size_t e = 0; e < keep.size(); ++e) keep[e] = !removed[e];
        keep_only(of, keep);
    }
    return exchanged;
}

}  // namespace tessera::det
