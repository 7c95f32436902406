// Discrete element texture synthesis (Pseudocode 1): initialize by patch copy,
// then iterate search and assignment, reporting the energy of Eq. 2 each time.
#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/crowding_repair.hpp"
#include "core/parallel.hpp"
#include "core/run_clock.hpp"
#include "det/assign.hpp"
#include "det/floor.hpp"
#include "det/init.hpp"
#include "det/input_index.hpp"
#include "det/layers.hpp"
#include "det/pair_relaxation.hpp"
#include "det/physics_guard.hpp"
#include "det/type_exchange.hpp"
#include "det/vacancies.hpp"
#include "det/search.hpp"
#include "tessera/det.hpp"
#include "tessera/error.hpp"
#include "tessera/physics.hpp"

namespace tessera {

namespace {

using core::Clock;
using core::report;
using core::seconds_since;

// Holes up to this many times the exemplar's largest are left alone: a larger output shows
// a slightly larger largest hole by chance alone.
constexpr double kHoleTolerance = 1.2;
// Holes this many times the exemplar's largest are filled whatever the counts (a margin below
// the 1.3 a user accepts, for the estimate of a hole's size).
constexpr double kHoleBound = 1.25;
// Holes filled during the iterations may take a type this far over its count.
constexpr double kCountAllowance = 0.01;

// Floor elements keep their elevation (section 5): the crowding repair moves them level only.
void hold_floor_levels(core::CrowdingRepairOptions& repair, const Arrangement& out, const Domain& domain,
                       const det::Params& params) {
    repair.held_level.clear();
    if (!params.floor_constraints) return;
    repair.held_level = det::floor_elements(out, domain, params.gravity, params.floor_distance, params.boundary);
    for (char& held : repair.held_level) held &= det::floor_bit;
    repair.level_axis = params.gravity.vector();
}

// The sub-steps that keep the output's holes and close pairs within the exemplar's:
// vacancies filled, types over their count thinned where crowded, pairs pushed apart.
core::CrowdingRepairReport keep_bounds(det::OutputState& state, const Exemplar& exemplar, const Domain& domain,
                                       const det::Params& params, const core::CrowdingBounds& tails,
                                       core::CrowdingRepairOptions& repair, det::VacancySettings vacancies, int round) {
    det::Provenance provenance{state.arrangement, state.match, state.source_element};
    state.arrangement.update_positions();
    vacancies.reach_count = false;
    vacancies.round = static_cast<std::uint64_t>(round);
    // A layer's elements (bricks in a wall) are often longer than their radius along the
    // layer: the gaps between them in a row look like holes to a ball, and filling them
    // after each iteration jumbled the courses. Layers are filled once, at initialization.
    if (det::layer_axes(exemplar.domain.bounds(), params.dimension, params.radius).any) vacancies.hole_radius = 0.0;
    int added = det::fill_vacancies(provenance, exemplar, domain, params, tails, vacancies).added;
    // What the filled holes add beyond 1% over the counts is taken back where elements crowd
    // most, if that opens no hole (the counts are estimates: a lattice may hold a few more).
    if (added > 0) added -= det::thin_crowds(provenance, exemplar, domain, params, vacancies.hole_radius, INFINITY, kCountAllowance);
    hold_floor_levels(repair, state.arrangement, domain, params);
    core::CrowdingRepairReport fixed = core::repair_crowding(state.arrangement, domain, tails, repair);
    const int removed = fixed.remaining > 0 ? det::remove_unresolved_crowding(provenance, domain, params, tails, repair) : 0;
    if (removed > 0) fixed.remaining = static_cast<int>(core::crowded_pairs(state.arrangement, tails, repair).size());
    if (added > 0 || removed > 0) state.key = det::sample_keys(state.arrangement);
    return fixed;
}

// The final repair moved elements after the last physics step: settle them, guarded,
// and say how many steps the guard undid.
void settle_physics(Arrangement& out, det::PhysicsGuard& guard, RunStats& stats) {
    PhysicsReport reference;
    reference.interpenetrating_pairs = stats.penetrations_before;
    reference.floating = stats.floating_before;
    guard.settle(out, reference);
    if (guard.undone() > 0)
        stats.notes.push_back("physics: " + std::to_string(guard.undone()) + " of " + std::to_string(guard.steps()) +
                              " steps undone (they raised the interpenetrating pairs or the floating elements)");
}

}  // namespace

Arrangement synthesize_det(const Exemplar& exemplar, const Domain& domain, const DetOptions& options,
                           const Progress& progress) {
    const auto t0 = Clock::now();
    exemplar.validate("exemplar");
    if (domain.dimension() != exemplar.dimension)
        throw Error(ErrorKind::domain, "the output domain is " + std::to_string(domain.dimension()) +
                                           "D but the exemplar is " + std::to_string(exemplar.dimension) + "D");
    const det::Params params = det::resolve_params(exemplar, options);
    const int threads = core::resolve_threads(options.threads);

    report(progress, {"init", -1, options.iterations, 0.0, seconds_since(t0)});
    const det::InputIndex index = det::build_input_index(
        exemplar, params, options.search == SearchMode::kcoherence ? options.k : 0, threads);
    report(progress, {"patches", -1, options.iterations, 0.0, seconds_since(t0)});
    det::InitResult init = det::initialize_patches(exemplar, index, domain, params, options);
    report(progress, {"fill", -1, options.iterations, 0.0, seconds_since(t0)});
    // The exemplar's close-distance tails bound the output's (core/crowding_repair.hpp), and
    // its largest hole the output's (det/vacancies.hpp).
    const core::CrowdingBounds tails(exemplar);
    const double hole_radius = kHoleTolerance * det::exemplar_hole_radius(exemplar, params.spacing, params.radius);
    init.thinned = det::thin_crowds(init.provenance(), exemplar, domain, params);
    det::VacancySettings vacancies;
    vacancies.hole_radius = hole_radius;
    vacancies.count_allowance = kCountAllowance;
    vacancies.must_fill_radius = hole_radius * kHoleBound / kHoleTolerance;
    vacancies.reach_count = true;
    vacancies.seed = options.seed;
    init.filled = det::fill_vacancies(init.provenance(), exemplar, domain, params, tails, vacancies).added;
    if (det::exchange_types(init.provenance(), exemplar, domain, params, tails, options.seed) > 0) {
        vacancies.round = 1;
        init.filled += det::fill_vacancies(init.provenance(), exemplar, domain, params, tails, vacancies).added;
    }

    det::OutputState state;
    state.arrangement = std::move(init.arrangement);
    state.key = det::sample_keys(state.arrangement);
    state.match = std::move(init.source_sample);
    state.source_element = std::move(init.source_element);
    state.type_target.assign(state.arrangement.types.size(), 0);
    for (size_t t = 0; t < state.type_target.size(); ++t)
        state.type_target[t] = static_cast<int>(std::lround(params.type_density[t] * domain.measure()));

    RunStats& stats = state.arrangement.stats;
    stats.method = "det";
    stats.threads = threads;
    stats.seed = options.seed;
    stats.init_seconds = seconds_since(t0);
    if (init.structure_range > params.radius) {
        char note[200];
        std::snprintf(note, sizeof note,
                      "initialization patches of %.4g: the exemplar is structured up to %.4g, beyond the "
                      "neighbourhood radius %.4g (docs/det.md)",
                      init.patch_size, init.structure_range, params.radius);
        stats.notes.push_back(note);
    }

    // Both bounds are kept after every iteration by sub-steps, like the interleaved physics of
    // section 5: pairs closer than the exemplar allows are pushed apart, holes filled.
    core::CrowdingRepairOptions repair;
    repair.threads = threads;
    const det::SearchSettings search{options.search, threads};
    PhysicsOptions physics = options.physics_options;
    if (options.physics && physics.gravity == Vec3{})
        physics.gravity = params.gravity.vector() * (9.81 * physics.units_per_metre);
    det::PhysicsGuard guard(physics, domain);
    for (int it = 0; it < options.iterations; ++it) {
        const auto ti = Clock::now();
        const double energy = det::search_step(state, index, domain, params, search);
        const det::AssignReport assigned = det::assign_step(state, index, domain, params, threads);
        stats.energy.push_back(energy);
        stats.iteration_seconds.push_back(seconds_since(ti));
        if (!assigned.cg_converged) ++stats.solver_bound_hits;
        if (options.physics) {  // the interleaved solver: extra steps after search and assign
            if (it == 0) {
                const PhysicsReport before = guard.measure(state.arrangement);
                stats.penetrations_before = before.interpenetrating_pairs;
                stats.max_depth_before = before.max_depth;
                stats.floating_before = before.floating;
            }
            guard.step(state.arrangement);
        }
        keep_bounds(state, exemplar, domain, params, tails, repair, vacancies, it + 1);
        report(progress, {"iteration", it, options.iterations, energy, seconds_since(t0)});
    }
    if (const det::PairRelaxation relaxation(exemplar, params); relaxation.applies() && options.relax_sweeps > 0) {
        state.arrangement.update_positions();
        hold_floor_levels(repair, state.arrangement, domain, params);
        relaxation.relax(state.arrangement, domain, repair.held_level, options.relax_sweeps, options.seed, threads,
                         [&](int sweep) { report(progress, {"relax", sweep, options.relax_sweeps, 0.0, seconds_since(t0)}); });
    }
    report(progress, {"repair", -1, options.iterations, 0.0, seconds_since(t0)});
    det::keep_inside_domain(state.arrangement, domain, params.dimension);
    state.arrangement.update_positions();
    if (det::drop_beyond_margin({state.arrangement, state.match, state.source_element}, exemplar, domain, params) > 0)
        state.key = det::sample_keys(state.arrangement);
    {
        const core::CrowdingRepairReport fixed =
            keep_bounds(state, exemplar, domain, params, tails, repair, vacancies, options.iterations + 1);
        if (fixed.bound_hit)
            stats.notes.push_back("crowding repair: " + std::to_string(fixed.remaining) +
                                  " elements are still closer to a neighbour than the exemplar allows after " +
                                  std::to_string(fixed.rounds) + " rounds");
    }
    if (options.physics) {
        report(progress, {"settle", -1, options.iterations, 0.0, seconds_since(t0)});
        settle_physics(state.arrangement, guard, stats);
    }
    // Last: the repair's pushes and fills (and the settling) may have left a sample just outside.
    if (const int outside = det::keep_inside_domain(state.arrangement, domain, params.dimension); outside > 0)
        stats.notes.push_back(std::to_string(outside) + " elements do not fit inside the domain; each is left where "
                              "its samples are least outside");
    det::update_poses(state, index, params.dimension);
    if (options.physics) {
        const PhysicsReport after = guard.measure(state.arrangement);
        if (after.interpenetrating_pairs > stats.penetrations_before || after.floating > stats.floating_before)
            stats.notes.push_back("physics: the result has more interpenetrating pairs or floating elements than "
                                  "before the first step (the iterations moved them; every physics step that "
                                  "raised them was undone)");
        stats.physics = true;
        stats.penetrations_after = after.interpenetrating_pairs;
        stats.max_depth_after = after.max_depth;
        stats.floating_after = after.floating;
    }
    // Energy of the result itself (a search without assignment).
    stats.final_energy = det::search_step(state, index, domain, params, search);
    stats.radius = params.radius;
    stats.total_seconds = seconds_since(t0);
    report(progress, {"done", options.iterations, options.iterations, stats.final_energy, stats.total_seconds});
    return std::move(state.arrangement);
}

}  // namespace tessera
