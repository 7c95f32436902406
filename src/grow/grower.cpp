// tessera::Grower (include/tessera/grow.hpp): starting points, the grow calls and their
// bounds, progress, and the arrangement a caller sees.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/rng.hpp"
#include "grow/grow_state.hpp"
#include "grow/rare_types.hpp"
#include "grow/round.hpp"
#include "grow/sample_holes.hpp"
#include "grow/thinning.hpp"
#include "grow/relax.hpp"
#include "grow/uncovered.hpp"
#include "grow/vacancies.hpp"
#include "tessera/error.hpp"

namespace tessera {

namespace {

using Clock = std::chrono::steady_clock;

// Rounds in a row without a net gain after which growth counts as done.
constexpr int kStallRounds = 3;

// The existing elements that can propose into `region`: within reach of it.
std::vector<int> elements_near(const Grower::Impl& g, const Domain& region, double reach) {
    const Box& b = region.bounds();
    Vec3 half = (b.hi - b.lo) * 0.5;
    if (g.metric.dimension == 2) half.z = 0.0;
    std::vector<int> ids, near;
    g.grid.query(
        b.center(), norm(half) + reach, [&](int i) { return g.out[i].p; }, ids);
    for (const int i : ids)
        if (norm(region.closest_inside(g.out[i].p) - g.out[i].p) <= reach) near.push_back(i);
    return near;
}

void extend(Box& box, bool& has, const Box& more) {
    if (!has) {
        box = more;
        has = true;
        return;
    }
    for (int k = 0; k < 3; ++k)
        box.lo[k] = std::min(box.lo[k], more.lo[k]), box.hi[k] = std::max(box.hi[k], more.hi[k]);
}

void report_progress(Grower::Impl& g, const char* stage, int round, int rounds, double fraction,
                     double energy) {
    if (!g.progress) return;
    ProgressEvent e;
    e.stage = stage;
    e.iteration = round;
    e.iterations = rounds;
    e.energy = energy;
    e.elapsed_s = std::chrono::duration<double>(Clock::now() - g.t0).count();
    e.fraction = std::clamp(fraction, 0.0, 1.0);
    g.last_event = e;
    if (!g.progress(e)) throw Cancelled();
}

// Rounds until `done` says so, no round adds anything, or the bound. Progress numbers them
// from `numbered_from` (rounds a call runs again after its own continue its count).
template <class Done, class Fraction>
GrowReport run_rounds(Grower::Impl& g, const grow::RoundLimits& base, const Done& done,
                      const Fraction& fraction, int seeded, bool last_stage = true, int numbered_from = 0) {
    GrowReport report;
    report.added = seeded;  // the seed patch is made by this call too
    const auto start = Clock::now();
    g.t0 = start;
    g.interrupt.rearm();
    // Kept up to date so that a cancelled call's report survives (Grower::last_report).
    auto keep = [&] {
        report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
        g.last_report = report;
    };
    keep();
    if (numbered_from == 0) report_progress(g, "round", -1, g.options.max_rounds, 0.0, 0.0);
    int stalled = 0;
    for (;;) {
        if (done(report)) break;
        if (report.rounds >= g.options.max_rounds) {
            report.bound_hit = true;
            break;
        }
        grow::RoundLimits limits = base;
        if (base.budget >= 0) limits.budget = base.budget - (report.added - seeded);
        g.seed_pending = false;
        const int added = grow::run_round(g, limits, report);  // a cancel leaves last_report as it was
        ++report.rounds;
        keep();
        report_progress(g, "round", numbered_from + report.rounds - 1, g.options.max_rounds, fraction(report),
                        report.energy);
        // Covered when a round makes nothing; a few rounds in a row that only displace as many
        // as they make would cycle.
        stalled = added <= 0 ? stalled + 1 : 0;
        if (report.last_made == 0 || stalled >= kStallRounds) {
            report.covered = true;
            break;
        }
    }
    if (last_stage) report_progress(g, "done", report.rounds, report.rounds, 1.0, report.energy);
    keep();
    return report;
}

}  // namespace

Grower::Grower(const Exemplar& exemplar, const GrowOptions& options)
    : impl_(std::make_unique<Impl>(exemplar, options)) {}
Grower::~Grower() = default;
Grower::Grower(Grower&&) noexcept = default;
Grower::Grower(const Grower& other) : impl_(std::make_unique<Impl>(*other.impl_)) {
    impl_->interrupt.set_poll(impl_->poll());
}
Grower& Grower::operator=(Grower&&) noexcept = default;

void Grower::set_progress(Progress progress) {
    impl_->progress = std::move(progress);
}
const std::vector<int>& Grower::horizon() const {
    return impl_->horizon;
}
double Grower::radius() const {
    return impl_->metric.params.radius;
}

namespace {

// Distance from c to the exemplar's border, along the axes that are not a layer's.
double seed_margin(const Grower::Impl& g, const Vec3& c) {
    if (g.exemplar.domain.kind() != Domain::Kind::box) return g.exemplar.domain.distance_to_boundary(c);
    const Box b = g.exemplar.domain.bounds();
    double margin = 1e300;
    for (int k = 0; k < g.metric.dimension; ++k)
        if (!g.layer[k]) margin = std::min({margin, c[k] - b.lo[k], b.hi[k] - c[k]});
    return margin;
}

// Adds a copy of an exemplar patch centred at `center` to the horizon: the seed element is
// drawn among the elements whose whole patch lies in the exemplar (all elements when none
// does), keyed by the seed and the world cell of the centre. A layer's seed (Impl::layer)
// copies its whole thickness, centred on `center` (or on the first seed's layer) and
// registers the layer. With `spare_others`, an element that would come closer to one
// already there than their hard core is left out.
void add_seed_patch(Grower::Impl& g, const Vec3& center, bool spare_others) {
    const grow::InputElements& in = g.input;
    std::vector<int> interior;
    for (int i = 0; i < in.size(); ++i)
        if (seed_margin(g, in.centroid[i]) >= g.metric.patch_radius) interior.push_back(i);
    if (interior.empty())
        for (int i = 0; i < in.size(); ++i) interior.push_back(i);
    const double cell = g.metric.params.spacing;
    const core::KeyedRng rng(
        g.options.seed, core::Purpose::grow_seed,
        static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(center.x / cell))),
        static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(center.y / cell))) * 1000003u +
            static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(center.z / cell))));
    const int e = interior[rng.below(0, interior.size())];
    const Quat frame = g.frame_at(center);
    const bool layered = g.layer[0] || g.layer[1] || g.layer[2];
    if (layered && !g.layer_registered) {  // the layer, not the seed element, centred on `center`
        g.layer_origin = center - g.exemplar.domain.bounds().center();
        g.layer_registered = true;
    }
    auto place = [&](int source, const Vec3& offset) {
        grow::OutElement o;
        o.p = center + frame.rotate(offset);
        g.register_on_layer(source, o.p);
        if (g.metric.dimension == 2) o.p.z = 0.0;
        o.type = in.type[source];
        if (spare_others) {
            bool near = false;
            g.grid.for_each_within(
                o.p, g.reach, [&](int i) { return g.out[i].p; },
                [&](int i) { near = near || norm(g.out[i].p - o.p) < g.hard_core(o.type, g.out[i].type); });
            if (near) return;
        }
        o.source = o.match = source;
        o.frame = frame;
        o.born = g.round;
        o.id = g.next_id++;
        g.horizon.push_back(g.add(o));
    };
    place(e, Vec3{});
    if (!layered) {
        for (int k = 0; k < in.patch_count[e]; ++k) place(in.neighbors(e)[k].element, in.neighbors(e)[k].offset);
        return;
    }
    const double patch2 = g.metric.patch_radius * g.metric.patch_radius;
    for (int i = 0; i < in.size(); ++i) {
        Vec3 in_plane = in.centroid[i] - in.centroid[e];
        for (int k = 0; k < 3; ++k)
            if (g.layer[k]) in_plane[k] = 0.0;
        if (i != e && dot(in_plane, in_plane) <= patch2) place(i, in.centroid[i] - in.centroid[e]);
    }
}

}  // namespace

void Grower::seed(const Vec3& center) { seed(std::vector<Vec3>{center}); }

void Grower::seed(const std::vector<Vec3>& centres) {
    Impl& g = *impl_;
    g.horizon.clear();
    ++g.round;
    g.round_first.push_back(static_cast<int>(g.out.size()));
    for (size_t k = 0; k < centres.size(); ++k) add_seed_patch(g, centres[k], k > 0);
    g.seed_pending = true;
}

void Grower::set_arrangement(const Arrangement& existing) {
    Impl& g = *impl_;
    existing.validate("existing arrangement");
    if (existing.dimension != g.exemplar.dimension)
        throw Error(ErrorKind::input, "existing arrangement: " + std::to_string(existing.dimension) +
                                          "D, the exemplar is " + std::to_string(g.exemplar.dimension) + "D");
    std::vector<int> type_map(existing.types.size());
    for (size_t t = 0; t < existing.types.size(); ++t) {
        type_map[t] = g.exemplar.find_type(existing.types[t].name);
        if (type_map[t] < 0)
            throw Error(ErrorKind::input, "existing arrangement: type '" + existing.types[t].name +
                                              "' is not a type of the exemplar");
    }
    for (const Element& e : existing.elements) {
        const int t = type_map[e.type];
        for (const Element& x : g.exemplar.elements)
            if (x.type == t && x.sample_count != e.sample_count)
                throw Error(ErrorKind::input,
                            "existing arrangement: elements of type '" + g.exemplar.types[t].name +
                                "' have " + std::to_string(e.sample_count) +
                                " samples, the exemplar's have " + std::to_string(x.sample_count));
    }
    Impl& h = g;  // a fresh output over the same index
    h.clear();
    h.seed_pending = false;
    h.horizon.clear();
    h.round = 0;
    h.round_first.clear();
    h.retry.clear();
    h.has_bounds = false;
    h.dirty = true;
    h.existing = existing;
    h.existing.types = h.exemplar.types;
    std::uint64_t max_id = 0;
    for (size_t i = 0; i < existing.elements.size(); ++i) {
        Element& e = h.existing.elements[i];
        e.type = type_map[existing.elements[i].type];
        grow::OutElement o;
        o.p = grow::element_centroid(existing, existing.elements[i]);
        o.type = e.type;
        o.kept = static_cast<int>(i);
        o.locked = true;
        o.frame = e.orientation;
        o.id = e.id;
        max_id = std::max(max_id, e.id);
        h.horizon.push_back(h.add(o));
    }
    h.next_id = existing.elements.empty() ? 0 : max_id + 1;
    h.round_first.clear();
    h.register_layer_of_elements();  // its layer's place is the arrangement's, not a seed's
    extend(h.grown, h.has_bounds, existing.domain.bounds());
}

namespace {

// A covered region's rare types brought back to their share (grow/rare_types.hpp), then the
// room the inserted elements cleared around them grown again: the elements within reach of
// them are the horizon of rounds that run until nothing more fits. (Only removing what a
// channel protein overlaps left a ring around it: the membrane lost 4% of its lipids.)
// The unlocked elements of some types from index `start` on, locked for the holder's
// lifetime and unlocked again when it ends, also when a cancel throws out of the rounds in
// between (an element left locked would never move again, and the caller would see it locked).
class HeldTypes {
public:
    HeldTypes(Grower::Impl& g, int start, const std::vector<char>& types) : g_(g), start_(start) {
        for (int i = start; i < static_cast<int>(g.out.size()); ++i) {
            grow::OutElement& o = g.out[i];
            if (!o.locked && types[o.type]) o.locked = true, ids_.push_back(o.id);
        }
        std::sort(ids_.begin(), ids_.end());
    }
    ~HeldTypes() {  // elements may have been removed or added since: found by id
        for (int i = start_; i < static_cast<int>(g_.out.size()); ++i)
            if (std::binary_search(ids_.begin(), ids_.end(), g_.out[i].id)) g_.out[i].locked = false;
    }
    HeldTypes(const HeldTypes&) = delete;
    HeldTypes& operator=(const HeldTypes&) = delete;

private:
    Grower::Impl& g_;
    const int start_;
    std::vector<std::uint64_t> ids_;
};

// Returns how many elements of a minority type were squeezed in.
int complete_rare_types(Grower::Impl& g, const Domain& region, int start, GrowReport& report) {
    const grow::TypeCompletion done = grow::complete_rare_types(g, start, region);
    const int rare = done.inserted;
    report.rare += rare;
    report.displaced += done.removed;
    report.added += rare - done.removed;
    if (rare == 0) return 0;
    const int first = static_cast<int>(g.out.size()) - rare;  // the inserted elements are the tail
    g.round_first.push_back(first);
    std::vector<int> horizon, near;
    const double reach = g.metric.patch_radius + g.metric.params.radius;
    for (int i = first; i < static_cast<int>(g.out.size()); ++i) {
        g.grid.query(
            g.out[i].p, reach, [&](int j) { return g.out[j].p; }, near);
        horizon.insert(horizon.end(), near.begin(), near.end());
    }
    std::sort(horizon.begin(), horizon.end());
    horizon.erase(std::unique(horizon.begin(), horizon.end()), horizon.end());
    g.horizon = std::move(horizon);
    grow::RoundLimits limits;
    limits.region = &region;
    // The completed types' elements stay put while the room is regrown: to the regrowth's
    // type balance they are over their share (the room around them is empty), and it took
    // a third of them out again (two classes: stones 343 -> 410 -> 376).
    const HeldTypes held(g, start, done.completed);
    const auto call_start = g.t0;  // run_rounds restarts the clock; the call's time runs on
    const GrowReport again = run_rounds(
        g, limits, [](const GrowReport&) { return false; }, [](const GrowReport&) { return 0.99; }, 0, false,
        report.rounds);
    g.t0 = call_start;
    report.rounds += again.rounds;
    report.added += again.added;
    report.candidates += again.candidates;
    report.merged += again.merged;
    report.high_energy += again.high_energy;
    report.outside += again.outside;
    report.reassigned += again.reassigned;
    report.displaced += again.displaced;
    report.filled += again.filled;
    report.bound_hit = report.bound_hit || again.bound_hit;
    return done.squeezed;
}

}  // namespace

namespace {

// The surplus of a covered region removed (grow/thinning.hpp), last, so that nothing after
// it adds elements back; the holes it may still open (its test of each removal follows one
// local maximum of the clearance) go through the covered-hole fill again.
void thin_to_density(Grower::Impl& g, const Domain& region, int start, GrowReport& report) {
    const int thinned = grow::thin_to_density(g, start, region);
    report.thinned += thinned;
    report.added -= thinned;
    if (thinned == 0) return;
    const int filled = grow::fill_covered_holes(g, start, static_cast<int>(g.out.size()), region);
    report.filled += filled;
    report.added += filled;
}

}  // namespace

GrowReport Grower::grow(const Domain& region, RegionEdge edge) {
    Impl& g = *impl_;
    struct OpenFor {  // the edge rule holds for this call only, also when it throws
        bool& flag;
        ~OpenFor() { flag = false; }
    } open_for{g.open_region};
    g.open_region = edge == RegionEdge::open;
    if (region.dimension() != g.metric.dimension)
        throw Error(ErrorKind::domain, "region: " + std::to_string(region.dimension()) +
                                           "D, the exemplar is " + std::to_string(g.metric.dimension) + "D");
    if (!(region.measure() > 0.0))
        throw Error(ErrorKind::domain, "region: it is empty (zero area or volume)");
    const double reach = g.metric.patch_radius + g.metric.params.radius;
    int seeded = 0;
    if (g.out.empty()) seed(region.closest_inside(region.bounds().center()));
    size_t start = g.out.size();  // the call's elements: from here on
    if (g.seed_pending) {  // the seed patches, kept where they fit the region
        const int first = g.round_first.back(), n = static_cast<int>(g.out.size());
        start = static_cast<size_t>(first);  // the call made them
        std::vector<char> keep(n - first);
        std::vector<Vec3> samples;
        for (int i = first; i < n; ++i)
            keep[i - first] = g.fits_region(region, -1, g.out[i].source, g.out[i].frame, g.out[i].p, samples);
        g.drop_tail(first, keep);
        g.horizon.clear();
        for (int i = first; i < static_cast<int>(g.out.size()); ++i) g.horizon.push_back(i);
        g.seed_pending = false;
        if (g.horizon.empty())
            throw Error(ErrorKind::domain, "region: too small to hold the exemplar's elements");
        seeded = static_cast<int>(g.horizon.size());
    } else {
        std::vector<int> near = elements_near(g, region, reach);
        if (near.empty())
            throw Error(ErrorKind::input, "region: it does not touch the arrangement (no element within " +
                                              std::to_string(reach) +
                                              " of it) and growth adds only next to elements");
        g.horizon = std::move(near);
    }
    extend(g.grown, g.has_bounds, region.bounds());
    const double per_element = g.exemplar.domain.measure() / std::max<size_t>(1, g.exemplar.elements.size());
    const double expected = region.measure() / per_element;
    grow::RoundLimits limits;
    limits.region = &region;
    GrowReport report = run_rounds(
        g, limits, [](const GrowReport&) { return false; },
        [&](const GrowReport&) {
            return 0.99 * std::min(1.0, (g.out.size() - start - seeded) / std::max(1.0, expected));
        },
        seeded, false);
    // Covered: the last two rounds are enclosed now (by later elements or the region's outside).
    const size_t r = g.round_first.size();
    if (report.covered && r > 0) {
        const int filled = grow::fill_enclosed_holes(g, g.round_first[r >= 2 ? r - 2 : 0],
                                                     static_cast<int>(g.out.size()), &region);
        report.filled += filled;
        report.added += filled;
        if (filled > 0) g.dirty = true;
    }
    if (report.covered && !g.options.stop_at_horizon) {
        const int uncovered = grow::fill_uncovered(g, region, arrangement());
        report.uncovered += uncovered;
        report.added += uncovered;
    }
    const int squeezed = report.covered ? complete_rare_types(g, region, static_cast<int>(start), report) : 0;
    // Squeezed elements stood at pushed distances the rounds around them did not solve:
    // one more sweep (two classes: PCF error 0.144-0.157 with one, 0.134-0.148 with two).
    const int extra_sweeps = squeezed > 0 && g.options.relax_sweeps < 0 ? 1 : 0;
    grow::relax_pair_correlation(g, region, static_cast<int>(start), report, extra_sweeps);
    // In a world's tile only holes closed toward its faces (grow/vacancies.hpp).
    if (report.covered) {
        const int filled = grow::fill_covered_holes(g, static_cast<int>(start), static_cast<int>(g.out.size()), region);
        report.filled += filled;
        report.added += filled;
    }
    if (report.covered) thin_to_density(g, region, static_cast<int>(start), report);
    if (report.covered) {  // grow/sample_holes.hpp
        const int filled = grow::fill_sample_holes(g, region);
        report.filled += filled;
        report.added += filled;
    }
    report.seconds = std::chrono::duration<double>(Clock::now() - g.t0).count();
    report_progress(g, "done", report.rounds, report.rounds, 1.0, report.energy);
    g.last_report = report;
    return report;
}

GrowReport Grower::grow(int n) {
    Impl& g = *impl_;
    if (n <= 0) throw Error(ErrorKind::option, "elements: must be > 0");
    Vec3 origin;
    int seeded = 0;
    if (g.out.empty()) {
        seed(Vec3{});
        seeded = static_cast<int>(g.out.size());
    }
    for (const grow::OutElement& e : g.out) origin = origin + e.p;
    origin = origin * (1.0 / g.out.size());
    grow::RoundLimits limits;
    limits.budget = std::max(0, n - seeded);  // what the rounds may add
    limits.origin = origin;
    return run_rounds(
        g, limits, [&](const GrowReport& r) { return r.added >= n; },
        [&](const GrowReport& r) { return static_cast<double>(r.added) / n; }, seeded);
}

GrowReport Grower::step() {
    Impl& g = *impl_;
    const auto start = Clock::now();
    GrowReport report;
    if (g.out.empty()) {
        seed(Vec3{});
        report.added = static_cast<int>(g.out.size());
    }
    g.interrupt.rearm();
    const int before = report.added;
    g.seed_pending = false;
    grow::run_round(g, grow::RoundLimits{}, report);
    report.rounds = 1;
    report.covered = report.added == before;
    report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    g.last_report = report;
    return report;
}

const GrowReport& Grower::last_report() const {
    return impl_->last_report;
}

const Arrangement& Grower::arrangement() const {
    const Impl& g = *impl_;
    if (!g.dirty) return g.view;
    Arrangement a;
    a.dimension = g.exemplar.dimension;
    a.types = g.exemplar.types;
    a.attribute_names = g.exemplar.attribute_names;
    Box box;
    bool has = g.has_bounds;
    if (has) box = g.grown;
    std::vector<Vec3> samples;
    for (const grow::OutElement& o : g.out) {
        g.sample_positions(o.kept, o.source, o.frame, o.p, samples);
        const Element& from = o.kept >= 0 ? g.existing.elements[o.kept] : g.exemplar.elements[o.source];
        const int index = a.add_element(o.type, samples, from.radius);
        Element& e = a.elements[index];
        // A kept element keeps its own position bit for bit (not its recomputed centroid).
        e.position = o.kept >= 0 ? from.position : o.p;
        e.orientation = o.kept >= 0 ? from.orientation : o.frame * from.orientation;
        e.scale = from.scale;
        e.attributes = from.attributes;
        e.id = o.id;
        e.locked = o.locked && !o.filled;
        for (const Vec3& q : samples) extend(box, has, Box{q, q});
    }
    const double margin = 0.5 * g.metric.params.spacing;
    if (!has) box = Box{Vec3{}, Vec3{1, 1, 1}};
    Vec3 lo = box.lo - Vec3{margin, margin, margin}, hi = box.hi + Vec3{margin, margin, margin};
    if (a.dimension == 2) lo.z = hi.z = 0.0;
    a.domain = Domain::box(lo, hi, a.dimension);
    a.stats.method = "grow";
    a.stats.radius = g.metric.params.radius;
    a.stats.seed = g.options.seed;
    a.stats.threads = g.threads;
    g.view = std::move(a);
    g.dirty = false;
    return g.view;
}

}  // namespace tessera
