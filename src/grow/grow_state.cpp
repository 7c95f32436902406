// Grower::Impl (grow/grow_state.hpp): what is prepared once from the exemplar and options,
// and the bookkeeping of the output's elements.
#include "grow/grow_state.hpp"

#include "core/dequantize.hpp"
#include "tessera/metrics.hpp"

#include <algorithm>
#include <cmath>

#include "core/parallel.hpp"
#include "det/input_index.hpp"
#include "det/vacancies.hpp"
#include "tessera/error.hpp"
#include "tessera/option_table.hpp"

namespace tessera {

namespace {

// Candidates closer than this share of the spacing always merge, whatever the exemplar's
// hard core (a clustered exemplar has close pairs; two proposals for one place are not one).
constexpr double kMergeFloor = 0.35;
// The share of the exemplar's nearest-neighbour distances (per type pair) below the merge distance.
constexpr double kMergeQuantile = 0.1;
// A type pair whose closest distance in the exemplar is under this share of its median
// nearest distance is soft: its hard core does not regulate density (Impl::owned). The
// inhibited and lattice-like examples lie at 0.86-0.94, the real point patterns of
// tests/data/spatstat (cells, pines, retinal mosaics) at 0.30-0.64. The small disks of
// examples/pcf/wide_radii lie at 0.80 and are not held by their hard core: at a bound of
// 0.8 they grew at 1.5x their density (the output at 1.39x); at 0.85, 1.0x.
constexpr double kSoftCore = 0.85;
// Pair-correlation relaxation sweeps of grow(region) when GrowOptions::relax_sweeps is
// automatic: for a soft pattern (`owned`) growth's own steps do not hold the pair
// correlation (field data grew with 2x to 7x synthesize_det's error; four sweeps bring it to
// 1x to 2.5x). A hard core holds more of it, but the least-squares solve still draws
// distances towards the typical one (Poisson disks' first peak of g 1.84 against the
// exemplar's 1.57): one sweep takes the Poisson disks' error from 0.116 to 0.078 and the two
// classes' from 0.158 to 0.134 for about a quarter of the growth's time; a second sweep
// gains a third as much again for as much time (docs/grow.md, step 7).
constexpr int kSoftRelaxSweeps = 4;
constexpr int kHardRelaxSweeps = 1;

// The exemplar growth copies from: validated, and moved off the lattice of its recorded
// coordinates' rounding (core/dequantize.hpp), which exact offset copies would otherwise
// spread over the whole output.
Exemplar growth_exemplar(const Exemplar& exemplar, const GrowOptions& o) {
    exemplar.validate("exemplar");
    if (exemplar.elements.size() < 2) return exemplar;
    return core::dequantized(exemplar, nearest_neighbor_distances(exemplar, o.threads).mean, o.seed);
}

grow::Metric resolve_metric(const Exemplar& exemplar, const GrowOptions& o) {
    check_options(grow_option_table(), o);  // each field against its row, naming it
    DetOptions det;
    det.radius = o.radius;
    det.alpha = o.alpha;
    det.field = o.field;
    grow::Metric m;
    m.params = det::resolve_params(exemplar, det);
    m.dimension = exemplar.dimension;
    m.patch_radius = (o.choice == GrowChoice::patch ? o.patch_extent : 1.0) * m.params.radius;
    m.threshold2 = std::pow(o.threshold * m.params.spacing, 2);
    return m;
}

// The axes along which a 3D box exemplar without a field is a layer (Impl::layer).
std::array<bool, 3> layer_axes_of(const Exemplar& exemplar, const grow::Metric& m, const GrowOptions& o) {
    std::array<bool, 3> layer{false, false, false};
    if (m.dimension != 3 || o.field.active() || exemplar.domain.kind() != Domain::Kind::box) return layer;
    const Box b = exemplar.domain.bounds();
    int thin = 0;
    for (int k = 0; k < 3; ++k) {
        layer[k] = b.hi[k] - b.lo[k] <= 2.0 * (m.patch_radius + m.params.radius);
        thin += layer[k];
    }
    if (thin > 1) layer = {false, false, false};  // a small block, not a layer
    return layer;
}

// An existing arrangement's layer is found from this many of its elements
// (Impl::register_layer_of_elements).
constexpr int kLayerSample = 256;

// One more than the 85% quantile of the number of neighbours within r of the input elements
// a match may pick: the count of the exemplar's crowded places.
int crowded_pool_count(const grow::InputElements& in) {
    std::vector<int> counts;
    for (const std::vector<int>& pool : in.pool)
        for (const int i : pool) counts.push_back(in.within_r[i]);
    if (counts.empty()) return 0;
    const size_t k = static_cast<size_t>(0.85 * (counts.size() - 1));
    std::nth_element(counts.begin(), counts.begin() + k, counts.end());
    return counts[k] + 1;
}

}  // namespace

Grower::Impl::Impl(const Exemplar& ex, const GrowOptions& o)
    : exemplar(growth_exemplar(ex, o)),
      options(o),
      metric(resolve_metric(exemplar, options)),
      threads(core::resolve_threads(options.threads)),
      bounds(ex),  // the recorded exemplar: its closest pairs, not the dequantized ones
      grid(metric.params.spacing, exemplar.dimension) {
    input = grow::index_input_elements(exemplar, metric, options.k, threads);
    const int types = static_cast<int>(exemplar.types.size());
    for (int a = 0; a < types; ++a)
        for (int b = 0; b < types; ++b) {
            hard_cores.push_back(compute_hard_core(a, b));
            sample_cores.push_back(bounds.has_samples ? bounds.samples.hard_core(a, b) : 0.0);
            reach = std::max(reach, hard_cores.back());
            repair_bounds.push_back(bounds.centroids.tail_distance(a, b, core::CrowdingRepairOptions{}.tail));
            repair_reach = std::max(repair_reach, repair_bounds.back());
        }
    for (int i = 0; i < input.size(); ++i) {
        const Element& e = exemplar.elements[i];
        for (int k = 0; k < e.sample_count; ++k)
            extent = std::max(extent, norm(exemplar.samples[e.first_sample + k].p - input.centroid[i]));
    }
    if (std::all_of(exemplar.elements.begin(), exemplar.elements.end(),
                    [](const Element& e) { return e.sample_count == 1; }))
        hole_radius = det::exemplar_hole_radius(exemplar, metric.params.spacing, metric.params.radius),
        fills_holes = true;
    owned.assign(static_cast<size_t>(types) * types, 0);
    if (!bounds.has_samples)
        for (int a = 0; a < types; ++a)
            for (int b = 0; b < types; ++b) {
                const double typical = bounds.centroids.quantile(a, b, 0.5);
                owned[a * types + b] = typical > 0.0 && hard_core(a, b) < kSoftCore * typical;
                any_owned = any_owned || owned[a * types + b];
            }
    if (any_owned) {  // a hard core regulates the other patterns' density
        double total = 0.0;
        for (const double d : metric.params.type_density) total += d;
        crowd = grow::exemplar_crowd_ceiling(exemplar, total);
    }
    relax_sweeps = options.relax_sweeps >= 0 ? options.relax_sweeps : (any_owned ? kSoftRelaxSweeps : kHardRelaxSweeps);
    if (relax_sweeps > 0) relaxation.emplace(ex, metric.params);
    if (bounds.has_samples) reshape_ceiling = crowded_pool_count(input);
    layer = layer_axes_of(exemplar, metric, options);
    type_count.assign(types, 0);
    existing.dimension = exemplar.dimension;
    existing.types = exemplar.types;
}

Quat Grower::Impl::frame_at(const Vec3& p) const {
    return options.field.active() ? options.field.frame(p, metric.dimension) : Quat{};
}

double Grower::Impl::compute_hard_core(int a, int b) const {
    double d = bounds.centroids.hard_core(a, b);
    if (bounds.has_samples) {
        // Multi-sample elements: the closest centroids of the exemplar come from particular
        // poses (two tilted lipids whose tails lean together) and the samples' own hard core
        // is checked anyway; what keeps misaligned patches from both staying and
        // overfilling is the exemplar's kMergeQuantile-th closest centroid distance.
        const core::NearestDistanceTails& t = bounds.centroids;
        if (!t.distances(a, b).empty()) d = std::max(d, t.quantile(a, b, kMergeQuantile));
        if (!t.distances(b, a).empty()) d = std::max(d, t.quantile(b, a, kMergeQuantile));
    }
    return std::max(d, kMergeFloor * metric.params.spacing);
}

int Grower::Impl::add(const grow::OutElement& e) {
    const int i = static_cast<int>(out.size());
    out.push_back(e);
    ++type_count[e.type];
    if (crowd.active()) out[i].crowd = count_crowd(e.p, i, +1);
    grid.insert(i, e.p);
    dirty = true;
    return i;
}

int Grower::Impl::add_filling(int type, int source, const Vec3& p) {
    grow::OutElement e;
    e.p = p;
    e.type = type;
    e.source = source;
    e.frame = frame_at(p);
    e.match = source;
    e.born = round;
    e.id = next_id++;
    return add(e);
}

void Grower::Impl::move(int i, const Vec3& p) {
    if (crowd.active()) count_crowd(out[i].p, i, -1);
    out[i].p = p;
    if (metric.dimension == 2) out[i].p.z = 0.0;
    if (crowd.active()) out[i].crowd = count_crowd(out[i].p, i, +1);
    grid.move(i, out[i].p);
    dirty = true;
}

void Grower::Impl::drop_tail(int first, const std::vector<char>& keep) {
    const int n = static_cast<int>(out.size());
    if (crowd.active())
        for (int i = first; i < n; ++i)
            if (!keep[i - first]) count_crowd(out[i].p, i, -1);
    for (int i = first; i < n; ++i) grid.remove(i);
    int w = first;
    for (int i = first; i < n; ++i)
        if (keep[i - first])
            out[w++] = out[i];
        else
            --type_count[out[i].type];
    out.resize(w);
    for (int i = first; i < w; ++i) grid.insert(i, out[i].p);
    dirty = true;
}

void Grower::Impl::remove_and_renumber(int base, const std::vector<char>& removed) {
    std::vector<int> renumber(removed.size(), -1);
    int next = base;
    for (size_t k = 0; k < removed.size(); ++k)
        if (!removed[k]) renumber[k] = next++;
    auto map = [&](int i) { return i < base ? i : renumber[i - base]; };
    std::vector<char> keep(removed.size());
    for (size_t k = 0; k < keep.size(); ++k) keep[k] = !removed[k];
    drop_tail(base, keep);
    std::vector<int> kept_horizon;
    for (const int h : horizon)
        if (map(h) >= 0) kept_horizon.push_back(map(h));
    horizon = std::move(kept_horizon);
    for (int& first : round_first) {
        if (first < base) continue;
        int k = first - base;
        while (k < static_cast<int>(removed.size()) && removed[k]) ++k;
        first = k < static_cast<int>(removed.size()) ? renumber[k] : next;
    }
}

void Grower::Impl::register_layer_of_elements() {
    layer_registered = false;
    int axis = -1;
    for (int k = 0; k < 3; ++k)
        if (layer[k]) axis = k;
    if (axis < 0 || out.empty()) return;
    const int n = std::min<int>(static_cast<int>(out.size()), kLayerSample);
    const double tolerance = kLayerTolerance * metric.params.spacing;
    // Every (element, exemplar element of its type) pair proposes the offset between their
    // depths; the true one is proposed by every element, a wrong one by some.
    std::vector<double> offsets;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < input.size(); ++j)
            if (input.type[j] == out[i].type) offsets.push_back(out[i].p[axis] - input.centroid[j][axis]);
    if (offsets.empty()) return;
    std::sort(offsets.begin(), offsets.end());
    size_t best = 0, best_count = 0;
    for (size_t a = 0, b = 0; a < offsets.size(); ++a) {
        while (b < offsets.size() && offsets[b] - offsets[a] <= tolerance) ++b;
        if (b - a > best_count) best = a, best_count = b - a;
    }
    layer_origin = Vec3{};
    layer_origin[axis] = offsets[best + best_count / 2];
    layer_registered = true;
    int held = 0;
    for (int i = 0; i < n; ++i) held += on_layer(out[i].type, out[i].p);
    layer_registered = 2 * held >= n;
}

bool Grower::Impl::on_layer(int type, const Vec3& p) const {
    if (!layer_registered) return true;
    const double tolerance = kLayerTolerance * metric.params.spacing;
    for (int k = 0; k < 3; ++k) {
        if (!layer[k]) continue;
        bool held = false;
        for (int i = 0; i < input.size() && !held; ++i)
            held = input.type[i] == type && std::abs(p[k] - layer_origin[k] - input.centroid[i][k]) <= tolerance;
        if (!held) return false;
    }
    return true;
}

int Grower::Impl::count_crowd(const Vec3& p, int self, int change) {
    int n = 0;
    grid.for_each_within(
        p, crowd.radius, [&](int j) { return out[j].p; },
        [&](int j) {
            if (j == self) return;
            out[j].crowd += change;
            ++n;
        });
    return n;
}

bool Grower::Impl::crowd_allows(const Vec3& p) const {
    if (!crowd.active()) return true;
    int own = 0;
    grid.for_each_within(
        p, crowd.radius, [&](int j) { return out[j].p; }, [&](int) { ++own; });
    return crowd.allows(own + 1);
}

void Grower::Impl::set_type(int i, int type) {
    --type_count[out[i].type];
    ++type_count[type];
    out[i].type = type;
    dirty = true;
}

void Grower::Impl::clear() {
    out.clear();
    std::fill(type_count.begin(), type_count.end(), 0);
    grid = core::DynamicGrid(metric.params.spacing, metric.dimension);
    dirty = true;
}

void Grower::Impl::sample_positions(int kept, int source, const Quat& frame, const Vec3& p,
                                    std::vector<Vec3>& samples) const {
    samples.clear();
    if (kept >= 0) {
        const Element& e = existing.elements[kept];
        for (int s = 0; s < e.sample_count; ++s) samples.push_back(existing.samples[e.first_sample + s].p);
        return;
    }
    const Element& e = exemplar.elements[source];
    const Vec3 c = input.centroid[source];
    for (int s = 0; s < e.sample_count; ++s) {
        Vec3 q = p + frame.rotate(exemplar.samples[e.first_sample + s].p - c);
        if (metric.dimension == 2) q.z = 0.0;
        samples.push_back(q);
    }
}

bool Grower::Impl::fits_region(const Domain& region, int kept, int source, const Quat& frame, const Vec3& p,
                               std::vector<Vec3>& samples) const {
    if (open_region) return region.inside(p);
    sample_positions(kept, source, frame, p, samples);
    return std::all_of(samples.begin(), samples.end(), [&](const Vec3& q) { return region.inside(q); });
}

}  // namespace tessera
