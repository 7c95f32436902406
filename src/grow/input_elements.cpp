// Indexing the exemplar's elements for growth (grow/input_elements.hpp).
#include "grow/input_elements.hpp"

#include <algorithm>
#include <cmath>

#include "core/parallel.hpp"

namespace tessera::grow {

namespace {

// Neighbourhoods of every element within `reach`, nearest first (ties by index).
void gather_input_neighborhoods(InputElements& in, const Exemplar& ex, double reach, const Metric& m) {
    const int n = in.size();
    core::SpatialGrid grid;
    grid.build(in.centroid, std::max(reach, 1e-9), m.dimension);
    in.nb_start.assign(n + 1, 0);
    in.metric_count.assign(n, 0);
    in.patch_count.assign(n, 0);
    in.within_r.assign(n, 0);
    const double metric_reach = m.params.radius + std::sqrt(m.params.cap2);
    std::vector<std::pair<double, int>> found;
    for (int i = 0; i < n; ++i) {
        found.clear();
        grid.for_each_within(in.centroid[i], reach, [&](int j, double d2) {
            if (j != i) found.emplace_back(d2, j);
        });
        std::sort(found.begin(), found.end());
        for (const auto& [d2, j] : found) {
            det::NeighborEntry e;
            e.offset = in.centroid[j] - in.centroid[i];
            e.sample = j;
            e.element = j;
            e.type = in.type[j];
            e.radius = ex.elements[j].radius;
            in.nb.push_back(e);
            const double d = std::sqrt(d2);
            in.metric_count[i] += d <= metric_reach;
            in.patch_count[i] += d <= m.patch_radius;
            in.within_r[i] += d <= m.params.radius;
        }
        in.nb_start[i + 1] = static_cast<int>(in.nb.size());
    }
    InputElements::Columns& col = in.columns;
    col.one_type = col.one_radius = n > 0;
    if (n > 0) col.the_type = in.type[0], col.the_radius = ex.elements[0].radius;
    for (int i = 0; i < n; ++i) {
        col.one_type = col.one_type && in.type[i] == col.the_type;
        col.one_radius = col.one_radius && ex.elements[i].radius == col.the_radius;
    }
    for (const det::NeighborEntry& e : in.nb) {
        in.columns.x.push_back(e.offset.x);
        in.columns.y.push_back(e.offset.y);
        in.columns.z.push_back(e.offset.z);
        in.columns.type.push_back(e.type);
        in.columns.radius.push_back(e.radius);
    }
}

// Per type, the elements whose patch lies inside the exemplar (a match there can copy a
// whole patch), else those whose metric neighbourhood does, else all of the type: the first
// of these that holds kMinPool elements (or a quarter of the type's). A match on an element
// at the exemplar's border copies a cut patch, and growth there stops.
constexpr int kMinPool = 8;

// How far an element lies from the exemplar's border, for the pools. A box exemplar thinner
// than a patch along an axis (a layer on a floor, a membrane) is the pattern's whole extent
// there, not a cut of it: that axis's faces do not count, or no element would have a
// whole patch and every match would fall back to the border elements, whose cut patches
// copy the exemplar and stop at its sides.
double pool_margin(const Exemplar& ex, const Vec3& c, double patch) {
    if (ex.domain.kind() != Domain::Kind::box) return ex.domain.distance_to_boundary(c);
    const Box b = ex.domain.bounds();
    double margin = 1e300;
    for (int k = 0; k < ex.dimension; ++k)
        if (b.hi[k] - b.lo[k] >= 2.0 * patch) margin = std::min({margin, c[k] - b.lo[k], b.hi[k] - c[k]});
    return margin;
}

void choose_pools(InputElements& in, const Exemplar& ex, const Metric& m) {
    const int types = static_cast<int>(ex.types.size());
    in.pool.assign(types, {});
    std::vector<double> margin(in.size());
    for (int i = 0; i < in.size(); ++i) margin[i] = pool_margin(ex, in.centroid[i], m.patch_radius);
    for (int t = 0; t < types; ++t) {
        int of_type = 0;
        for (int i = 0; i < in.size(); ++i) of_type += in.type[i] == t;
        for (const double need : {m.patch_radius, m.params.radius, -1.0}) {
            in.pool[t].clear();
            for (int i = 0; i < in.size(); ++i)
                if (in.type[i] == t && margin[i] >= need) in.pool[t].push_back(i);
            if (static_cast<int>(in.pool[t].size()) >= std::max(1, std::min(kMinPool, of_type / 4)) ||
                need < 0.0)
                break;
        }
    }
    in.pool_position.assign(types, {});
    in.pool_grid.assign(types, {});
    for (int t = 0; t < types; ++t) {
        for (const int i : in.pool[t]) in.pool_position[t].push_back(in.centroid[i]);
        in.pool_grid[t].build(in.pool_position[t], std::max(m.params.spacing, 1e-9), m.dimension);
    }
}

// k most similar pool elements of the same type to each element (by Eq. 3 between their
// neighbourhoods within r), for the k-coherence search.
void build_similarity_sets(InputElements& in, const Metric& m, int k, int threads) {
    const int n = in.size();
    std::vector<std::vector<int>> sets(n);
    core::parallel_for(n, threads, [&](int begin, int end, int) {
        det::MatchScratch scratch;
        std::vector<std::pair<double, int>> scored;
        for (int i = begin; i < end; ++i) {
            scored.clear();
            for (const int j : in.pool[in.type[i]]) {
                if (j == i) continue;
                const double c = in.shape_distance(i, j) +
                                 det::match_greedy(in.neighbors(i), in.within_r[i], in.neighbors(j),
                                                   in.metric_count[j], m.params, scratch, nullptr, 1e300);
                scored.emplace_back(c, j);
            }
            const int keep = std::min<int>(k, static_cast<int>(scored.size()));
            std::partial_sort(scored.begin(), scored.begin() + keep, scored.end());
            for (int s = 0; s < keep; ++s) sets[i].push_back(scored[s].second);
        }
    });
    in.sim_start.assign(n + 1, 0);
    for (int i = 0; i < n; ++i) {
        in.sim_start[i + 1] = in.sim_start[i] + static_cast<int>(sets[i].size());
        in.sim.insert(in.sim.end(), sets[i].begin(), sets[i].end());
    }
}

}  // namespace

Vec3 element_centroid(const Exemplar& data, const Element& element) {
    Vec3 c;
    for (int s = 0; s < element.sample_count; ++s) c = c + data.samples[element.first_sample + s].p;
    c = c * (1.0 / element.sample_count);
    if (data.dimension == 2) c.z = 0.0;
    return c;
}

int InputElements::nearest_in_pool(int t, const Vec3& p, double max_distance) const {
    if (t < 0 || t >= static_cast<int>(pool.size()) || pool[t].empty()) return -1;
    const int k = pool_grid[t].nearest(p, max_distance, [](int) { return true; });
    return k < 0 ? -1 : pool[t][k];
}

double InputElements::shape_distance(int a, int b) const {
    if (a < 0 || b < 0) return 0.0;
    const int n = layout_start[a + 1] - layout_start[a];
    if (n <= 1 || n != layout_start[b + 1] - layout_start[b]) return 0.0;
    double sum = 0.0;
    for (int k = 0; k < n; ++k) {
        const Vec3 d = layout[layout_start[a] + k] - layout[layout_start[b] + k];
        sum += dot(d, d);
    }
    return sum / n;
}

InputElements index_input_elements(const Exemplar& exemplar, const Metric& metric, int k, int threads) {
    InputElements in;
    in.layout_start.push_back(0);
    for (const Element& e : exemplar.elements) {
        in.centroid.push_back(element_centroid(exemplar, e));
        in.type.push_back(e.type);
        for (int s = 0; s < e.sample_count; ++s)
            in.layout.push_back(exemplar.samples[e.first_sample + s].p - in.centroid.back());
        in.layout_start.push_back(static_cast<int>(in.layout.size()));
    }
    const double reach = std::max(metric.patch_radius, metric.params.radius + std::sqrt(metric.params.cap2)) +
                         std::sqrt(metric.threshold2);
    gather_input_neighborhoods(in, exemplar, reach, metric);
    choose_pools(in, exemplar, metric);
    build_similarity_sets(in, metric, k, threads);
    return in;
}

}  // namespace tessera::grow
