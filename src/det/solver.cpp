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
#include "det/search.hpp"
#include "tessera/det.hpp"
#include "tessera/error.hpp"
#include "tessera/physics.hpp"

namespace tessera {

namespace {

using core::Clock;
using core::report;
using core::seconds_since;

// Floor elements keep their elevation (section 5): the crowding repair moves them level only.
void hold_floor_levels(core::CrowdingRepairOptions& repair, const Arrangement& out, const Domain& domain,
                       const det::Params& params) {
    repair.held_level.clear();
    if (!params.floor_constraints) return;
    repair.held_level = det::floor_elements(out, domain, params.gravity, params.floor_distance, params.boundary);
    for (char& held : repair.held_level) held &= det::floor_bit;
    repair.level_axis = params.gravity.vector();
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
    det::InitResult init = det::initialize_patches(exemplar, index, domain, params, options);
    init.thinned = det::thin_crowds(init, exemplar, domain, params);
    init.filled = det::fill_holes(init, exemplar, domain, params, options.seed);

    det::OutputState state;
    state.arrangement = std::move(init.arrangement);
    state.key = det::sample_keys(state.arrangement);
    state.match = std::move(init.source_sample);
    state.source_element = std::move(init.source_element);
    state.type_target.assign(state.arrangement.types.size(), 0);
    for (const Element& e : state.arrangement.elements) ++state.type_target[e.type];

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

    // The exemplar's close-distance tails bound the output's (core/crowding_repair.hpp): a
    // separation sub-step after every iteration, like the interleaved physics of section 5.
    const core::NearestDistanceTails tails(exemplar);
    core::CrowdingRepairOptions repair;
    repair.threads = threads;
    const det::SearchSettings search{options.search, threads};
    PhysicsOptions physics = options.physics_options;
    if (options.physics && physics.gravity == Vec3{})
        physics.gravity = params.gravity.vector() * (9.81 * physics.units_per_metre);
    for (int it = 0; it < options.iterations; ++it) {
        const auto ti = Clock::now();
        const double energy = det::search_step(state, index, domain, params, search);
        const det::AssignReport assigned = det::assign_step(state, index, domain, params, threads);
        stats.energy.push_back(energy);
        stats.iteration_seconds.push_back(seconds_since(ti));
        if (!assigned.cg_converged) ++stats.solver_bound_hits;
        if (options.physics) {  // the interleaved solver: extra steps after search and assign
            if (it == 0) {
                const PhysicsReport before =
                    measure_physics(state.arrangement, domain, physics.gravity, physics.tolerance);
                stats.penetrations_before = before.interpenetrating_pairs;
                stats.max_depth_before = before.max_depth;
                stats.floating_before = before.floating;
            }
            step_physics(state.arrangement, domain, physics);
        }
        hold_floor_levels(repair, state.arrangement, domain, params);
        core::repair_crowding(state.arrangement, domain, tails, repair);
        report(progress, {"iteration", it, options.iterations, energy, seconds_since(t0)});
    }
    det::keep_inside_domain(state.arrangement, domain, params.dimension);
    {
        hold_floor_levels(repair, state.arrangement, domain, params);
        const core::CrowdingRepairReport fixed = core::repair_crowding(state.arrangement, domain, tails, repair);
        if (fixed.bound_hit)
            stats.notes.push_back("crowding repair: " + std::to_string(fixed.remaining) +
                                  " elements are still closer to a neighbour than the exemplar allows after " +
                                  std::to_string(fixed.rounds) + " rounds");
    }
    det::update_poses(state, index, params.dimension);
    if (options.physics) {
        const PhysicsReport after = measure_physics(state.arrangement, domain, physics.gravity, physics.tolerance);
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
