// The search step of the brush solver (brush/distribution.hpp): Eq. 1 and Eq. 2.
#include "brush/distribution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel.hpp"
#include "tessera/field.hpp"

namespace tessera::brush {

namespace {

// A neighbour of another type than the input's costs this share of r^2 more (the attribute
// term of the neighbourhood metric; Eq. 1 itself compares positions only).
constexpr double kTypeMismatch = 0.25;
// Pairs of the assignment: at most this share of the exemplar's spacing apart (the threshold c
// of the partial pair assignment, as growth uses it).
constexpr double kPairThreshold = 0.4;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct LocalNeighbour {
    Vec3 offset;     // R(o(s_o))^-1 (p(s'_o) - p(s_o))
    double weight;   // c(s'_o) w_s(s'_o)
    int type;
    int sample;
};

struct Scratch {
    std::vector<int> found;
    std::vector<std::pair<double, int>> by_distance;
    std::vector<LocalNeighbour> local;
    std::vector<double> taken;  // per input neighbour: 0, or infinity once paired (no branch in the scan)
    std::vector<int> paired, best_paired;
};

// Where an input neighbour would fall around the output sample: in the canvas or not.
struct Placement {
    const Domain& canvas;
    Vec3 origin;
    Quat frame;
    double scale;
    bool whole = false;  // the neighbourhood's disk lies in the canvas: every offset does
    bool inside(const Vec3& offset) const { return whole || canvas.inside(origin + frame.rotate(offset * scale)); }
};

// Eq. 1 for one candidate input neighbourhood, greedy pairing in order of output distance;
// stops once the cost exceeds `bound`. paired[j] = input neighbour of local[j] or -1.
// An unpaired output neighbour costs r^2, and so does an unpaired input neighbour that would
// fall inside the canvas: charging only the output side (as Eq. 1 reads) prefers the densest
// input neighbourhoods, and the arrangement contracts round after round.
double neighbourhood_cost(const InputNeighbourhood& in, double own_weight, const std::vector<LocalNeighbour>& local,
                          double r2, double bound, const Placement& place, Scratch& scratch) {
    scratch.taken.assign(in.offsets.size(), 0.0);
    scratch.paired.assign(local.size(), -1);
    double cost = 0.0;
    const double mismatch = kTypeMismatch * r2;
    // Input neighbours beyond the output's count stay unpaired, and cost r2 each when the
    // whole disk is in the canvas: the pairing stops once that would reach the bound.
    const double reserve = place.whole ? r2 * static_cast<double>(in.offsets.size() > local.size() ? in.offsets.size() - local.size() : 0) : 0.0;
    for (size_t j = 0; j < local.size() && cost + reserve < bound; ++j) {
        double best = r2;
        int best_k = -1;
        const Vec3& l = local[j].offset;
        const double summed = local[j].weight + own_weight;
        const int type = local[j].type;
        for (size_t k = 0; k < in.offsets.size(); ++k) {
            const double w_scale = summed * in.inverse_summed[k];  // Eq. 1
            const Vec3& o = in.offsets[k];
            const double dx = l.x - o.x * w_scale, dy = l.y - o.y * w_scale, dz = l.z - o.z * w_scale;
            double c = dx * dx + dy * dy + dz * dz + scratch.taken[k];
            c += in.types[k] != type ? mismatch : 0.0;
            if (c < best) best = c, best_k = static_cast<int>(k);
        }
        cost += best;
        if (best_k >= 0) scratch.taken[static_cast<size_t>(best_k)] = kInfinity, scratch.paired[j] = best_k;
    }
    for (size_t k = 0; k < in.offsets.size() && cost < bound; ++k)
        if (scratch.taken[k] == 0.0 && place.inside(in.offsets[k])) cost += r2;
    return cost;
}

void match_sample(const BrushCanvas::Impl& st, const OutputNeighbours& nb, int s, SampleMatch& m, Scratch& scratch) {
    const Arrangement& arr = st.arrangement;
    const Element& e = arr.elements[arr.samples[s].element];
    const OutType& ot = st.out_types[e.type];
    const PaletteEntry& entry = st.palette[ot.kappa];
    m.pairs.clear();
    m.cost = 0.0;
    const Quat frame = st.frame_of_sample(s);
    const Quat inverse = frame.conjugate();
    nb.gather(st, s, entry.radius, scratch.found, scratch.by_distance);
    scratch.local.clear();
    for (int o : scratch.found) {
        const Element& oe = arr.elements[arr.samples[o].element];
        scratch.local.push_back({inverse.rotate(arr.samples[o].p - arr.samples[s].p) * (1.0 / e.scale),
                                 oe.scale * st.weight_of_sample(o) / e.scale, oe.type, o});
    }
    const double own_weight = st.weight_of_sample(s);
    const Placement place{st.space(), arr.samples[s].p, frame, e.scale,
                          st.space().distance_to_boundary(arr.samples[s].p) >= entry.radius * e.scale};
    const double r2 = entry.radius * entry.radius;
    const double pair_limit2 = kPairThreshold * kPairThreshold * entry.spacing * entry.spacing;
    double best = std::numeric_limits<double>::infinity();
    const int previous = m.neighbourhood;  // the last iteration's match: tried first, its cost prunes the rest
    const std::vector<int>& candidates = entry.by_type[ot.type][arr.samples[s].sample_id];
    m.neighbourhood = -1;
    auto consider = [&](int candidate) {
        const InputNeighbourhood& in = entry.neighbourhoods[candidate];
        // Output neighbours beyond the input's count are unpaired whatever the pairing, and so
        // are input neighbours beyond the output's, each charged when it falls in the canvas
        // (surely so when the whole disk does): a lower bound that skips most candidates.
        const std::ptrdiff_t surplus = static_cast<std::ptrdiff_t>(scratch.local.size()) -
                                       static_cast<std::ptrdiff_t>(in.offsets.size());
        const double floor = r2 * static_cast<double>(place.whole ? std::abs(surplus) : std::max<std::ptrdiff_t>(0, surplus));
        if (floor >= best) return;
        const double c = neighbourhood_cost(in, own_weight, scratch.local, r2, best, place, scratch);
        if (c < best) best = c, m.neighbourhood = candidate, scratch.best_paired = scratch.paired;
    };
    const bool known = std::find(candidates.begin(), candidates.end(), previous) != candidates.end();
    if (known) consider(previous);
    for (int candidate : candidates)
        if (candidate != previous || !known) consider(candidate);
    if (m.neighbourhood < 0) return;
    m.cost = best;
    const InputNeighbourhood& in = entry.neighbourhoods[m.neighbourhood];
    for (size_t j = 0; j < scratch.local.size(); ++j) {
        const int k = scratch.best_paired[j];
        if (k < 0) continue;
        const double w_scale = (scratch.local[j].weight + own_weight) * in.inverse_summed[k];
        const Vec3 target = in.offsets[k] * w_scale;
        // A pair further apart than the pairing threshold is more likely a wrong pairing than a
        // displaced neighbour: it is charged by the search but predicts nothing.
        if (squared_norm(scratch.local[j].offset - target) > pair_limit2) continue;
        m.pairs.push_back({scratch.local[j].sample, target * e.scale});
    }
}

}  // namespace

void OutputNeighbours::build(const BrushCanvas::Impl& st) {
    points.clear();
    for (const Sample& s : st.arrangement.samples) points.push_back(s.p);
    max_radius = 0.0;
    for (const PaletteEntry& p : st.palette) max_radius = std::max(max_radius, p.radius);
    grid.build(points, max_radius > 0.0 ? max_radius : 1.0, st.dimension);
}

void OutputNeighbours::gather(const BrushCanvas::Impl& st, int s, double radius, std::vector<int>& out,
                              std::vector<std::pair<double, int>>& by_distance) const {
    by_distance.clear();
    const int element = st.arrangement.samples[s].element;
    grid.for_each_within(points[s], radius, [&](int o, double d2) {
        if (st.arrangement.samples[o].element != element) by_distance.emplace_back(d2, o);
    });
    // Nearest first (ties by index), so that the greedy pairing does not depend on the grid.
    std::sort(by_distance.begin(), by_distance.end());
    out.clear();
    for (const auto& [d2, o] : by_distance) out.push_back(o);
}

void search_matches(const BrushCanvas::Impl& st, const std::vector<char>& movable, std::vector<SampleMatch>& matches) {
    OutputNeighbours nb;
    nb.build(st);
    const int n = static_cast<int>(st.arrangement.samples.size());
    matches.resize(static_cast<size_t>(n));
    const int threads = core::resolve_threads(st.options.threads);
    std::vector<Scratch> scratch(static_cast<size_t>(threads));
    core::parallel_for(
        n, threads,
        [&](int begin, int end, int thread) {
            for (int s = begin; s < end; ++s)
                if (movable[s]) match_sample(st, nb, s, matches[s], scratch[static_cast<size_t>(thread)]);
        },
        16);
}

}  // namespace tessera::brush
