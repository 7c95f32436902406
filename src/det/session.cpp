// DetSession (include/tessera/det_session.hpp): the neighbourhood method's state kept
// between calls. Pseudocode 1 of the paper is initialize() then iterate(); the sub-steps
// after every iteration keep the exemplar's bounds of crowding and holes, like the
// interleaved physics of section 5.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/parallel.hpp"
#include "core/run_clock.hpp"
#include "det/assign.hpp"
#include "det/init.hpp"
#include "det/session_state.hpp"
#include "det/session_region.hpp"
#include "det/session_steps.hpp"
#include "det/type_exchange.hpp"
#include "tessera/error.hpp"

namespace tessera {

namespace {

using core::Clock;
using core::seconds_since;

// Holes up to this many times the exemplar's largest are left alone: a larger output shows
// a slightly larger largest hole by chance alone.
constexpr double kHoleTolerance = 1.2;
// Holes this many times the exemplar's largest are filled whatever the counts (a margin below
// the 1.3 a user accepts, for the estimate of a hole's size).
constexpr double kHoleBound = 1.25;
// Holes filled during the iterations may take a type this far over its count.
constexpr double kCountAllowance = 0.01;

const Exemplar& validated(const Exemplar& exemplar) {
    exemplar.validate("exemplar");
    return exemplar;
}

// Copied elements that would sit on an existing one (closer than the exemplar's hard-core
// distance for their two types) are dropped; the others are appended.
int append_apart(det::OutputState& state, det::InitResult& init, const core::CrowdingBounds& tails, int dimension) {
    Arrangement& out = state.arrangement;
    std::vector<Vec3> existing = det::element_centroids(out.elements, dimension);
    double reach = 0.0;
    const int types = static_cast<int>(out.types.size());
    for (int a = 0; a < types; ++a)
        for (int b = 0; b < types; ++b) reach = std::max(reach, tails.hard_core(a, b));
    core::SpatialGrid grid;
    grid.build(existing, std::max(reach, 1e-9), dimension);
    std::vector<char> keep(init.arrangement.elements.size(), 1);
    for (size_t e = 0; e < keep.size(); ++e) {
        const Element& el = init.arrangement.elements[e];
        Vec3 p = el.position;
        if (dimension == 2) p.z = 0.0;
        const int near = grid.nearest(p, reach, [&](int k) {
            return norm(existing[k] - p) < tails.hard_core(el.type, out.elements[k].type);
        });
        keep[e] = near < 0;
    }
    det::keep_only(init.provenance(), keep);
    const int added = static_cast<int>(init.arrangement.elements.size());
    std::vector<int> per_type(state.type_target.size(), 0);
    for (const Element& el : init.arrangement.elements) ++per_type[el.type];
    det::append_elements(state, init);
    for (size_t t = 0; t < per_type.size(); ++t) state.type_target[t] += per_type[t];
    return added;
}

}  // namespace

DetSession::Impl::Impl(const Exemplar& ex, const DetOptions& o)
    : exemplar(validated(ex)),
      options(o),
      params(det::resolve_params(exemplar, options)),
      threads(core::resolve_threads(options.threads)),
      tails(exemplar) {
    index = det::build_input_index(exemplar, params, options.search == SearchMode::kcoherence ? options.k : 0,
                                   threads);
    const double hole_radius = kHoleTolerance * det::exemplar_hole_radius(exemplar, params.spacing, params.radius);
    vacancies.hole_radius = hole_radius;
    vacancies.count_allowance = kCountAllowance;
    vacancies.must_fill_radius = hole_radius * kHoleBound / kHoleTolerance;
    vacancies.seed = options.seed;
    search = det::SearchSettings{options.search, threads, &interrupt};
    state.arrangement.dimension = exemplar.dimension;
    state.arrangement.types = exemplar.types;
    state.arrangement.attribute_names = exemplar.attribute_names;
    state.type_target.assign(exemplar.types.size(), 0);
    RunStats& stats = state.arrangement.stats;
    stats.method = "det";
    stats.threads = threads;
    stats.seed = options.seed;
    stats.radius = params.radius;
}

void DetSession::Impl::report(const char* stage, int index_in_stage, int count, double energy) {
    const double local = count > 0 && index_in_stage >= 0 ? std::min(1.0, (index_in_stage + 1.0) / count) : 0.0;
    // Never backwards: a stage's start (index -1) within a span reports what is done so far.
    last_fraction = std::max(last_fraction, span_lo + (span_hi - span_lo) * local);
    last_event = {stage, index_in_stage, count, energy, seconds_since(t0), last_fraction};
    core::report(progress, last_event);
}

void DetSession::Impl::resend_last_event() {
    if (!progress || last_event.stage.empty()) return;
    last_event.elapsed_s = seconds_since(t0);
    core::report(progress, last_event);
}

double DetSession::Impl::iterate_once(bool whole) {
    RunStats& stats = state.arrangement.stats;
    const auto ti = Clock::now();
    const double energy = det::search_step(state, index, domain, params, search);
    const det::AssignReport assigned = det::assign_step(state, index, domain, params, threads);
    stats.energy.push_back(energy);
    stats.iteration_seconds.push_back(seconds_since(ti));
    if (!assigned.cg_converged) ++stats.solver_bound_hits;
    if (options.physics && whole) {  // the interleaved solver: extra steps after search and assign
        if (!guard) guard.emplace(det::physics_options(options, params), domain);
        if (!physics_measured) {
            const PhysicsReport before = guard->measure(state.arrangement);
            stats.penetrations_before = before.interpenetrating_pairs;
            stats.max_depth_before = before.max_depth;
            stats.floating_before = before.floating;
            physics_measured = true;
        }
        guard->step(state.arrangement);
    }
    ++rounds;
    det::keep_bounds(*this, rounds, whole);
    return energy;
}

DetSession::DetSession(const Exemplar& exemplar, const DetOptions& options)
    : impl_(std::make_unique<Impl>(exemplar, options)) {}
DetSession::~DetSession() = default;
DetSession::DetSession(DetSession&&) noexcept = default;
DetSession& DetSession::operator=(DetSession&&) noexcept = default;

void DetSession::set_progress(Progress progress) { impl_->progress = std::move(progress); }

void DetSession::set_arrangement(const Arrangement& existing) {
    Impl& s = *impl_;
    det::adopt_arrangement(s, existing);
}

const Arrangement& DetSession::arrangement() const { return impl_->state.arrangement; }

Arrangement DetSession::take_arrangement() {
    Arrangement out = std::move(impl_->state.arrangement);
    impl_->state = det::OutputState{};
    impl_->has_domain = false;
    return out;
}

void DetSession::set_domain(const Domain& domain) {
    if (domain.dimension() != impl_->exemplar.dimension)
        throw Error(ErrorKind::domain, "the output domain is " + std::to_string(domain.dimension()) +
                                           "D but the exemplar is " + std::to_string(impl_->exemplar.dimension) + "D");
    impl_->domain = domain;
    impl_->has_domain = true;
    impl_->state.arrangement.domain = domain;
}

const Domain& DetSession::domain() const { return impl_->domain; }

double DetSession::radius() const { return impl_->params.radius; }

int DetSession::initialize(const Domain& region) {
    Impl& s = *impl_;
    s.interrupt.rearm();
    const bool empty = s.state.arrangement.elements.empty();
    if (empty || !s.has_domain) set_domain(region);
    else if (region.dimension() != s.exemplar.dimension)
        throw Error(ErrorKind::domain, "the region is " + std::to_string(region.dimension()) + "D but the exemplar is " +
                                           std::to_string(s.exemplar.dimension) + "D");
    const auto t_init = Clock::now();
    s.report("patches", -1, s.options.iterations);
    det::InitResult init = det::initialize_patches(s.exemplar, s.index, region, s.params, s.options,
                                                    [&](int done, int total) { s.report("patches", done, total); });
    s.report("fill", -1, s.options.iterations);
    init.thinned = det::thin_crowds(init.provenance(), s.exemplar, region, s.params);
    det::VacancySettings vacancies = s.vacancies;
    vacancies.reach_count = true;
    init.filled = det::fill_vacancies(init.provenance(), s.exemplar, region, s.params, s.tails, vacancies).added;
    if (det::exchange_types(init.provenance(), s.exemplar, region, s.params, s.tails, s.options.seed) > 0) {
        vacancies.round = 1;
        init.filled += det::fill_vacancies(init.provenance(), s.exemplar, region, s.params, s.tails, vacancies).added;
    }
    RunStats& stats = s.state.arrangement.stats;
    if (init.structure_range > s.params.radius) {
        char note[200];
        std::snprintf(note, sizeof note,
                      "initialization patches of %.4g: the exemplar is structured up to %.4g, beyond the "
                      "neighbourhood radius %.4g (docs/det.md)",
                      init.patch_size, init.structure_range, s.params.radius);
        stats.notes.push_back(note);
    }
    int added = 0;
    if (empty) {
        added = static_cast<int>(init.arrangement.elements.size());
        det::adopt_initialization(s, std::move(init), region);
    } else {
        added = append_apart(s.state, init, s.tails, s.params.dimension);
    }
    det::number_new_elements(s.state.arrangement, s.next_id);
    stats.init_seconds += seconds_since(t_init);
    return added;
}

double DetSession::iterate(int iterations) {
    Impl& s = *impl_;
    s.interrupt.rearm();
    if (iterations < 0) throw Error(ErrorKind::option, "iterations must be >= 0, got " + std::to_string(iterations));
    double energy = 0.0;
    try {
        for (int it = 0; it < iterations; ++it) {
            energy = s.iterate_once();
            s.report("iteration", it, iterations, energy);
        }
    } catch (...) {
        det::number_new_elements(s.state.arrangement, s.next_id);
        throw;
    }
    det::number_new_elements(s.state.arrangement, s.next_id);
    return energy;
}

double DetSession::iterate(const Domain& region, int iterations) {
    Impl& s = *impl_;
    s.interrupt.rearm();
    if (iterations < 0) throw Error(ErrorKind::option, "iterations must be >= 0, got " + std::to_string(iterations));
    if (region.dimension() != s.exemplar.dimension)
        throw Error(ErrorKind::domain, "the region is " + std::to_string(region.dimension()) + "D but the exemplar is " +
                                           std::to_string(s.exemplar.dimension) + "D");
    return det::iterate_region(s, region, iterations);
}

void DetSession::finish() {
    impl_->interrupt.rearm();
    det::finish(*impl_);
}

}  // namespace tessera
