#include "det/session_steps.hpp"

#include <algorithm>

#include "core/run_clock.hpp"
#include "det/assign.hpp"
#include "det/floor.hpp"
#include "det/layers.hpp"
#include "det/pair_relaxation.hpp"
#include "det/search.hpp"
#include "det/type_exchange.hpp"
#include "tessera/error.hpp"

namespace tessera::det {

namespace {

// Holes filled during the iterations may take a type this far over its count (as at
// initialization, session.cpp).
constexpr double kCountAllowance = 0.01;

// Floor elements keep their elevation (section 5): the crowding repair moves them level only.
void hold_floor_levels(core::CrowdingRepairOptions& repair, const Arrangement& out, const Domain& domain,
                       const Params& params) {
    repair.held_level.clear();
    if (!params.floor_constraints) return;
    repair.held_level = floor_elements(out, domain, params.gravity, params.floor_distance, params.boundary);
    for (char& held : repair.held_level) held &= floor_bit;
    repair.level_axis = params.gravity.vector();
}

core::CrowdingRepairOptions repair_options(const DetSession::Impl& s) {
    core::CrowdingRepairOptions repair;
    repair.threads = s.threads;
    repair.interrupt = &s.interrupt;
    return repair;
}

// The final repair moved elements after the last physics step: settle them, guarded,
// and say how many steps the guard undid.
void settle_physics(Arrangement& out, PhysicsGuard& guard, RunStats& stats) {
    PhysicsReport reference;
    reference.interpenetrating_pairs = stats.penetrations_before;
    reference.floating = stats.floating_before;
    guard.settle(out, reference);
    if (guard.undone() > 0)
        stats.notes.push_back("physics: " + std::to_string(guard.undone()) + " of " + std::to_string(guard.steps()) +
                              " steps undone (they raised the interpenetrating pairs or the floating elements)");
}

void record_physics_result(DetSession::Impl& s) {
    RunStats& stats = s.state.arrangement.stats;
    const PhysicsReport after = s.guard->measure(s.state.arrangement);
    if (after.interpenetrating_pairs > stats.penetrations_before || after.floating > stats.floating_before)
        stats.notes.push_back("physics: the result has more interpenetrating pairs or floating elements than "
                              "before the first step (the iterations moved them; every physics step that "
                              "raised them was undone)");
    stats.physics = true;
    stats.penetrations_after = after.interpenetrating_pairs;
    stats.max_depth_after = after.max_depth;
    stats.floating_after = after.floating;
}

}  // namespace

PhysicsOptions physics_options(const DetOptions& options, const Params& params) {
    PhysicsOptions physics = options.physics_options;
    if (options.physics && physics.gravity == Vec3{})
        physics.gravity = params.gravity.vector() * (9.81 * physics.units_per_metre);
    return physics;
}

void adopt_initialization(DetSession::Impl& s, InitResult init, const Domain& region) {
    OutputState& state = s.state;
    RunStats stats = std::move(state.arrangement.stats);
    state.arrangement = std::move(init.arrangement);
    state.arrangement.stats = std::move(stats);
    state.arrangement.domain = region;
    state.key = sample_keys(state.arrangement);
    state.match = std::move(init.source_sample);
    state.source_element = std::move(init.source_element);
    state.type_target.assign(state.arrangement.types.size(), 0);
    for (size_t t = 0; t < state.type_target.size(); ++t)
        state.type_target[t] = static_cast<int>(std::lround(s.params.type_density[t] * region.measure()));
}

void append_elements(OutputState& state, InitResult& init) {
    Arrangement& out = state.arrangement;
    const int element_base = static_cast<int>(out.elements.size());
    const int sample_base = static_cast<int>(out.samples.size());
    for (Element e : init.arrangement.elements) {
        e.first_sample += sample_base;
        out.elements.push_back(std::move(e));
    }
    for (Sample smp : init.arrangement.samples) {
        smp.element += element_base;
        out.samples.push_back(smp);
    }
    // A search has not seen the new samples yet: their previous match is where they came from.
    state.match.resize(sample_base, -1);
    state.match.insert(state.match.end(), init.source_sample.begin(), init.source_sample.end());
    state.source_element.insert(state.source_element.end(), init.source_element.begin(), init.source_element.end());
    state.key = sample_keys(out);
}

void adopt_arrangement(DetSession::Impl& s, const Arrangement& existing) {
    const Exemplar& ex = s.exemplar;
    if (existing.dimension != ex.dimension)
        throw Error(ErrorKind::input, "the existing arrangement is " + std::to_string(existing.dimension) +
                                          "D but the exemplar is " + std::to_string(ex.dimension) + "D");
    existing.validate("the existing arrangement");
    // Types by name; each must be the exemplar's, with the exemplar's sample count.
    std::vector<int> type_of(existing.types.size(), -1);
    std::vector<int> samples_of(ex.types.size(), -1);
    for (const Element& e : ex.elements) samples_of[e.type] = e.sample_count;
    for (size_t t = 0; t < existing.types.size(); ++t) {
        type_of[t] = ex.find_type(existing.types[t].name);
        if (type_of[t] < 0)
            throw Error(ErrorKind::input, "the existing arrangement has type '" + existing.types[t].name +
                                              "', which the exemplar does not have");
    }
    Arrangement out;
    out.dimension = ex.dimension;
    out.types = ex.types;
    out.attribute_names = ex.attribute_names;
    out.domain = existing.domain;
    out.samples = existing.samples;
    out.elements = existing.elements;
    for (Element& e : out.elements) {
        const int t = type_of[e.type];
        if (samples_of[t] >= 0 && e.sample_count != samples_of[t])
            throw Error(ErrorKind::input, "the existing arrangement's element " + std::to_string(e.id) + " of type '" +
                                              ex.types[t].name + "' has " + std::to_string(e.sample_count) +
                                              " samples; the exemplar's have " + std::to_string(samples_of[t]));
        e.type = t;
        e.attributes.resize(ex.attribute_names.size(), 0.0);
    }
    out.stats = std::move(s.state.arrangement.stats);
    OutputState& state = s.state;
    state = OutputState{};
    state.arrangement = std::move(out);
    state.key = sample_keys(state.arrangement);
    state.match.assign(state.arrangement.samples.size(), -1);  // no previous match: the search scans
    // Attributes come from the element itself until a vote chooses an exemplar element: the
    // nearest exemplar element of the same type stands in as its source.
    state.source_element.assign(state.arrangement.elements.size(), -1);
    std::vector<int> first_of_type(ex.types.size(), -1);
    for (size_t e = 0; e < ex.elements.size(); ++e)
        if (first_of_type[ex.elements[e].type] < 0) first_of_type[ex.elements[e].type] = static_cast<int>(e);
    for (size_t e = 0; e < state.arrangement.elements.size(); ++e)
        state.source_element[e] = first_of_type[state.arrangement.elements[e].type];
    state.type_target.assign(ex.types.size(), 0);
    for (const Element& e : state.arrangement.elements) ++state.type_target[e.type];
    s.next_id = 0;
    for (const Element& e : state.arrangement.elements) s.next_id = std::max(s.next_id, e.id + 1);
    s.domain = state.arrangement.domain;
    s.has_domain = true;
    s.physics_measured = false;
    s.guard.reset();
}

core::CrowdingRepairReport keep_bounds(DetSession::Impl& s, int round, bool fill_holes) {
    OutputState& state = s.state;
    const Exemplar& exemplar = s.exemplar;
    const Params& params = s.params;
    const Domain& domain = s.domain;
    Provenance provenance{state.arrangement, state.match, state.source_element};
    state.arrangement.update_positions();
    VacancySettings vacancies = s.vacancies;
    vacancies.reach_count = false;
    vacancies.round = static_cast<std::uint64_t>(round);
    // A layer's elements (bricks in a wall) are often longer than their radius along the
    // layer: the gaps between them in a row look like holes to a ball, and filling them
    // after each iteration jumbled the courses. Layers are filled once, at initialization.
    if (!fill_holes || layer_axes(exemplar.domain.bounds(), params.dimension, params.radius).any)
        vacancies.hole_radius = 0.0;
    int added = fill_vacancies(provenance, exemplar, domain, params, s.tails, vacancies).added;
    // What the filled holes add beyond 1% over the counts is taken back where elements crowd
    // most, if that opens no hole (the counts are estimates: a lattice may hold a few more).
    if (added > 0) added -= thin_crowds(provenance, exemplar, domain, params, vacancies.hole_radius, INFINITY, kCountAllowance);
    core::CrowdingRepairOptions repair = repair_options(s);
    hold_floor_levels(repair, state.arrangement, domain, params);
    core::CrowdingRepairReport fixed = core::repair_crowding(state.arrangement, domain, s.tails, repair);
    const int removed = fixed.remaining > 0 ? remove_unresolved_crowding(provenance, domain, params, s.tails, repair) : 0;
    if (removed > 0) fixed.remaining = static_cast<int>(core::crowded_pairs(state.arrangement, s.tails, repair).size());
    if (added > 0 || removed > 0) state.key = sample_keys(state.arrangement);
    return fixed;
}

void finish(DetSession::Impl& s) {
    OutputState& state = s.state;
    const Params& params = s.params;
    const Domain& domain = s.domain;
    RunStats& stats = state.arrangement.stats;
    if (const PairRelaxation relaxation(s.exemplar, params); relaxation.applies() && s.options.relax_sweeps > 0) {
        state.arrangement.update_positions();
        core::CrowdingRepairOptions repair = repair_options(s);
        hold_floor_levels(repair, state.arrangement, domain, params);
        relaxation.relax(state.arrangement, domain, repair.held_level, s.options.relax_sweeps, s.options.seed, s.threads,
                         [&](int sweep) { s.report("relax", sweep, s.options.relax_sweeps); }, &s.interrupt);
    }
    s.report("repair", -1, 1);
    keep_inside_domain(state.arrangement, domain, params.dimension);
    state.arrangement.update_positions();
    if (drop_beyond_margin({state.arrangement, state.match, state.source_element}, s.exemplar, domain, params) > 0)
        state.key = sample_keys(state.arrangement);
    {
        const core::CrowdingRepairReport fixed = keep_bounds(s, s.rounds + 1);
        if (fixed.bound_hit)
            stats.notes.push_back("crowding repair: " + std::to_string(fixed.remaining) +
                                  " elements are still closer to a neighbour than the exemplar allows after " +
                                  std::to_string(fixed.rounds) + " rounds");
    }
    if (s.options.physics) {
        s.report("settle", -1, 1);
        if (!s.guard) s.guard.emplace(physics_options(s.options, params), domain);
        settle_physics(state.arrangement, *s.guard, stats);
    }
    // Last: the repair's pushes and fills (and the settling) may have left a sample just outside.
    if (const int outside = keep_inside_domain(state.arrangement, domain, params.dimension); outside > 0)
        stats.notes.push_back(std::to_string(outside) + " elements do not fit inside the domain; each is left where "
                              "its samples are least outside");
    update_poses(state, s.index, params.dimension);
    if (s.options.physics) record_physics_result(s);
    // Energy of the result itself (a search without assignment).
    stats.final_energy = search_step(state, s.index, domain, params, s.search);
    stats.radius = params.radius;
    number_new_elements(state.arrangement, s.next_id);
}

void number_new_elements(Arrangement& out, std::uint64_t& next_id) {
    for (Element& e : out.elements)
        if (e.id == kNewElementId) e.id = next_id++;
}

void number_compactly(Arrangement& out) {
    for (size_t e = 0; e < out.elements.size(); ++e) out.elements[e].id = e;
}

}  // namespace tessera::det
