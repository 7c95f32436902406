// Graph synthesis for a still of multi-sample elements (dynamic/graph_shapes.hpp).
#include "dynamic/graph_shapes.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include "core/parallel.hpp"
#include "core/rigid_fit.hpp"
#include "dynamic/element_contacts.hpp"
#include "dynamic/element_lengths.hpp"
#include "dynamic/graph_nodes.hpp"
#include "dynamic/graph_path.hpp"
#include "dynamic/path_blend.hpp"
#include "dynamic/topology_grid.hpp"
#include "tessera/error.hpp"
#include "tessera/metrics.hpp"

namespace tessera::dynamic {

namespace {

constexpr double frame_time = 1.0;  // as enrich_by_graph's: one unit of time per frame
// Threads and sheets are projected until every edge is within 0.5% of its rest length, as
// the coarse-motion synthesis does (synthesize_on_coarse.cpp), at most this many sweeps.
constexpr double length_tolerance = 0.005;
constexpr int length_sweeps = 200;
// And, alternating with the lengths, the elements held apart (element_contacts.hpp): no two
// samples of different elements closer than half the still's closest approach (its 2%
// quantile, as the coarse-motion synthesis), or half their distance in the still.
constexpr double contact_quantile = 0.02;
constexpr double contact_tolerance = 0.02;
constexpr int contact_sweeps = 50;
constexpr int constraint_passes = 8;

// Every element's samples as offsets from its centroid, element after element.
struct Shapes {
    std::vector<int> first;      // per element, into `offset`; first.back() = total
    std::vector<Vec3> offset;
    std::vector<Vec3> centroid;  // per element
    const Vec3* of(int e) const { return offset.data() + first[e]; }
    int count(int e) const { return first[e + 1] - first[e]; }
};

Shapes shapes_of(const Exemplar& still) {
    Shapes s;
    s.first.push_back(0);
    for (const Element& e : still.elements) {
        Vec3 c;
        for (int k = 0; k < e.sample_count; ++k) c += still.samples[e.first_sample + k].p;
        c = c * (1.0 / e.sample_count);
        for (int k = 0; k < e.sample_count; ++k) s.offset.push_back(still.samples[e.first_sample + k].p - c);
        s.centroid.push_back(c);
        s.first.push_back(static_cast<int>(s.offset.size()));
    }
    return s;
}

// The complete graph of shapes: mean squared distance of the topology-paired offsets
// (sample k with sample k), infinite between elements of other types or sample counts.
NeighbourhoodGraph shape_graph(const Exemplar& still, const Shapes& shapes, int k, int threads) {
    const int n = static_cast<int>(still.elements.size());
    std::vector<double> w(static_cast<size_t>(n) * n, std::numeric_limits<double>::infinity());
    core::parallel_for(n, threads, [&](int begin, int end, int) {
        for (int a = begin; a < end; ++a)
            for (int b = 0; b < n; ++b) {
                if (still.elements[a].type != still.elements[b].type || shapes.count(a) != shapes.count(b)) continue;
                double d = 0.0;
                for (int s = 0; s < shapes.count(a); ++s) d += squared_norm(shapes.of(a)[s] - shapes.of(b)[s]);
                w[static_cast<size_t>(a) * n + b] = d / shapes.count(a);
            }
    });
    return NeighbourhoodGraph(n, std::move(w), k, threads);
}

// The still's centroids as a still of particles (ids and types kept), and their motion.
Animation centroid_motion(const Exemplar& still, const Shapes& shapes, const GraphMotionOptions& options,
                          GraphMotionStats& stats) {
    Exemplar c;
    c.dimension = still.dimension;
    c.domain = still.domain;
    c.types = still.types;
    for (ElementType& t : c.types) t.topology = ElementTopology::automatic, t.sheet_columns = 0;
    for (size_t e = 0; e < still.elements.size(); ++e) {
        const int i = c.add_element(still.elements[e].type, {shapes.centroid[e]});
        c.elements[i].id = still.elements[e].id;
    }
    GraphMotionStats centroid_stats;
    Animation motion = enrich_by_graph(c, options, &centroid_stats);
    stats.anneal_bound_hits += centroid_stats.anneal_bound_hits;
    stats.sweep_bound_hits += centroid_stats.sweep_bound_hits;
    return motion;
}

// Per element, the share of its centroid's motion it takes: 1 for an element no longer than
// the centroids' spacing, (spacing / length)^2 for a longer one. The centroids' motion keeps
// them apart as points; a noodle longer than that spacing drifting as far sweeps across its
// neighbours, which no contact between samples stops (two noodles cross between samples).
// Measured on noodles_2d (noodles 1.7 long, centroids 1.0 apart): segments of two noodles
// crossing in 22 of 24 frames with the whole motion (up to 11 pairs), in 10 with the share
// to the power 1, in none squared.
std::vector<double> drift_shares(const Exemplar& still, const Shapes& shapes, double spacing) {
    std::vector<double> share(still.elements.size(), 1.0);
    for (size_t e = 0; e < share.size(); ++e) {
        double extent = 0.0;
        for (int k = 0; k < shapes.count(static_cast<int>(e)); ++k) extent = std::max(extent, norm(shapes.of(static_cast<int>(e))[k]));
        if (2.0 * extent > spacing) share[e] = std::pow(spacing / (2.0 * extent), 2.0);
    }
    return share;
}

// Whether element e keeps its own shape (turned only): a rigid type, or samples with no
// thread or sheet to hold them together.
bool keeps_shape(const Exemplar& still, int e) {
    const Element& el = still.elements[e];
    return el.sample_count > 1 && (still.types[el.type].rigid ||
                                   effective_topology(still, el.type) == ElementTopology::none);
}

// The rest lengths of the deformable elements' edges (none for the rigid ones).
std::vector<std::vector<Edge>> deformable_edges(const Exemplar& still) {
    Exemplar grid_view = still;  // a multi-sample element of topology none is rigid here: no grid needed
    for (size_t t = 0; t < grid_view.types.size(); ++t)
        if (effective_topology(still, static_cast<int>(t)) == ElementTopology::none)
            grid_view.types[t].topology = ElementTopology::automatic;
    const TopologyGrid grid(grid_view, "exemplar");
    std::vector<int> types;
    for (const Element& e : still.elements) types.push_back(e.type);
    std::vector<Vec3> rest;
    for (const Sample& s : still.samples) rest.push_back(s.p);
    std::vector<std::vector<Edge>> edges =
        element_edges(grid, types, rest.data(), std::vector<double>(still.types.size(), 1.0));
    for (size_t e = 0; e < edges.size(); ++e)
        if (keeps_shape(still, static_cast<int>(e))) edges[e].clear();
    return edges;
}

// The contacts push samples one by one: a rigid element's own shape fitted back onto them.
void rigid_again(const Exemplar& still, std::vector<Vec3>& frames, int frame_count) {
    const int samples = static_cast<int>(still.samples.size());
    std::vector<Vec3> own, now;
    for (size_t e = 0; e < still.elements.size(); ++e) {
        if (!keeps_shape(still, static_cast<int>(e))) continue;
        const Element& el = still.elements[e];
        own.clear();
        for (int k = 0; k < el.sample_count; ++k) own.push_back(still.samples[el.first_sample + k].p);
        for (int f = 1; f < frame_count; ++f) {
            Vec3* at = frames.data() + static_cast<size_t>(f) * samples + el.first_sample;
            now.assign(at, at + el.sample_count);
            Quat turn;
            Vec3 shift;
            core::best_rigid_fit(own.data(), now.data(), el.sample_count, still.dimension, turn, shift);
            for (int k = 0; k < el.sample_count; ++k) at[k] = turn.rotate(own[k]) + shift;
        }
    }
}

// Blending shapes shortens a thread where they differ, and moving elements may touch: the
// rest lengths and the contacts, alternately, frame 0 (the still) untouched.
void hold_constraints(const Exemplar& still, const Animation& still_frames, std::vector<Vec3>& frames,
                      const GraphMotionOptions& options, GraphMotionStats& stats) {
    const int samples = static_cast<int>(still.samples.size());
    const std::vector<std::vector<Edge>> edges = deformable_edges(still);
    std::vector<int> element_of(samples);
    for (int s = 0; s < samples; ++s) element_of[s] = still.samples[s].element;
    std::vector<Vec3> rest(frames.size());  // the still at every frame: the pairs' own distances
    for (size_t i = 0; i < rest.size(); ++i) rest[i] = still.samples[i % samples].p;
    const double contact = exemplar_contact_distance(still_frames, contact_quantile);
    LengthReport lengths;
    ContactReport contacts;
    for (int pass = 0; pass < constraint_passes; ++pass) {
        lengths = keep_lengths(frames, options.frames, samples, edges, length_tolerance, length_sweeps, options.threads);
        contacts = keep_apart(frames, rest, element_of, options.frames, samples, still.dimension, contact,
                              contact_tolerance, contact_sweeps, options.threads);
        if (contacts.first_gap <= contact_tolerance * contact) break;
    }
    lengths = keep_lengths(frames, options.frames, samples, edges, length_tolerance, length_sweeps, options.threads);
    rigid_again(still, frames, options.frames);
    if (lengths.bound_hits > 0)
        stats.notes.push_back("graph synthesis: " + std::to_string(lengths.bound_hits) +
                              " element-frames were still off their rest lengths when the projection's sweeps (" +
                              std::to_string(length_sweeps) + ") ran out");
    if (contacts.bound_hits > 0)
        stats.notes.push_back("graph synthesis: " + std::to_string(contacts.bound_hits) +
                              " frames still had elements too close when the contact sweeps (" +
                              std::to_string(contact_sweeps) + ") ran out");
}

}  // namespace

Animation enrich_elements_by_graph(const Exemplar& still, const GraphMotionOptions& options, GraphMotionStats& stats) {
    if (still.elements.size() < 2) throw Error(ErrorKind::input, "exemplar: graph synthesis needs at least 2 elements");
    const Shapes shapes = shapes_of(still);
    const Animation centroids = centroid_motion(still, shapes, options, stats);
    const NeighbourhoodGraph graph = shape_graph(still, shapes, options.neighbours, options.threads);
    stats.nodes = static_cast<int>(graph.nodes().size());
    stats.delta = graph.delta();

    const int n = static_cast<int>(still.elements.size());
    const AnnealSettings settings{options.path_length, options.path_length, options.alpha, options.anneal_iterations,
                                  options.seed};
    const int chains = path_chains(options.frames - 1, options.path_length);
    std::vector<MotionPath> paths(n);
    core::parallel_for(n, options.threads, [&](int begin, int end, int) {
        for (int e = begin; e < end; ++e) paths[e] = chained_path(graph, e, settings, chains);
    });
    add_path_stats(paths, stats);

    // A thread or sheet bends through its path's shapes, each turned onto its own (Kabsch):
    // unturned, a noodle morphing into a neighbour's shape swung through its orientation and
    // crossed the noodles beside it. A rigid element blends them as they are, and turns.
    std::vector<std::vector<Quat>> turns(n);
    for (int e = 0; e < n; ++e)
        for (int node : paths[e].nodes) {
            Quat turn;
            Vec3 shift;
            if (!keeps_shape(still, e) && still.elements[e].sample_count > 1)
                core::best_rigid_fit(shapes.of(node), shapes.of(e), shapes.count(e), still.dimension, turn, shift);
            turns[e].push_back(turn);
        }

    // The centroids' mean spacing: the drift's scale and the unit of the reported motion.
    const double spacing = nearest_neighbor_distances(centroids.frame(0), options.threads).mean;
    const std::vector<double> drift = drift_shares(still, shapes, spacing);

    size_t most = 1;
    for (const MotionPath& p : paths) most = std::max(most, p.nodes.size());
    const std::vector<SplineBlend> splines = splines_up_to(static_cast<int>(most));
    Animation result = animation_from_exemplar(still, still.samples.front().time);
    const int samples = result.sample_count();
    std::vector<Vec3> frames(static_cast<size_t>(options.frames) * samples);
    for (int s = 0; s < samples; ++s) frames[s] = still.samples[s].p;
    core::parallel_for(n, options.threads, [&](int begin, int end, int) {
        std::vector<Vec3> shape;
        std::vector<double> w(splines.size());
        for (int e = begin; e < end; ++e) {
            const Element& el = still.elements[e];
            const std::vector<int>& nodes = paths[e].nodes;
            for (int f = 1; f < options.frames; ++f) {
                splines[nodes.size() - 1].weights(double(nodes.size() - 1) * f / (options.frames - 1), w.data());
                shape.assign(el.sample_count, Vec3{});
                for (size_t i = 0; i < nodes.size(); ++i)
                    for (int k = 0; k < el.sample_count; ++k) shape[k] += turns[e][i].rotate(shapes.of(nodes[i])[k]) * w[i];
                if (keeps_shape(still, e)) {  // its own shape, turned onto the blended one
                    Quat turn;
                    Vec3 shift;
                    core::best_rigid_fit(shapes.of(e), shape.data(), el.sample_count, still.dimension, turn, shift);
                    for (int k = 0; k < el.sample_count; ++k) shape[k] = turn.rotate(shapes.of(e)[k]);
                }
                const Vec3 c = shapes.centroid[e] + (centroids.at(f, e) - shapes.centroid[e]) * drift[e];
                for (int k = 0; k < el.sample_count; ++k) frames[static_cast<size_t>(f) * samples + el.first_sample + k] = c + shape[k];
            }
        }
    });
    hold_constraints(still, result, frames, options, stats);
    double travelled = 0.0;
    for (int f = 1; f < options.frames; ++f) {
        const std::vector<Vec3> at(frames.begin() + static_cast<long>(f) * samples,
                                   frames.begin() + static_cast<long>(f + 1) * samples);
        for (int s = 0; s < samples; ++s) travelled += norm(at[s] - frames[static_cast<size_t>(f - 1) * samples + s]);
        result.add_frame(result.times.front() + f * frame_time, at);
    }
    stats.mean_speed = travelled / (double(options.frames - 1) * samples * spacing);
    return result;
}

}  // namespace tessera::dynamic
