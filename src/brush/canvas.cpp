// BrushCanvas (tessera/brush.hpp): the palette, the calls a user makes, and the solver loop
// of section 5 (search/assignment over positions alternating with L-BFGS over orientations).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "brush/brush_state.hpp"
#include "brush/canvas_grow.hpp"
#include "brush/canvas_surface.hpp"
#include "brush/distribution.hpp"
#include "brush/laplacian_field.hpp"
#include "brush/orientations.hpp"
#include "brush/palette.hpp"
#include "brush/positions.hpp"
#include "brush/strokes.hpp"
#include "brush/surface.hpp"
#include "core/progress_span.hpp"
#include "core/spatial_grid.hpp"
#include "tessera/error.hpp"
#include "tessera/option_table.hpp"

namespace tessera {

using namespace brush;

double BrushCanvas::Impl::weight_of_sample(int s) const {
    const Sample& sample = arrangement.samples[s];
    const OutType& ot = out_types[arrangement.elements[sample.element].type];
    return palette[ot.kappa].weights[ot.type][sample.sample_id];
}

namespace {

// Tilt of the first guess of fill's element field (brush/canvas_grow.hpp, tilted_direction).
constexpr double kFillTilt = 0.05;

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Restores the canvas when a call throws (a cancel, a bad stroke): the call is all or nothing.
struct Transaction {
    BrushCanvas::Impl& state;
    BrushCanvas::Impl saved;
    bool done = false;
    explicit Transaction(BrushCanvas::Impl& s) : state(s), saved(s) {}
    ~Transaction() {
        if (!done) state = std::move(saved);
    }
};

void report_progress(const BrushCanvas::Impl& st, const std::string& stage, int iteration, int iterations,
                     double energy, double fraction, std::chrono::steady_clock::time_point start) {
    if (!st.progress) return;
    ProgressEvent e;
    e.stage = stage;
    e.iteration = iteration;
    e.iterations = iterations;
    e.energy = energy;
    e.elapsed_s = seconds_since(start);
    e.fraction = fraction;
    if (!st.progress(e)) throw Cancelled();
}

// While alive, the canvas's listener sees a part of the call as [from, to] of the whole.
struct ProgressPart {
    BrushCanvas::Impl& state;
    Progress whole;
    ProgressPart(BrushCanvas::Impl& s, double from, double to, const char* done_stage)
        : state(s), whole(s.progress) {
        state.progress = core::progress_within(whole, from, to, done_stage);
    }
    ~ProgressPart() { state.progress = std::move(whole); }
};

// Fill's share of its progress spent growing; the solver's iterations take the rest.
constexpr double kFillGrowthShare = 0.3;
// How far past the border of its part (in its spacings) an entry grows in fill's second pass.
constexpr double kSeamSpacings = 2.0;

double stroke_half_width(const BrushCanvas::Impl& st, const Stroke& stroke, int kappa) {
    const double spacing = kappa >= 0 ? st.palette[kappa].spacing : 1.0;
    return 0.5 * (stroke.width > 0.0 ? stroke.width : st.options.stroke_width * spacing);
}

double smallest_spacing(const BrushCanvas::Impl& st) {
    double s = std::numeric_limits<double>::infinity();
    for (const PaletteEntry& p : st.palette) s = std::min(s, p.spacing);
    return std::isfinite(s) ? s : 1.0;
}

// On a surface a stroke is moved onto it in steps of half the smallest spacing (elsewhere: as is).
Stroke canvas_stroke(const BrushCanvas::Impl& st, const Stroke& stroke, int min_points, const std::string& where) {
    return snap_stroke(st, stroke, 0.5 * smallest_spacing(st), min_points, where);
}

std::vector<char> movable_samples(const BrushCanvas::Impl& st) {
    std::vector<char> movable(st.arrangement.samples.size(), 0);
    for (const Element& e : st.arrangement.elements)
        if (!e.locked)
            for (int k = 0; k < e.sample_count; ++k) movable[e.first_sample + k] = 1;
    return movable;
}

void remove_elements(BrushCanvas::Impl& st, const std::vector<char>& remove) {
    Arrangement kept;
    static_cast<Exemplar&>(kept) = Exemplar{};
    kept.dimension = st.arrangement.dimension;
    kept.types = st.arrangement.types;
    kept.domain = st.arrangement.domain;
    std::vector<Vec3> direction, reference;
    std::vector<Quat> relative;
    const Arrangement& arr = st.arrangement;
    for (int i = 0; i < static_cast<int>(arr.elements.size()); ++i) {
        if (remove[i]) continue;
        const Element& e = arr.elements[i];
        std::vector<Vec3> points;
        for (int k = 0; k < e.sample_count; ++k) {
            points.push_back(arr.samples[e.first_sample + k].p);
            direction.push_back(st.direction[e.first_sample + k]);
            reference.push_back(st.reference[e.first_sample + k]);
        }
        const int j = kept.add_element(e.type, points, e.radius);
        Element copy = e;
        copy.first_sample = kept.elements[j].first_sample;
        kept.elements[j] = copy;
        relative.push_back(st.relative[i]);
    }
    kept.stats = arr.stats;
    st.arrangement = std::move(kept);
    st.direction = std::move(direction);
    st.reference = std::move(reference);
    st.relative = std::move(relative);
}

// Samples of two palette entries closer than this share of their summed weights overlap.
constexpr double kOverlapShare = 0.8;

// The solve's conflict term (Eq. 3) is a penalty, not a bound: where two entries' parts meet
// after a fill it left a few pairs of their samples under kOverlapShare of their summed
// weights (4 on the design example). Each such pair loses an unlocked element (the later one
// when both are), so that no elements of two entries overlap. Returns how many went.
int drop_overlaps_between_entries(BrushCanvas::Impl& st) {
    const Arrangement& arr = st.arrangement;
    const int n = static_cast<int>(arr.samples.size());
    if (n == 0 || st.palette.size() < 2) return 0;
    std::vector<Vec3> points(n);
    double reach = 0.0;
    for (int s = 0; s < n; ++s) points[s] = arr.samples[s].p, reach = std::max(reach, st.weight_of_sample(s));
    core::SpatialGrid grid;
    grid.build(points, std::max(2.0 * reach, 1e-6), st.dimension);
    auto kappa_of = [&](int s) { return st.kappa_of_element(arr.samples[s].element); };
    std::vector<char> remove(arr.elements.size(), 0);
    std::vector<int> near;
    for (int a = 0; a < n; ++a) {
        near.clear();
        const double wa = st.weight_of_sample(a);
        grid.for_each_within(points[a], wa + reach, [&](int b, double d2) {
            const double summed = kOverlapShare * (wa + st.weight_of_sample(b));
            if (b > a && kappa_of(b) != kappa_of(a) && d2 < summed * summed) near.push_back(b);
        });
        std::sort(near.begin(), near.end());  // the grid's order is not the samples'
        for (const int b : near) {
            const int ea = arr.samples[a].element, eb = arr.samples[b].element;
            const Element &ca = arr.elements[ea], &cb = arr.elements[eb];
            if (remove[ea] || remove[eb] || (ca.locked && cb.locked)) continue;
            remove[cb.locked ? ea : (ca.locked ? eb : std::max(ea, eb))] = 1;
        }
    }
    const int dropped = static_cast<int>(std::count(remove.begin(), remove.end(), 1));
    if (dropped > 0) remove_elements(st, remove);
    return dropped;
}

}  // namespace

BrushCanvas::BrushCanvas(const Domain& domain, const BrushOptions& options)
    : BrushCanvas(domain, options, domain.kind() == Domain::Kind::shell ? surface_of_shell(domain) : nullptr) {}

BrushCanvas::BrushCanvas(const TriangleMesh& surface, double thickness, const BrushOptions& options,
                         const std::string& name)
    : BrushCanvas(Domain::shell(surface, thickness, 128, name), options,
                  std::make_shared<const Surface>(surface, thickness, name)) {}

BrushCanvas::BrushCanvas(const Domain& domain, const BrushOptions& options, std::shared_ptr<const brush::Surface> surface)
    : impl_(std::make_unique<Impl>()) {
    impl_->surface = std::move(surface);
    check_options(brush_option_table(), options);
    if (!(domain.measure() > 0.0)) throw Error(ErrorKind::domain, "canvas: the domain is empty");
    impl_->domain = domain;
    impl_->options = options;
    impl_->dimension = domain.dimension();
    impl_->arrangement.dimension = domain.dimension();
    impl_->arrangement.domain = domain;
    impl_->arrangement.types.clear();
    impl_->arrangement.stats.method = "brush";
    impl_->arrangement.stats.seed = options.seed;
}

BrushCanvas::~BrushCanvas() = default;
BrushCanvas::BrushCanvas(BrushCanvas&&) noexcept = default;
BrushCanvas& BrushCanvas::operator=(BrushCanvas&&) noexcept = default;
BrushCanvas::BrushCanvas(const BrushCanvas& other) : impl_(std::make_unique<Impl>(*other.impl_)) {}

int BrushCanvas::add_exemplar(const std::string& name, const Exemplar& exemplar) {
    Impl& st = *impl_;
    if (name.empty()) throw Error(ErrorKind::input, "palette: an entry needs a name");
    if (find_exemplar(name) >= 0) throw Error(ErrorKind::input, "palette: the name '" + name + "' is used already");
    PaletteEntry entry = prepare_entry(name, exemplar, st.dimension, st.options);
    const int kappa = static_cast<int>(st.palette.size());
    for (int t = 0; t < static_cast<int>(exemplar.types.size()); ++t) {
        ElementType type = exemplar.types[t];
        if (st.arrangement.find_type(type.name) >= 0) type.name += " (" + name + ")";
        type.weights = entry.weights[t];
        type.graph = entry.graph[t];
        entry.out_type.push_back(static_cast<int>(st.arrangement.types.size()));
        st.arrangement.types.push_back(std::move(type));
        st.out_types.push_back({kappa, t});
    }
    index_neighbourhoods(entry);
    st.palette.push_back(std::move(entry));
    st.names.push_back(name);
    return kappa;
}

int BrushCanvas::find_exemplar(const std::string& name) const {
    for (size_t i = 0; i < impl_->names.size(); ++i)
        if (impl_->names[i] == name) return static_cast<int>(i);
    return -1;
}

const std::vector<std::string>& BrushCanvas::palette() const { return impl_->names; }

BrushReport BrushCanvas::paint(int exemplar, const Stroke& stroke) {
    Impl& st = *impl_;
    const auto start = std::chrono::steady_clock::now();
    if (exemplar < 0 || exemplar >= static_cast<int>(st.palette.size()))
        throw Error(ErrorKind::input, "paint: no palette entry " + std::to_string(exemplar));
    check_stroke(stroke, st.dimension, 1, "paint");
    const Stroke on = canvas_stroke(st, stroke, 1, "paint");
    Transaction t(st);
    report_progress(st, "paint", -1, 1, 0.0, 0.0, start);
    const Domain band = stroke_band(st.space(), on, stroke_half_width(st, on, exemplar));
    const double spacing = st.palette[exemplar].spacing;
    const OrientationField field =
        on.points.size() >= 2 ? canvas_field(st, OrientationField::polyline(on.points))
                              : interpolate_strokes(st.space(), st.strokes, spacing, st.options.sigma * spacing, st.surface.get());
    const int first = static_cast<int>(st.arrangement.elements.size());
    const auto [added, dropped] = [&] {
        const ProgressPart part(st, 0.0, 0.95, "paint");
        return grow_entry(st, exemplar, band, field, on.points.front());
    }();
    for (int i = first; i < static_cast<int>(st.arrangement.elements.size()); ++i) st.arrangement.elements[i].locked = true;
    if (on.points.size() >= 2) st.strokes.push_back(on);
    BrushReport r;
    r.added = added;
    r.removed = dropped;
    r.seconds = seconds_since(start);
    report_progress(st, "done", 0, 1, 0.0, 1.0, start);
    t.done = true;
    return r;
}

BrushReport BrushCanvas::direct(const Stroke& stroke) {
    check_stroke(stroke, impl_->dimension, 2, "direction");
    impl_->strokes.push_back(canvas_stroke(*impl_, stroke, 2, "direction"));
    return {};
}

BrushReport BrushCanvas::erase(const Stroke& stroke) {
    Impl& st = *impl_;
    check_stroke(stroke, st.dimension, 1, "erase");
    const Stroke on = canvas_stroke(st, stroke, 1, "erase");
    const double half = stroke_half_width(st, on, st.palette.empty() ? -1 : 0);
    std::vector<char> remove(st.arrangement.elements.size(), 0);
    BrushReport r;
    for (size_t i = 0; i < remove.size(); ++i)
        if (distance_to_stroke(on, st.arrangement.elements[i].position) <= half) remove[i] = 1, ++r.removed;
    remove_elements(st, remove);
    return r;
}

namespace {

// The elements of `entries` before the fill grows anything: their places and entries. Every
// entry's part of the canvas is measured against these: measured against the canvas as the
// earlier entries' growth left it, a later entry's part lost the cells next to their new
// elements, which no entry then filled (a band between two painted parts stayed empty).
struct PaintedPlaces {
    std::vector<Vec3> position;
    std::vector<int> kappa;
};
PaintedPlaces painted_places(const BrushCanvas::Impl& st, const std::vector<char>& entries) {
    PaintedPlaces places;
    for (const Element& e : st.arrangement.elements) {
        const int k = st.out_types[e.type].kappa;
        if (!entries[k]) continue;
        places.position.push_back(e.position);
        places.kappa.push_back(k);
    }
    return places;
}

// Whether p is no more than `margin` further from entry k's nearest painted place than from
// any other entry's (margin 0: the part of the canvas nearest to entry k; a brute-force scan:
// fill runs it over the cells of a coarse grid, against the painted elements only).
bool near_part(const PaintedPlaces& places, const Vec3& p, int k, double margin) {
    double own = std::numeric_limits<double>::infinity(), other = own;
    for (size_t i = 0; i < places.position.size(); ++i) {
        double& nearest = places.kappa[i] == k ? own : other;
        nearest = std::min(nearest, norm(places.position[i] - p));
    }
    return own <= other + margin;
}

double weighted_energy(const BrushOptions& o, const BrushCanvas::Energies& e) {
    return o.w_distribution * e.distribution + o.w_conflict * e.conflict + o.w_graph * e.graph +
           o.w_alignment * e.alignment + o.w_continuity * e.continuity + o.w_rigidity * e.rigidity;
}

// The terms per sample, the distribution term from the matches of a search (of the samples it
// matched), the others from the arrangement.
BrushCanvas::Energies measure_energies(const BrushCanvas::Impl& st, const std::vector<SampleMatch>& matches) {
    BrushCanvas::Energies e;
    const size_t n = st.arrangement.samples.size();
    if (n == 0) return e;
    for (const SampleMatch& m : matches) e.distribution += m.cost;
    OutputNeighbours nb;
    nb.build(st);
    for_each_conflict(st, nb, [&](int, int, double summed, double d) { e.conflict += (summed - d) * (summed - d); });
    const Arrangement& arr = st.arrangement;
    for (const Element& el : arr.elements) {
        const OutType& ot = st.out_types[el.type];
        for (const auto& edge : st.palette[ot.kappa].graph[ot.type]) {
            const int a = el.first_sample + edge[0], b = el.first_sample + edge[1];
            const Vec3 want = st.frame_of_sample(a).rotate(st.reference[b] - st.reference[a]) * el.scale;
            e.graph += squared_norm(arr.samples[b].p - arr.samples[a].p - want);  // Eq. 4
        }
    }
    const FieldEnergies f = field_energies(st);
    e.alignment = f.alignment, e.continuity = f.continuity, e.rigidity = f.rigidity;
    const double per = 1.0 / static_cast<double>(n);
    e.distribution *= per, e.conflict *= per, e.graph *= per, e.alignment *= per, e.continuity *= per, e.rigidity *= per;
    return e;
}

}  // namespace

BrushReport BrushCanvas::fill(const std::vector<int>& exemplars) {
    Impl& st = *impl_;
    const auto start = std::chrono::steady_clock::now();
    for (int k : exemplars)
        if (k < 0 || k >= static_cast<int>(st.palette.size()))
            throw Error(ErrorKind::input, "fill: no palette entry " + std::to_string(k));
    if (exemplars.empty() && st.arrangement.elements.empty())
        throw Error(ErrorKind::input, "fill: the canvas is empty; name the palette entries to fill it with");
    Transaction t(st);
    report_progress(st, "fill", -1, 1, 0.0, 0.0, start);
    std::vector<char> entries(st.palette.size(), 0);
    bool any_present = false;
    for (const Element& e : st.arrangement.elements) {
        const int k = st.out_types[e.type].kappa;
        if (exemplars.empty() || std::find(exemplars.begin(), exemplars.end(), k) != exemplars.end())
            entries[k] = 1, any_present = true;
    }
    const double spacing = smallest_spacing(st);
    const OrientationField field =
        interpolate_strokes(st.space(), st.strokes, spacing, st.options.sigma * spacing, st.surface.get());
    BrushReport r;
    if (!any_present) {  // nothing of the chosen entries yet: the first grows over the canvas
        const ProgressPart part(st, 0.0, kFillGrowthShare, "fill");
        const auto [added, dropped] = grow_entry(st, exemplars.front(), st.space(), field, st.space().bounds().center(), kFillTilt);
        r.added += added, r.removed += dropped;
    } else {
        const int parts = static_cast<int>(std::count(entries.begin(), entries.end(), 1));
        const PaintedPlaces painted = painted_places(st, entries);
        // Each entry grows over its part, then (several parts) over its part widened past the
        // border by kSeamSpacings of its spacing, next to what it and the others grew: the
        // conflict check drops an entry's elements where the other's stand, and the first
        // pass left a seam where the parts meet (a bare band across the surface demo's blob).
        const int passes = parts > 1 ? 2 : 1;
        for (int pass = 0, part = 0; pass < passes; ++pass)
            for (int k = 0; k < static_cast<int>(entries.size()); ++k) {
                if (!entries[k]) continue;
                const double share = kFillGrowthShare / (parts * passes);
                const ProgressPart progress_part(st, share * part, share * (part + 1), "fill");
                ++part;
                const double margin = pass == 0 ? 0.0 : kSeamSpacings * st.palette[k].spacing;
                std::optional<Domain> region;
                try {  // the cells nearer to an element of entry k than to any other entry's (+ margin)
                    region = Domain::region(
                        st.space(), [&](const Vec3& p) { return near_part(painted, p, k, margin); }, 0.5 * spacing,
                        "the part of the canvas nearest to '" + st.names[k] + "'");
                } catch (const Error&) {
                    continue;  // no cell of the canvas is nearest to it
                }
                const auto [added, dropped] =
                    grow_entry(st, k, *region, field, region->bounds().center(), kFillTilt, RegionEdge::open);
                r.added += added, r.removed += dropped;
            }
    }
    const BrushReport solved = [&] {
        const ProgressPart part(st, kFillGrowthShare, 1.0, "done");
        return optimize(st.options.iterations);
    }();
    r.iterations = solved.iterations;
    r.removed += solved.removed;
    r.lbfgs_bound_hits = solved.lbfgs_bound_hits;
    r.energy = solved.energy;
    r.seconds = seconds_since(start);
    t.done = true;
    return r;
}

BrushReport BrushCanvas::optimize(int iterations) {
    Impl& st = *impl_;
    const auto start = std::chrono::steady_clock::now();
    if (iterations < 0) throw Error(ErrorKind::option, "iterations must be >= 0, got " + std::to_string(iterations));
    Transaction t(st);
    const std::vector<char> movable = movable_samples(st);
    // Every sample is searched (the locked ones' matches enter the energy, not the solve), so
    // that each measured state's energies are those of the whole canvas, as energies() gives.
    const std::vector<char> everything(st.arrangement.samples.size(), 1);
    std::vector<SampleMatch> matches;
    BrushReport r;
    // The alternation is a heuristic (the search re-pairs every iteration), so the energy need
    // not fall at every iteration: the best state seen is kept. A state is measured by the
    // search that follows its orientation solve (only samples and orientations change here).
    double best = std::numeric_limits<double>::infinity();
    Energies best_energies, kept;
    Arrangement best_arrangement;
    std::vector<Vec3> best_direction;
    for (int it = 0; it <= iterations; ++it) {
        if (it < iterations) {
            report_progress(st, "iteration", it, iterations, std::isfinite(best) ? best : 0.0,
                            static_cast<double>(it) / iterations, start);
            // The orientations first: the search pairs neighbourhoods in each sample's frame,
            // and the assignment rotates the pairs' targets by it, so both see the same o(s).
            const OrientationResult o = solve_orientations(st, movable);  // Eq. 5-7 (L-BFGS)
            if (o.bound_hit) ++r.lbfgs_bound_hits;
        }
        search_matches(st, everything, matches);  // Eq. 1-2
        const Energies measured = measure_energies(st, matches);
        const double now = weighted_energy(st.options, measured);
        const bool improved = now < best;
        if (it == iterations) {
            kept = measured;
            if (!improved && iterations > 0) {
                st.arrangement = std::move(best_arrangement);
                st.direction = std::move(best_direction);
                kept = best_energies;
                r.kept_earlier = true;
            }
            break;
        }
        if (improved) best = now, best_energies = measured, best_arrangement = st.arrangement, best_direction = st.direction;
        if (assign_positions(st, movable, matches)) ++r.solve_bound_hits;  // Eq. 1, 3, 4
        ++r.iterations;
    }
    r.removed += drop_overlaps_between_entries(st);
    const Energies& e = kept;
    r.energy = e.distribution + e.conflict + e.graph + e.alignment + e.continuity + e.rigidity;
    st.arrangement.stats.final_energy = r.energy;
    r.seconds = seconds_since(start);
    report_progress(st, "done", iterations, iterations, r.energy, 1.0, start);
    t.done = true;
    return r;
}

void BrushCanvas::set_progress(Progress progress) { impl_->progress = std::move(progress); }
const Arrangement& BrushCanvas::arrangement() const { return impl_->arrangement; }
const std::vector<Vec3>& BrushCanvas::sample_directions() const { return impl_->direction; }
const std::vector<Stroke>& BrushCanvas::direction_strokes() const { return impl_->strokes; }
const Domain& BrushCanvas::domain() const { return impl_->domain; }
const BrushOptions& BrushCanvas::options() const { return impl_->options; }

std::vector<int> BrushCanvas::sample_exemplars() const {
    std::vector<int> k;
    for (const Sample& s : impl_->arrangement.samples) k.push_back(impl_->kappa_of_element(s.element));
    return k;
}

BrushCanvas::Energies BrushCanvas::energies() const {
    const Impl& st = *impl_;
    std::vector<SampleMatch> matches;
    search_matches(st, std::vector<char>(st.arrangement.samples.size(), 1), matches);
    return measure_energies(st, matches);
}

}  // namespace tessera
