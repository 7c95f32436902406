// The counterpart of fill_holes: where patches meet, both may fill the same place, and the
// copy can hold more elements than the exemplar's density asks for (up to 5-10% more on
// the real datasets of the shared data). Such seam pairs also break the exemplar's
// inhibition distance, which shows in the output's pair correlation at short range.
// While a type holds more than its count (its exemplar density times the output's
// measure), its most crowded element is removed if it is crowded at all (fill_holes then
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

namespace tessera::det {
namespace {

constexpr double reach_in_spacings = 3.0;  // neighbours farther than this never crowd
constexpr double close_quantile = 0.1;

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

// Keeps the elements with keep[e] (and their samples, source maps), renumbering ids 0..n-1.
void keep_only(InitResult& init, const std::vector<char>& keep) {
    Arrangement& out = init.arrangement;
    std::vector<Element> elements;
    std::vector<Sample> samples;
    std::vector<int> source_sample, source_element;
    for (size_t e = 0; e < out.elements.size(); ++e) {
        if (!keep[e]) continue;
        Element element = out.elements[e];
        const int index = static_cast<int>(elements.size());
        element.first_sample = static_cast<int>(samples.size());
        element.id = static_cast<std::uint64_t>(index);
        for (int s = 0; s < element.sample_count; ++s) {
            const int old = out.elements[e].first_sample + s;
            Sample smp = out.samples[old];
            smp.element = index;
            samples.push_back(smp);
            source_sample.push_back(init.source_sample[old]);
        }
        source_element.push_back(init.source_element[e]);
        elements.push_back(std::move(element));
    }
    out.elements = std::move(elements);
    out.samples = std::move(samples);
    init.source_sample = std::move(source_sample);
    init.source_element = std::move(source_element);
}

}  // namespace

int thin_crowds(InitResult& init, const Exemplar& exemplar, const Domain& domain, const Params& params) {
    Arrangement& out = init.arrangement;
    const int dim = params.dimension;
    const int types = static_cast<int>(exemplar.types.size());
    const double ratio = domain.measure() / exemplar.domain.measure();
    if (!(ratio > 0.0) || !std::isfinite(ratio) || !(params.spacing > 0.0)) return 0;

    std::vector<long> count(types, 0), target(types, 0);
    for (const Element& e : exemplar.elements) ++target[e.type];
    for (long& t : target) t = std::lround(static_cast<double>(t) * ratio);
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

    // (crowding, -index): most crowded first; of a crowded pair the later copy (the seam
    // newcomer) goes. Runs before fill_holes, so every element here is a patch copy.
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
    for (size_t i = 0; i < out.elements.size(); ++i) {
        const int t = out.elements[i].type;
        if (count[t] > target[t] && !out.elements[i].locked) heap.emplace(crowding(static_cast<int>(i)), -static_cast<int>(i));
    }
    int removed = 0;
    while (!heap.empty()) {  // bounded: every element leaves the heap at most once per re-rank
        const auto [score, negative_index] = heap.top();
        if (score >= 1.0) break;  // nobody closer than the exemplar's close distance is left
        heap.pop();
        const int i = -negative_index;
        const int t = out.elements[i].type;
        if (count[t] <= target[t]) continue;  // its type is full: it stays (types only lose elements)
        const double fresh = crowding(i);
        if (fresh > score) {  // a neighbour was removed since: re-rank
            heap.emplace(fresh, -i);
            continue;
        }
        keep[i] = 0;
        --count[t];
        ++removed;
    }
    if (removed > 0) keep_only(init, keep);
    return removed;
}

}  // namespace tessera::det
