// The exemplar, prepared once before synthesis (section 4.2's pre-process).
#include "det/input_index.hpp"

#include <algorithm>
#include <cmath>

#include "core/parallel.hpp"
#include "det/density.hpp"
#include "det/matching.hpp"
#include "tessera/error.hpp"
#include "tessera/option_table.hpp"

namespace tessera::det {

std::vector<int> sample_keys(const Exemplar& data, std::vector<int>* type_key_base) {
    // Sample count per type (validate() guarantees one count per type).
    std::vector<int> count(data.types.size(), 1);
    for (const auto& e : data.elements) count[e.type] = e.sample_count;
    std::vector<int> base(data.types.size(), 0);
    int next = 1;
    for (size_t t = 0; t < data.types.size(); ++t) {
        if (count[t] > 1) {
            base[t] = next;
            next += count[t];
        }
    }
    std::vector<int> key(data.samples.size(), 0);
    for (size_t i = 0; i < data.samples.size(); ++i) {
        const auto& s = data.samples[i];
        const int t = data.elements[s.element].type;
        key[i] = count[t] > 1 ? base[t] + s.sample_id : 0;
    }
    if (type_key_base) *type_key_base = base;
    return key;
}

Params resolve_params(const Exemplar& exemplar, const DetOptions& options) {
    auto bad = [](const std::string& what) { throw Error(ErrorKind::option, what); };
    check_options(det_option_table(), options);  // each field against its row, naming it
    Params p;
    p.dimension = exemplar.dimension;
    p.spacing = mean_nearest_neighbor_distance(exemplar);
    if (!(p.spacing > 0.0)) {
        // One element, or all elements on one spot: fall back to the domain's scale.
        p.spacing = std::pow(exemplar.domain.measure() / std::max<size_t>(1, exemplar.elements.size()),
                             1.0 / exemplar.dimension);
    }
    p.type_density = exemplar_type_density(exemplar, p.spacing);
    p.radius = options.radius > 0.0 ? options.radius : default_radius_factor(exemplar.dimension) * p.spacing;
    // A neighbour displaced by a whole spacing from its prediction is as good as
    // unmatched: pair costs are truncated there (robust to boundary and density
    // mismatches), and input neighbourhoods reach that far beyond r.
    const double cap = p.spacing;
    p.cap2 = cap * cap;
    p.input_radius = p.radius + cap;
    p.alpha = options.alpha >= 0.0 ? options.alpha : p.spacing * p.spacing;
    p.lambda = options.lambda >= 0.0 ? options.lambda : p.spacing * p.spacing;
    p.matching = options.matching;
    p.field = options.field;
    Vec3 gravity = options.gravity;
    if (gravity == Vec3{}) gravity = exemplar.dimension == 2 ? Vec3{0, -1, 0} : Vec3{0, 0, -1};
    p.gravity = resolve_gravity(gravity, exemplar.dimension);
    p.floor_distance = options.floor_distance;
    if (options.boundary_sides.size() > 6) bad("at most 6 boundary sides");
    for (const auto& side : options.boundary_sides)
        if (side.axis < 0 || side.axis >= exemplar.dimension || (side.sign != -1 && side.sign != 1))
            bad("a boundary side must be -x, +x, -y, +y" + std::string(exemplar.dimension == 3 ? ", -z or +z" : ""));
    p.boundary.sides = options.boundary_sides;
    p.boundary.distance = options.boundary_sides.empty() ? 0.0 : options.boundary_distance;
    for (char f : floor_elements(exemplar, exemplar.domain, p.gravity, p.floor_distance, p.boundary))
        p.floor_constraints |= f != 0;
    return p;
}

void gather_neighbors(const core::SpatialGrid& grid, const std::vector<Vec3>& positions, const Vec3& center,
                      int self, double radius, int dimension, const std::vector<int>& key,
                      const std::vector<int>& type, const std::vector<int>& element,
                      const std::vector<double>& element_radius, std::vector<NeighborEntry>& out,
                      std::vector<std::pair<double, int>>& scratch, int max_count) {
    scratch.clear();
    grid.for_each_within(center, radius, [&](int i, double d2) {
        if (i != self) scratch.emplace_back(d2, i);
    });
    std::sort(scratch.begin(), scratch.end());
    if (static_cast<int>(scratch.size()) > max_count) scratch.resize(max_count);
    out.clear();
    for (const auto& [d2, i] : scratch) {
        NeighborEntry e;
        e.offset = positions[i] - center;
        if (dimension == 2) e.offset.z = 0.0;
        e.sample = i;
        e.key = key[i];
        e.match_key = key[i] * 2 + (self >= 0 && element[i] == element[self] ? 1 : 0);
        e.type = type[i];
        e.element = element[i];
        e.radius = element_radius[i];
        out.push_back(e);
    }
}

int InputIndex::nearest_with_key(const Vec3& p, int k, double max_distance) const {
    if (k < 0 || k >= static_cast<int>(key_grid.size())) return -1;
    const int local = key_grid[k].nearest(p, max_distance, [](int) { return true; });
    return local < 0 ? -1 : by_key[k][local];
}

namespace {

void build_similarity_sets(InputIndex& index, const Params& params, int k, int threads) {
    const int n = index.size();
    std::vector<std::vector<int>> sets(n);
    const int nthreads = core::resolve_threads(threads);
    std::vector<MatchScratch> scratch(nthreads);
    std::vector<std::vector<std::pair<double, int>>> ranked(nthreads);
    std::vector<std::vector<NeighborEntry>> own(nthreads);
    const double r2 = params.radius * params.radius;
    core::parallel_for(n, nthreads, [&](int begin, int end, int t) {
        for (int i = begin; i < end; ++i) {
            // n(s_i) within r plays the output neighbourhood; candidates use their full extent.
            auto& mine = own[t];
            mine.clear();
            for (int q = 0; q < index.neighbor_count(i); ++q)
                if (squared_norm(index.neighbors(i)[q].offset) <= r2) mine.push_back(index.neighbors(i)[q]);
            const int m = static_cast<int>(mine.size());
            auto& r = ranked[t];
            r.clear();
            for (int j : index.by_key[index.key[i]]) {
                if (j == i) continue;
                double c = match_neighborhoods(mine.data(), m, index.neighbors(j), index.neighbor_count(j), params,
                                               scratch[t], nullptr, INFINITY);
                if (index.key[i] == 0 && index.type[i] != index.type[j]) c += params.alpha;
                r.emplace_back(c, j);
            }
            const int keep = std::min<int>(k, static_cast<int>(r.size()));
            std::partial_sort(r.begin(), r.begin() + keep, r.end());
            for (int q = 0; q < keep; ++q) sets[i].push_back(r[q].second);
        }
    });
    index.sim_start.assign(n + 1, 0);
    for (int i = 0; i < n; ++i) index.sim_start[i + 1] = index.sim_start[i] + static_cast<int>(sets[i].size());
    index.sim.clear();
    for (auto& s : sets) index.sim.insert(index.sim.end(), s.begin(), s.end());
}

}  // namespace

InputIndex build_input_index(const Exemplar& exemplar, const Params& params, int k, int threads) {
    InputIndex index;
    index.exemplar = &exemplar;
    const int n = static_cast<int>(exemplar.samples.size());
    index.positions.resize(n);
    index.type.resize(n);
    index.element.resize(n);
    index.radius.resize(n);
    for (int i = 0; i < n; ++i) {
        const auto& s = exemplar.samples[i];
        index.positions[i] = s.p;
        if (params.dimension == 2) index.positions[i].z = 0.0;
        index.element[i] = s.element;
        index.type[i] = exemplar.elements[s.element].type;
        index.radius[i] = exemplar.elements[s.element].radius;
    }
    index.key = sample_keys(exemplar);
    int max_key = 0;
    for (int kk : index.key) max_key = std::max(max_key, kk);
    index.by_key.assign(max_key + 1, {});
    for (int i = 0; i < n; ++i) index.by_key[index.key[i]].push_back(i);

    index.grid.build(index.positions, params.input_radius, params.dimension);
    index.key_positions.resize(index.by_key.size());
    index.key_grid.resize(index.by_key.size());
    for (size_t kk = 0; kk < index.by_key.size(); ++kk) {
        for (int i : index.by_key[kk]) index.key_positions[kk].push_back(index.positions[i]);
        index.key_grid[kk].build(index.key_positions[kk], params.spacing, params.dimension);
    }
    index.nb_start.assign(n + 1, 0);
    std::vector<NeighborEntry> entries;
    std::vector<std::pair<double, int>> scratch;
    for (int i = 0; i < n; ++i) {
        gather_neighbors(index.grid, index.positions, index.positions[i], i, params.input_radius, params.dimension,
                         index.key, index.type, index.element, index.radius, entries, scratch, max_neighbors * 2);
        // Key-major order lets the pairing find an output sample's possible partners by binary search.
        std::stable_sort(entries.begin(), entries.end(),
                         [](const NeighborEntry& a, const NeighborEntry& b) { return a.match_key < b.match_key; });
        index.nb.insert(index.nb.end(), entries.begin(), entries.end());
        index.nb_start[i + 1] = static_cast<int>(index.nb.size());
    }
    const std::vector<char> floor_element =
        floor_elements(exemplar, exemplar.domain, params.gravity, params.floor_distance, params.boundary);
    index.floor.resize(n);
    for (int i = 0; i < n; ++i) index.floor[i] = floor_element[index.element[i]];
    if (k > 0) build_similarity_sets(index, params, k, threads);
    return index;
}

}  // namespace tessera::det
