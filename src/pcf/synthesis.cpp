// PCF synthesis (pcf_synthesis.hpp): output counts and radii (section 4.3), then per
// class in the model's topological order: initialisation (Algorithm 1), refinement
// (Eq. 4 to 6) against the class's own PCF and its parent edges (section 3.2; parents
// stay where they are), and re-placement of the elements whose individual PCFs leave the
// validity region (section 6.4). docs/pcf_synthesis.md describes the whole method.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <sstream>

#include "core/parallel.hpp"
#include "core/run_clock.hpp"
#include "core/rng.hpp"
#include "pcf/sparse_classes.hpp"
#include "pcf/synth_steps.hpp"
#include "tessera/error.hpp"
#include "tessera/option_table.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera {

namespace {

using core::Clock;
using core::report;
using core::seconds_since;

// An element's individual PCF further outside the validity region than this (the
// envelope term of Eq. 11: relative to the bound) makes it an outlier (section 6.4):
// above its upper envelope by 90% of the envelope, or below 10% of its lower envelope.
constexpr double kOutlierTolerance = 0.9;
// At most this share of a class, and at most kOutlierMax elements, are re-placed per
// outlier round (the worst first). The re-placement of a complete class ends in grid
// search (every dart fails), 64 x 64 candidates per element: the count bound keeps a
// round's cost independent of the class's size.
constexpr double kOutlierShare = 0.1;
constexpr size_t kOutlierMax = 16;
// An outlier round may raise the class's PCF error (sum of squares) by this much.
constexpr double kOutlierSlack = 0.1;
// Initialisation reports progress this often (seconds of work) at most.
constexpr double kTickSeconds = 0.25;

// Every option against its row of the table (tessera/option_table.hpp), naming the field.
void check_options(const PcfSynthOptions& o) { tessera::check_options(pcf_option_table(), o); }

[[noreturn]] void bad_model(const std::string& message) { throw Error(ErrorKind::input, "PCF model: " + message); }

// A model from a file may be inconsistent: check everything synthesis indexes.
void check_model(const PcfModel& m) {
    const int classes = static_cast<int>(m.classes.size());
    if (classes == 0) bad_model("no classes");
    const PcfAnalysisSettings& s = m.settings;
    if (!(std::isfinite(s.sigma) && s.sigma > 0.0 && std::isfinite(s.step) && s.step > 0.0 &&
          std::isfinite(s.extent) && s.extent > 0.0))
        bad_model("sigma, step and extent must be numbers > 0");
    const int bins = pcf::make_axis(s, m.disks).bins;
    if (static_cast<int>(m.x.size()) != bins)
        bad_model("the axis has " + std::to_string(m.x.size()) + " values, its settings give " + std::to_string(bins));
    if (!(std::isfinite(m.r_max) && m.r_max > 0.0)) bad_model("r_max must be a number > 0");
    if (!(std::isfinite(m.area) && m.area > 0.0)) bad_model("area must be a number > 0");
    if (static_cast<int>(m.parents.size()) != classes || static_cast<int>(m.counts.size()) != classes ||
        static_cast<int>(m.radii.size()) != classes)
        bad_model("parents, counts and radii need one entry per class");
    std::vector<int> position(classes, -1);
    if (static_cast<int>(m.order.size()) != classes) bad_model("the order must list every class once");
    for (int k = 0; k < classes; ++k) {
        const int c = m.order[k];
        if (c < 0 || c >= classes || position[c] >= 0) bad_model("the order must list every class once");
        position[c] = k;
    }
    for (int c = 0; c < classes; ++c) {
        if (m.counts[c] < 0) bad_model("class '" + m.classes[c] + "' has a negative count");
        for (double r : m.radii[c])
            if (!(std::isfinite(r) && r >= 0.0)) bad_model("class '" + m.classes[c] + "' has a radius that is not >= 0");
        for (int p : m.parents[c])
            if (p < 0 || p >= classes || position[p] >= position[c])
                bad_model("class '" + m.classes[c] + "' has a parent that is not before it in the order");
    }
    for (const PcfEnvelope& e : m.pcfs) {
        if (e.parent < 0 || e.parent >= classes || e.child < 0 || e.child >= classes)
            bad_model("a PCF names a class that does not exist");
        if (position[e.parent] > position[e.child]) bad_model("a PCF's parent comes after its child in the order");
        if (static_cast<int>(e.mean.size()) != bins || static_cast<int>(e.lower.size()) != bins ||
            static_cast<int>(e.upper.size()) != bins)
            bad_model("the PCF of " + m.classes[e.parent] + " -> " + m.classes[e.child] + " does not have " +
                      std::to_string(bins) + " values");
        for (int k = 0; k < bins; ++k)
            if (!std::isfinite(e.mean[k]) || !std::isfinite(e.lower[k]) || !std::isfinite(e.upper[k]))
                bad_model("the PCF of " + m.classes[e.parent] + " -> " + m.classes[e.child] + " has a value that is not finite");
    }
    for (const PcfSparseClass& sc : m.sparse)
        if (sc.cls < 0 || sc.cls >= classes || static_cast<int>(sc.closest.size()) != classes ||
            static_cast<int>(sc.tether.size()) != classes || !(std::isfinite(sc.spacing) && sc.spacing >= 0.0))
            bad_model("a sparse class needs a class, a spacing >= 0 and one closest approach and tether per class");
    for (int c = 0; c < classes; ++c)
        if (m.counts[c] < kPcfSparseCount && !pcf::sparse_class(m, c))
            bad_model("class '" + m.classes[c] + "' has " + std::to_string(m.counts[c]) +
                      " elements and no entry in the sparse classes");
    for (const PcfSeparation& sep : m.separations)
        if (sep.a < 0 || sep.a >= classes || sep.b < 0 || sep.b >= classes || sep.a == sep.b ||
            !(std::isfinite(sep.x) && sep.x >= 0.0))
            bad_model("a separation needs two different classes and a distance >= 0");
}

// Section 4.3: the exemplar's radii repeated as often as they fit, the shortfall drawn at
// random without repeats, sorted largest first.
std::vector<double> output_radii(const std::vector<double>& input, int n, std::uint64_t seed, int c) {
    std::vector<double> out;
    if (n <= 0) return out;
    if (input.empty()) return std::vector<double>(n, 0.0);
    const int m = static_cast<int>(input.size());
    for (int k = 0; k + m <= n; k += m) out.insert(out.end(), input.begin(), input.end());
    const int rest = n - static_cast<int>(out.size());
    std::vector<int> index(m);
    std::iota(index.begin(), index.end(), 0);
    const core::KeyedRng rng(seed, core::Purpose::pcf_radii, static_cast<std::uint64_t>(c));
    for (int k = 0; k < rest; ++k) {  // partial Fisher-Yates
        const int pick = k + static_cast<int>(rng.below(k, static_cast<std::uint64_t>(m - k)));
        std::swap(index[k], index[pick]);
        out.push_back(input[index[k]]);
    }
    std::sort(out.begin(), out.end(), std::greater<>());
    return out;
}

std::string format(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

// What the fallback for a class with few elements did, for the notes.
std::string sparse_note(const PcfModel& m, const PcfSparseClass& sc, int placed) {
    const int n = m.counts[sc.cls];
    std::string note = "class '" + m.classes[sc.cls] + "' has " + std::to_string(n) + (n == 1 ? " element" : " elements") +
                       " in the exemplar, too few for PCFs: its " + std::to_string(placed) +
                       " elements were placed at random (same density) at least " + format(sc.spacing) +
                       " apart, no closer to any class than in the exemplar";
    std::string tethers;
    for (size_t o = 0; o < sc.tether.size(); ++o)
        if (sc.tether[o] > 0.0)
            tethers += (tethers.empty() ? "" : ", ") + ("'" + m.classes[o] + "'") + " within x = " + format(sc.tether[o]);
    if (!tethers.empty()) note += ", each with a " + tethers;
    return note + " (its PCFs and its children's PCFs on it were not used)";
}

// The fixed elements of synthesize_pcf_next_to, checked: the model's classes, single
// samples, inside the domain.
std::vector<pcf::FixedElem> fixed_elements(const PcfModel& model, const Domain& domain, const Exemplar& fixed) {
    std::vector<pcf::FixedElem> out;
    for (const Element& e : fixed.elements) {
        if (e.type < 0 || e.type >= static_cast<int>(model.classes.size()) ||
            fixed.types[e.type].name != model.classes[e.type])
            throw Error(ErrorKind::input, "fixed element " + std::to_string(e.id) + ": its type is not the model's class " +
                                              std::to_string(e.type));
        if (e.sample_count != 1) throw Error(ErrorKind::input, "fixed element " + std::to_string(e.id) + ": the PCF method's elements have one sample");
        if (!domain.inside(e.position))
            throw Error(ErrorKind::input, "fixed element " + std::to_string(e.id) + " lies outside the output domain");
        out.push_back({e.type, e.position, e.radius});
    }
    return out;
}

Arrangement synthesize(const PcfModel& model, const Domain& domain, const std::vector<pcf::FixedElem>& fixed,
                       const Domain& fill, const PcfSynthOptions& options, const Progress& progress);

}  // namespace

Arrangement synthesize_pcf(const PcfModel& model, const Domain& domain, const PcfSynthOptions& options,
                           const Progress& progress) {
    return synthesize(model, domain, {}, domain, options, progress);
}

Arrangement synthesize_pcf_next_to(const PcfModel& model, const Domain& domain, const Exemplar& fixed,
                                   const Domain& fill, const PcfSynthOptions& options, const Progress& progress) {
    check_model(model);
    return synthesize(model, domain, fixed_elements(model, domain, fixed), fill, options, progress);
}

namespace {

Arrangement synthesize(const PcfModel& model, const Domain& domain, const std::vector<pcf::FixedElem>& fixed,
                       const Domain& fill, const PcfSynthOptions& options, const Progress& progress) {
    const auto t0 = Clock::now();
    check_options(options);
    check_model(model);
    if (domain.dimension() != 2)
        throw Error(ErrorKind::domain, "the PCF method synthesizes in 2D; the output domain is 3D");
    const int threads = core::resolve_threads(options.threads);
    const int classes = static_cast<int>(model.classes.size());

    // Counts = the exemplar's density x the area to fill, per class (the whole domain, or
    // the part the fixed elements leave: they already stand at that density in theirs).
    const double area = fill.measure();
    std::vector<std::vector<double>> radii(classes);
    for (int c = 0; c < classes; ++c) {
        const double expected = model.counts[c] / model.area * area;
        const int n = static_cast<int>(std::lround(expected));
        if (model.counts[c] > 0 && n < 1 && fixed.empty())
            throw Error(ErrorKind::domain, "the output domain " + domain.describe() + " (area " + format(area) +
                                               ") is too small for one element of class '" + model.classes[c] +
                                               "' (" + format(expected) + " expected)");
        radii[c] = output_radii(model.radii[c], n, options.seed, c);
    }

    Arrangement out;
    RunStats& stats = out.stats;
    stats.method = "pcf";
    stats.seed = options.seed;
    stats.threads = threads;
    stats.radius = model.r_max;

    pcf::State state(model, domain, radii, fixed);
    state.fill = &fill;
    pcf::InitSettings init;
    init.seed = options.seed;
    init.threads = threads;
    init.epsilon0 = options.epsilon0;
    init.epsilon_step = options.epsilon_step;
    init.max_fails = options.max_fails;
    init.grid_cells = options.grid_cells;
    pcf::Scratch scratch(state);

    // Progress: sweeps are numbered over the whole run; the plan is the most there can be:
    // max_iterations per class and a quarter of that per outlier round.
    const int outlier_sweeps = options.max_iterations > 0 ? std::max(1, options.max_iterations / 4) : 0;
    const int planned = (options.max_iterations + options.outlier_rounds * outlier_sweeps) * classes;
    int sweep_index = 0;
    // The progress fraction: classes done, and the current class's sweeps of its most.
    int classes_done = 0, class_sweeps = 0;
    const auto share_done = [&] {
        const double current = std::min(1.0, class_sweeps / std::max(1.0, 1.0 * options.max_iterations));
        return 0.97 * (classes_done + current) / std::max(1, classes);
    };
    double init_seconds = 0.0;
    auto sweep_start = Clock::now();
    // Placements report at most every kTickSeconds (a grid search takes up to ~50 ms).
    auto last_tick = Clock::now();
    const auto tick = [&] {
        if (seconds_since(last_tick) < kTickSeconds) return;
        last_tick = Clock::now();
        report(progress, {"init", -1, planned, 0.0, seconds_since(t0), share_done()});
    };
    const auto on_sweep = [&](double energy) {
        stats.energy.push_back(energy);
        stats.iteration_seconds.push_back(seconds_since(sweep_start));
        ++sweep_index, ++class_sweeps;
        report(progress, {"iteration", sweep_index - 1, planned, energy, seconds_since(t0), share_done()});
        sweep_start = Clock::now();
    };
    const auto run_init = [&](int c, const std::vector<int>& elements, int round) {
        const auto ti = Clock::now();
        init.round = round;
        const pcf::InitReport r = pcf::initialise(state, c, elements, init, tick);
        init_seconds += seconds_since(ti);
        stats.fallbacks += r.by_grid + r.by_fallback;
        const std::string name = "class '" + model.classes[c] + "'";
        const std::string when = round == 0 ? "" : " (outlier round " + std::to_string(round) + ")";
        if (r.by_grid > 0)
            stats.notes.push_back("grid search placed " + std::to_string(r.by_grid) + " of " +
                                  std::to_string(elements.size()) + " elements of " + name + when + " after " +
                                  std::to_string(options.max_fails) + " successive rejections");
        if (r.by_fallback > 0)
            stats.notes.push_back("no grid cell was inside the domain: " + std::to_string(r.by_fallback) +
                                  " elements of " + name + when + " were placed at random points");
    };
    // A class with too few elements for PCFs: the fallback of PcfSparseClass.
    const auto run_sparse = [&](const PcfSparseClass& sc, const std::vector<int>& elements) {
        const auto ti = Clock::now();
        const pcf::SparseReport r = pcf::place_sparse(state, sc, elements, options.seed, tick);
        init_seconds += seconds_since(ti);
        stats.notes.push_back(sparse_note(model, sc, static_cast<int>(elements.size())));
        if (r.by_bound > 0) {
            ++stats.solver_bound_hits;
            stats.notes.push_back("class '" + model.classes[sc.cls] + "': " + std::to_string(r.by_bound) +
                                  " elements placed at the best of their darts (bound reached), up to " +
                                  format(r.worst) + " r_max inside the fallback's distances");
        }
    };
    // Returns 1 when the refinement stopped at its sweep bound, not by convergence.
    const auto run_refine = [&](int c, const std::vector<int>& elements, int sweeps) {
        sweep_start = Clock::now();
        const pcf::RefineReport r = pcf::refine(state, c, elements, sweeps, options.convergence, options.stall, threads,
                                                    on_sweep);
        return r.sweeps > 0 && !r.converged ? 1 : 0;
    };

    for (int c : model.order) {
        class_sweeps = 0;
        report(progress, {"init", -1, planned, 0.0, seconds_since(t0), share_done()});
        state.insert_fixed(c);
        const std::vector<int>& members = state.members[c];
        if (const PcfSparseClass* sparse = pcf::sparse_class(model, c)) {
            run_sparse(*sparse, members);
            ++classes_done;
            continue;
        }
        run_init(c, members, 0);
        stats.solver_bound_hits += run_refine(c, members, options.max_iterations);
        // Section 6.4: re-place the elements whose individual PCFs left the validity
        // region, then refine the class again (a quarter of the sweeps); a round that
        // makes the class's PCF error worse by more than kOutlierSlack is undone.
        const auto class_error = [&] {
            double e = 0.0;
            for (int t : state.class_terms[c]) e += state.term_error(t);
            return e;
        };
        for (int round = 1; round <= options.outlier_rounds && !members.empty(); ++round) {
            std::vector<double> violation(members.size());
            std::vector<pcf::Scratch> per_thread(threads, scratch);
            core::parallel_for(static_cast<int>(members.size()), threads, [&](int begin, int end, int thread) {
                for (int k = begin; k < end; ++k)
                    violation[k] = pcf::envelope_violation(state, members[k], per_thread[thread]);
            });
            std::vector<int> outliers;
            for (size_t k = 0; k < members.size(); ++k)
                if (violation[k] > kOutlierTolerance) outliers.push_back(static_cast<int>(k));
            if (outliers.empty()) break;
            std::stable_sort(outliers.begin(), outliers.end(),
                             [&](int a, int b) { return violation[a] > violation[b]; });
            const size_t found = outliers.size();
            const size_t share = static_cast<size_t>(std::max(1.0, std::floor(kOutlierShare * members.size())));
            outliers.resize(std::min({found, share, kOutlierMax}));
            std::vector<int> elements;
            for (int k : outliers) elements.push_back(members[k]);
            std::sort(elements.begin(), elements.end());  // members are largest radius first

            // Only the re-placed elements and the class's elements near where they were or
            // now are take part (section 6.4 refines the class; refining its far parts
            // again costs the class's size per sweep and moves little).
            const double reach = pcf::local_reach(state, c);
            std::vector<int> local = state.near_members(c, elements, reach);
            const double before = class_error();
            const pcf::State::Snapshot snap = state.snapshot(c, local);
            for (int i : elements) state.remove(i);
            run_init(c, elements, round);
            std::vector<int> moved = state.near_members(c, elements, reach);
            moved.insert(moved.end(), local.begin(), local.end());
            std::sort(moved.begin(), moved.end());
            moved.erase(std::unique(moved.begin(), moved.end()), moved.end());
            local = std::move(moved);
            const pcf::State::Snapshot wider = state.snapshot(c, local);  // the new neighbours too
            const int bound_hit = run_refine(c, local, outlier_sweeps);
            const double after = class_error();
            std::string what = "outlier round " + std::to_string(round) + " of class '" + model.classes[c] + "': " +
                               std::to_string(elements.size()) + " of " + std::to_string(members.size()) +
                               " elements re-placed";
            if (found > elements.size())
                what += " (" + std::to_string(found) + " outliers; at most " + std::to_string(kOutlierMax) +
                        " and 10% of the class per round)";
            if (after > before * (1.0 + kOutlierSlack)) {
                state.restore(c, wider);  // the refinement's moves, then the re-placement
                state.restore(c, snap);
                stats.notes.push_back(what + ", undone (its PCF error rose from " + format(before) + " to " +
                                      format(after) + ")");
                break;
            }
            stats.solver_bound_hits += bound_hit;
            stats.notes.push_back(what + " (PCF error " + format(before) + " -> " + format(after) + ")");
        }
        ++classes_done;
    }
    stats.init_seconds = init_seconds;

    // The result: elements grouped by class, largest first within a class.
    out.dimension = 2;
    out.domain = domain;
    for (int c = 0; c < classes; ++c) {
        ElementType type;
        type.name = model.classes[c];
        std::vector<std::string> parents;
        for (int p : model.parents[c]) parents.push_back(model.classes[p]);
        type.depends_on = parents;
        out.types.push_back(type);
    }
    for (int c = 0; c < classes; ++c)
        for (int i : state.members[c]) {
            const pcf::Elem& e = state.elems[i];
            const int index = out.add_element(c, {e.p}, e.r);
            out.elements[index].id = static_cast<std::uint64_t>(index);
        }
    double final_energy = 0.0;  // of the PCFs synthesis used (not those of the sparse classes)
    for (const std::vector<int>& ts : state.class_terms)
        for (int t : ts) final_energy += state.term_error(t);
    stats.final_energy = final_energy;
    stats.total_seconds = seconds_since(t0);
    report(progress, {"done", sweep_index, planned, final_energy, stats.total_seconds, 1.0});
    return out;
}

}  // namespace

}  // namespace tessera
