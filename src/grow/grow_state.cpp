// Grower::Impl (grow/grow_state.hpp): what is prepared once from the exemplar and options,
// and the bookkeeping of the output's elements.
#include "grow/grow_state.hpp"

#include <algorithm>
#include <cmath>

#include "core/parallel.hpp"
#include "det/input_index.hpp"
#include "tessera/error.hpp"

namespace tessera {

namespace {

// Candidates closer than this share of the spacing always merge, whatever the exemplar's
// hard core (a clustered exemplar has close pairs; two proposals for one place are not one).
constexpr double kMergeFloor = 0.35;
// The share of the exemplar's nearest-neighbour distances (per type pair) below the merge distance.
constexpr double kMergeQuantile = 0.1;

const Exemplar& validated(const Exemplar& exemplar) {
    exemplar.validate("exemplar");
    return exemplar;
}

void check_options(const GrowOptions& o) {
    auto bad = [](const std::string& what) { throw Error(ErrorKind::option, what); };
    auto finite_at_least = [&](double v, double lo, const char* name) {
        if (!std::isfinite(v) || v < lo) bad(std::string(name) + ": must be a number >= " + std::to_string(lo).substr(0, 4));
    };
    finite_at_least(o.radius, 0.0, "radius");
    finite_at_least(o.patch_extent, 1.0, "patch_extent");
    if (!std::isfinite(o.threshold) || o.threshold <= 0.0 || o.threshold > 1.0)
        bad("threshold: must be > 0 and <= 1 (a share of the mean spacing)");
    if (!std::isfinite(o.energy_factor) || o.energy_factor <= 1.0) bad("energy_factor: must be a number > 1");
    if (!std::isfinite(o.lock_distance) || o.lock_distance <= 0.0) bad("lock_distance: must be a number > 0");
    finite_at_least(o.band_weight, 0.0, "band_weight");
    if (o.solves < 0 || o.solves > 100) bad("solves: must be from 0 to 100");
    if (o.votes < 1) bad("votes: must be >= 1");
    if (o.k < 1) bad("k: must be >= 1");
    if (!std::isfinite(o.alpha)) bad("alpha: must be a finite number");
    if (o.playouts < 1 || o.playouts > 100000) bad("playouts: must be from 1 to 100000");
    finite_at_least(o.explore, 0.0, "explore");
    finite_at_least(o.exploit, 0.0, "exploit");
    if (o.max_rounds < 1) bad("max_rounds: must be >= 1");
    if (o.threads < 0) bad("threads: must be >= 0");
}

grow::Metric resolve_metric(const Exemplar& exemplar, const GrowOptions& o) {
    check_options(o);
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

}  // namespace

Grower::Impl::Impl(const Exemplar& ex, const GrowOptions& o)
    : exemplar(validated(ex)),
      options(o),
      metric(resolve_metric(exemplar, options)),
      threads(core::resolve_threads(options.threads)),
      bounds(exemplar),
      grid(metric.params.spacing, exemplar.dimension) {
    input = grow::index_input_elements(exemplar, metric, options.k, threads);
    const int types = static_cast<int>(exemplar.types.size());
    for (int a = 0; a < types; ++a)
        for (int b = 0; b < types; ++b) reach = std::max(reach, hard_core(a, b));
    for (int i = 0; i < input.size(); ++i) {
        const Element& e = exemplar.elements[i];
        for (int k = 0; k < e.sample_count; ++k)
            extent = std::max(extent, norm(exemplar.samples[e.first_sample + k].p - input.centroid[i]));
    }
    existing.dimension = exemplar.dimension;
    existing.types = exemplar.types;
}

Quat Grower::Impl::frame_at(const Vec3& p) const {
    return options.field.active() ? options.field.frame(p, metric.dimension) : Quat{};
}

double Grower::Impl::hard_core(int a, int b) const {
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

double Grower::Impl::sample_core(int a, int b) const {
    return bounds.has_samples ? bounds.samples.hard_core(a, b) : 0.0;
}

int Grower::Impl::add(const grow::OutElement& e) {
    const int i = static_cast<int>(out.size());
    out.push_back(e);
    grid.insert(i, e.p);
    dirty = true;
    return i;
}

void Grower::Impl::move(int i, const Vec3& p) {
    out[i].p = p;
    if (metric.dimension == 2) out[i].p.z = 0.0;
    grid.move(i, out[i].p);
    dirty = true;
}

void Grower::Impl::drop_tail(int first, const std::vector<char>& keep) {
    const int n = static_cast<int>(out.size());
    for (int i = first; i < n; ++i) grid.remove(i);
    int w = first;
    for (int i = first; i < n; ++i)
        if (keep[i - first]) out[w++] = out[i];
    out.resize(w);
    for (int i = first; i < w; ++i) grid.insert(i, out[i].p);
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

}  // namespace tessera
