// dynamic/synthesize_all_frames.cpp — all-frame synthesis of particles: spatio-temporal
// patch copy, then search and assignment over every frame together (section 4.1).
#include "dynamic/synthesize_all_frames.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "core/parallel.hpp"
#include "dynamic/all_frames.hpp"
#include "dynamic/all_frames_init.hpp"
#include "dynamic/all_frames_solve.hpp"
#include "dynamic/collision_step.hpp"
#include "dynamic/graph_exemplar.hpp"
#include "tessera/error.hpp"
#include "tessera/metrics.hpp"
#include "tessera/option_table.hpp"

namespace tessera::dynamic {

namespace {

constexpr int similarity_k = 4;     // size of the k-coherence sets (as frame by frame)
constexpr int similarity_scan = 64; // input sample-frames scanned to build each set

int reach_of(const DynamicOptions& options) { return std::clamp(options.temporal_size / 2, 1, (max_temporal - 1) / 2); }

void check_inputs(const Animation& exemplar, const Domain& domain, const DynamicOptions& options) {
    exemplar.validate("exemplar");
    if (exemplar.structure.has_multi_sample_elements())
        throw Error(ErrorKind::input, "exemplar: sequencing all takes single-sample elements (particles, agents); "
                                      "threads and sheets follow a coarse motion (--coarse)");
    if (domain.dimension() != exemplar.structure.dimension)
        throw Error(ErrorKind::domain, "the output domain is " + std::to_string(domain.dimension()) +
                                           "D but the exemplar is " + std::to_string(exemplar.structure.dimension) + "D");
    if (options.shape == NeighbourhoodShape::full)
        throw Error(ErrorKind::option, "shape full is not available with sequencing all (use shape compact)");
    const int window = 2 * reach_of(options) + 1;
    if (exemplar.frame_count() < window)
        throw Error(ErrorKind::option, "sequencing all: the exemplar needs at least " + std::to_string(window) +
                                           " frames for temporal_size " + std::to_string(options.temporal_size) +
                                           ", it has " + std::to_string(exemplar.frame_count()));
}

// As frame by frame (1-ring radius, cap, alpha, falloffs), with the non-causal window.
StParams resolve_params(const Animation& exemplar, const DynamicOptions& options) {
    StParams p;
    p.ahead = reach_of(options);
    p.temporal = 2 * p.ahead + 1;
    const Exemplar middle = exemplar.frame(p.ahead);
    p.dimension = middle.dimension;
    p.shape = NeighbourhoodShape::compact;
    p.spacing = nearest_neighbor_distances(middle, options.threads).mean;
    if (!(p.spacing > 0.0)) throw Error(ErrorKind::input, "exemplar: its elements have no spacing (all coincide)");
    p.radius = options.radius > 0.0 ? options.radius : 1.5 * p.spacing;
    p.input_radius = p.radius + p.spacing;
    p.cap2 = p.spacing * p.spacing;
    p.alpha = options.alpha >= 0.0 ? options.alpha : p.spacing * p.spacing;
    if (options.sigma_p > 0.0) p.inv_sigma_p2 = 1.0 / (options.sigma_p * p.radius * options.sigma_p * p.radius);
    if (options.sigma_t > 0.0) p.inv_sigma_t2 = 1.0 / (options.sigma_t * options.sigma_t);
    return p;
}

double frame_interval(const Animation& exemplar) {
    const int n = exemplar.frame_count();
    return n > 1 ? (exemplar.times.back() - exemplar.times.front()) / (n - 1) : 1.0;
}

// The far flow's step into each frame: the flow at the step's middle turned by flow_turn
// degrees per unit of time about z, times the step (index 0 unused).
std::vector<Vec3> flow_steps(const DynamicOptions& options, int frames, double dt) {
    std::vector<Vec3> steps(frames);
    for (int f = 1; f < frames; ++f) {
        const double a = options.flow_turn * std::numbers::pi / 180.0 * (f - 0.5) * dt;
        const Vec3& v = options.flow;
        steps[f] = Vec3{v.x * std::cos(a) - v.y * std::sin(a), v.x * std::sin(a) + v.y * std::cos(a), v.z} * dt;
    }
    return steps;
}

std::vector<int> sample_types(const Arrangement& first, const Exemplar& exemplar) {
    std::vector<int> types(first.samples.size());
    for (size_t s = 0; s < types.size(); ++s)
        types[s] = exemplar.find_type(first.types[first.elements[first.samples[s].element].type].name);
    return types;
}

Periodic periodic_of(const Domain& domain, bool wrap) {
    if (!wrap) return {};
    return {true, domain.bounds().lo, domain.bounds().size()};
}

// The physics sub-step (Figure 5) on every frame: the particles each frame holds are pushed
// apart where closer than the exemplar's come, and out of the domain's walls and obstacles.
// Frame by frame it follows each advection; here every frame is made at once, so it follows
// each round's assignment, and the next round's temporal neighbourhoods smooth what it moved
// (the last round's moves stay: no collision is put back). Frames in order, one Bullet world
// at a time, so the bits do not depend on the thread count. Returns the particles moved.
int resolve_collisions(AllFrames& out, CollisionStep& collisions, const Domain& domain, bool wrap) {
    const int n = out.size();
    std::vector<Vec3> frame(n);
    int moved = 0;
    for (int f = 0; f < out.frames(); ++f) {
        std::copy_n(out.positions().begin() + static_cast<long>(f) * n, n, frame.begin());
        moved += collisions.apply(frame);
        for (Vec3& p : frame) keep_inside_domain(p, domain, wrap);
        std::copy(frame.begin(), frame.end(), out.positions().begin() + static_cast<long>(f) * n);
    }
    return moved;
}

// One round: search (returning its energy), then the assignment, the domain and the physics
// sub-step when asked for, and the drift along the new paths.
double search_and_assign(const InputFrames& input, AllFrames& out, const StParams& params, SearchSettings& settings,
                         std::vector<SearchScratch>& scratch, const Domain& domain, const DynamicOptions& options,
                         const ObstacleFlow& flow, CollisionStep* collisions) {
    out.index_frames(options.threads);
    const double energy = search_all_frames(input, out, params, settings, scratch, options.threads);
    assign_all_frames(out, params.radius, params, options.threads);
    for (Vec3& p : out.positions()) keep_inside_domain(p, domain, options.wrap);
    if (collisions) resolve_collisions(out, *collisions, domain, options.wrap);
    if (!flow.uniform()) out.carry(flow, options.threads);
    return energy;
}

}  // namespace

AnimatedArrangement synthesize_all_frames(const Animation& given, const Domain& domain, const DynamicOptions& options,
                                          const Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    check_options(dynamic_option_table(), options);
    std::optional<Animation> enriched;
    std::vector<std::string> notes;
    const Animation& exemplar = exemplar_with_motion(given, options, enriched, notes);
    check_inputs(exemplar, domain, options);
    const StParams params = resolve_params(exemplar, options);
    const int frames = options.frames > 0 ? options.frames : std::max(2, exemplar.frame_count());
    const double dt = frame_interval(exemplar);

    InputFrames input(exemplar, params, options.threads);
    if (options.search == SearchMode::kcoherence)
        build_similarity(input, params, similarity_k, similarity_scan, options.seed, options.threads);
    std::vector<int> source;
    const Arrangement first = copy_first_frame(exemplar, domain, options, params, params.ahead, source);
    AllFrames out(frames, sample_types(first, exemplar.structure), options.matches, params,
                  periodic_of(domain, options.wrap));
    out.flow_steps() = flow_steps(options, frames, dt);
    // The flow round the domain's obstacles (the potential flow frame by frame uses too).
    const ObstacleFlow flow(domain, options.threads, squared_norm(options.flow) > 0.0);
    std::vector<Vec3> first_positions(first.samples.size());
    for (size_t s = 0; s < first_positions.size(); ++s) first_positions[s] = first.samples[s].p;
    copy_trajectories(exemplar, input, first_positions, source, params.ahead, domain, flow, options.wrap, out,
                      options.threads);
    std::optional<CollisionStep> collisions;  // the physics sub-step, when asked for
    if (options.physics) {
        collisions.emplace(exemplar, domain, options.wrap);
        resolve_collisions(out, *collisions, domain, options.wrap);  // the patch copy's seams first
    }

    AnimatedArrangement result;
    result.stats.method = "dynamic";
    result.stats.notes = notes;
    result.stats.notes.push_back("sequencing all: " + std::to_string(2 * params.ahead + 1) +
                                 "-frame temporal-non-causal neighbourhoods");
    result.stats.radius = params.radius;
    result.stats.seed = options.seed;
    result.stats.threads = core::resolve_threads(options.threads);
    result.stats.init_seconds = elapsed();
    std::vector<SearchScratch> scratch(core::resolve_threads(options.threads));
    SearchSettings settings{options.search, options.random_candidates, options.seed, 0, false};
    for (int round = 0; round < options.iterations; ++round) {
        const double round_start = elapsed();
        settings.round = round;
        const double energy = search_and_assign(input, out, params, settings, scratch, domain, options, flow,
                                                collisions ? &*collisions : nullptr);
        result.stats.energy.push_back(energy);
        result.stats.iteration_seconds.push_back(elapsed() - round_start);
        if (progress && !progress(ProgressEvent{"iteration", round + 1, options.iterations, energy, elapsed(),
                                                double(round + 1) / (options.iterations + 1)}))
            throw Cancelled();
    }
    // The energy of the result: one more search, without moving anything.
    out.index_frames(options.threads);
    settings.round = options.iterations;
    result.stats.energy.push_back(search_all_frames(input, out, params, settings, scratch, options.threads));

    result.structure = static_cast<const Exemplar&>(first);
    const int n = out.size();
    for (int f = 0; f < frames; ++f)
        result.add_frame(exemplar.times.front() + f * dt,
                         std::vector<Vec3>(out.positions().begin() + static_cast<long>(f) * n,
                                           out.positions().begin() + static_cast<long>(f + 1) * n));
    for (Sample& s : result.structure.samples) s.time = result.times.front();
    result.stats.final_energy = result.stats.energy.back();
    result.stats.total_seconds = elapsed();
    if (progress) progress(ProgressEvent{"done", options.iterations, options.iterations, result.stats.final_energy,
                                         elapsed(), 1.0});
    return result;
}

}  // namespace tessera::dynamic
