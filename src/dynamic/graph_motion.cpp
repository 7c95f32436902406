// dynamic/graph_motion.cpp — graph synthesis (section 4.3): a still exemplar enriched with
// motion. The graph of its neighbourhoods (graph_nodes), a motion path per sample
// (graph_path, Eq. 13), the neighbourhood blended along it (path_blend) and the positions
// solved frame by frame (graph_solve, Eq. 7). A still of threads, sheets or rigid
// multi-sample elements goes through graph_shapes.hpp instead.
#include <chrono>
#include <cmath>
#include <string>

#include "core/parallel.hpp"
#include "dynamic/graph_nodes.hpp"
#include "dynamic/graph_path.hpp"
#include "dynamic/graph_shapes.hpp"
#include "dynamic/graph_solve.hpp"
#include "dynamic/path_blend.hpp"
#include "tessera/error.hpp"
#include "tessera/graph_motion.hpp"
#include "tessera/metrics.hpp"

namespace tessera {

namespace {

using namespace dynamic;

// A still has no time unit: its enriched frames are one unit apart, as synthesize_dynamic
// spaces a one-frame exemplar's, so that a flow moves a still as far per frame with graph
// synthesis as without.
constexpr double frame_time = 1.0;

void check_still(const Exemplar& still) {
    if (still.samples.size() < 2) throw Error(ErrorKind::input, "exemplar: graph synthesis needs at least 2 elements");
}

// The metric's parameters as the dynamic method resolves them, for one frame: the 1-ring
// radius, input neighbourhoods one spacing further, a pair costing at most a spacing squared.
StParams graph_params(const Exemplar& still, const GraphMotionOptions& options) {
    StParams p;
    p.dimension = still.dimension;
    p.temporal = 1;
    p.spacing = nearest_neighbor_distances(still, options.threads).mean;
    if (!(p.spacing > 0.0)) throw Error(ErrorKind::input, "exemplar: its elements have no spacing (all coincide)");
    p.radius = options.radius > 0.0 ? options.radius : 1.5 * p.spacing;
    p.input_radius = p.radius + p.spacing;
    p.cap2 = p.spacing * p.spacing;
    p.alpha = p.cap2;
    return p;
}

// Every sample's motion path, from its node at the clip's last frame (nodes: every frame's
// sample neighbourhoods), and the tracks of its neighbours along it.
std::vector<PathTracks> plan_paths(const InputFrames& frames, const NeighbourhoodGraph& graph, const StParams& params,
                                   const GraphMotionOptions& options, int chains, GraphMotionStats& stats) {
    const int n = frames.size() / frames.frame_count(), last = n * (frames.frame_count() - 1);
    std::vector<MotionPath> paths(n);
    std::vector<PathTracks> tracks(n);
    std::vector<MetricScratch> scratch(core::resolve_threads(options.threads));
    // The paper's fixed n: Eq. 13 over paths of any length prefers the direct one (see
    // docs/dynamic.md), which would make every motion a single morph s_a -> s_b.
    const AnnealSettings settings{options.path_length, options.path_length, options.alpha, options.anneal_iterations,
                                  options.seed};
    core::parallel_for(n, options.threads, [&](int begin, int end, int thread) {
        for (int s = begin; s < end; ++s) {
            paths[s] = chained_path(graph, last + s, settings, chains);
            tracks[s] = path_tracks(frames, spatial_neighbourhood(frames, last + s, params.radius), paths[s].nodes,
                                    params, scratch[thread]);
        }
    });
    add_path_stats(paths, stats);
    return tracks;
}

// Each sample's predicted neighbour offsets at the f-th new frame of `steps`: its tracks
// blended at u = n f / steps, so every path is walked from s_a (the clip's last frame: a
// still's only one) to s_b (the last new frame).
void predict_frame(const std::vector<PathTracks>& tracks, const std::vector<SplineBlend>& splines,
                   const FrameSolver& solver, int f, int steps, int threads, std::vector<Vec3>& predicted) {
    core::parallel_for(static_cast<int>(tracks.size()), threads, [&](int begin, int end, int) {
        std::vector<double> w(splines.size());
        for (int s = begin; s < end; ++s) {
            const SplineBlend& spline = splines[tracks[s].nodes - 1];
            spline.weights(double(tracks[s].nodes - 1) * f / steps, w.data());
            blend_tracks(tracks[s], w.data(), predicted.data() + solver.first(s));
        }
    });
}

}  // namespace

Animation enrich_by_graph(const Exemplar& still, const GraphMotionOptions& options, GraphMotionStats* stats_out) {
    check_options(graph_motion_option_table(), options);
    still.validate("exemplar");
    return extend_by_graph(animation_from_exemplar(still, still.samples.empty() ? 0.0 : still.samples.front().time),
                           options, stats_out);
}

Animation extend_by_graph(const Animation& clip, const GraphMotionOptions& options, GraphMotionStats* stats_out) {
    check_options(graph_motion_option_table(), options);
    clip.validate("exemplar");
    const auto start = std::chrono::steady_clock::now();
    GraphMotionStats stats;
    const int given = clip.frame_count(), steps = options.frames - given;
    if (steps <= 0) {
        if (stats_out) *stats_out = stats;
        return clip;
    }
    // The clip's own frame interval goes on; a still's frames are one unit apart.
    const double interval = given >= 2 ? clip.times[given - 1] - clip.times[given - 2] : frame_time;
    const Exemplar last = clip.frame(given - 1);
    Animation result = clip;
    if (last.has_multi_sample_elements()) {  // threads, sheets, rigid bodies: dynamic/graph_shapes.hpp
        GraphMotionOptions from_last = options;
        from_last.frames = steps + 1;
        const Animation more = enrich_elements_by_graph(last, from_last, stats);
        for (int f = 1; f < more.frame_count(); ++f)
            result.add_frame(clip.times.back() + f * interval,
                             std::vector<Vec3>(more.positions.begin() + static_cast<long>(f) * more.sample_count(),
                                               more.positions.begin() + static_cast<long>(f + 1) * more.sample_count()));
        stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (stats_out) *stats_out = stats;
        return result;
    }
    check_still(last);
    const StParams params = graph_params(last, options);
    const InputFrames frames(clip, params, options.threads);  // the nodes: every frame's neighbourhoods
    const NeighbourhoodGraph graph(frames, params, options.max_nodes, options.neighbours, options.seed, options.threads);
    stats.nodes = static_cast<int>(graph.nodes().size());
    stats.delta = graph.delta();
    const std::vector<PathTracks> tracks =
        plan_paths(frames, graph, params, options, path_chains(steps, options.path_length), stats);
    int most = 1;
    for (const PathTracks& t : tracks) most = std::max(most, t.nodes);
    const std::vector<SplineBlend> splines = splines_up_to(most);
    const FrameSolver solver(tracks);
    std::vector<Vec3> predicted(solver.track_count());
    std::vector<Vec3> positions(clip.positions.end() - clip.sample_count(), clip.positions.end());
    double travelled = 0.0;
    const double last_time = clip.times.back();
    for (int f = 1; f <= steps; ++f) {
        predict_frame(tracks, splines, solver, f, steps, options.threads, predicted);
        const std::vector<Vec3> before = positions;
        // Converged when no sample moves 1/200 of a spacing in a sweep (a frame moves them
        // about a tenth of a spacing).
        if (solver.solve(predicted, positions, clip.structure.domain, options.sweeps, 5e-3 * params.spacing,
                         options.threads) < 0)
            ++stats.sweep_bound_hits;
        for (size_t s = 0; s < positions.size(); ++s) travelled += norm(positions[s] - before[s]);
        result.add_frame(last_time + f * interval, positions);
    }
    stats.mean_speed = travelled / (double(steps) * positions.size() * params.spacing);
    if (stats.anneal_bound_hits > 0)
        stats.notes.push_back("graph synthesis: " + std::to_string(stats.anneal_bound_hits) +
                              " motion paths were still accepting moves when anneal_iterations (" +
                              std::to_string(options.anneal_iterations) + ") ran out");
    if (stats.sweep_bound_hits > 0)
        stats.notes.push_back("graph synthesis: " + std::to_string(stats.sweep_bound_hits) +
                              " frames were still moving when the Jacobi sweeps (" + std::to_string(options.sweeps) +
                              ") ran out");
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (stats_out) *stats_out = stats;
    return result;
}

}  // namespace tessera
