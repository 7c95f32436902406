// tessera/graph_motion.hpp — graph synthesis (Dynamic Element Textures, section 4.3): motion
// for an exemplar that has none, a static arrangement (one frame).
//
// The nodes of a graph are the spatial neighbourhoods of the still's samples (the relative
// offsets of the neighbours within the radius, Eq. 2-3 with one frame); an edge weighs the
// neighbourhood distance of Eq. 4 (Hungarian pairing, capped cost per unpaired entry). For
// every sample s_a, the node s_b is the farthest of its k nearest nodes, and a motion path
// s_a = s_0, ..., s_n = s_b minimises Eq. 13 (smooth steps + node diversity), found by
// simulated annealing. Along the path the neighbourhood of s_a morphs through the path's
// nodes (each node's entries paired with s_a's own by the Hungarian algorithm, blended over
// time by an interpolating cubic B-spline through the nodes); at every frame each sample is
// placed by the least-squares assignment (Eq. 7, damped Jacobi sweeps) that best fits the
// blended neighbourhoods of it and its neighbours. Frame 0 is the still.
//
// Docs: docs/dynamic.md, "Graph synthesis (motion from a still)".
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tessera/animation.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/option_table.hpp"

namespace tessera {

struct DynamicOptions;

struct GraphMotionOptions {
    // Frames of the enriched exemplar, the still's included (one unit of time apart).
    int frames = 24;
    // n: the steps of every motion path (Eq. 13), s_0 .. s_n.
    int path_length = 6;
    // Weight of the diversity term of Eq. 13 (the paper's 0.5).
    double alpha = 0.5;
    // k: a node's immediate neighbours, its k nearest nodes; s_b is the farthest of them.
    int neighbours = 8;
    // Simulated annealing iterations per path (geometric cooling over this many steps; a
    // path still improving when they run out counts in GraphMotionStats::anneal_bound_hits).
    int anneal_iterations = 1000;
    // At most this many graph nodes (drawn by the seed, per type in proportion): the edge
    // weights cost O(samples x nodes) Hungarian pairings.
    int max_nodes = 512;
    // Neighbourhood radius in the still's units; 0 = automatic: 1.5 x the mean
    // nearest-neighbour distance (the 1-ring, as the dynamic method's).
    double radius = 0.0;
    // Jacobi sweeps of the least-squares assignment per frame (Eq. 7); a frame still moving
    // when they run out counts in GraphMotionStats::sweep_bound_hits.
    int sweeps = 40;
    // Worker threads; 0 = all hardware threads. Results are byte-identical for every value.
    int threads = 0;
    // Seed of every random draw (node pool, annealing), keyed by (seed, sample).
    std::uint64_t seed = 1;
};

struct GraphMotionStats {
    int nodes = 0;                  // graph nodes
    double delta = 0.0;             // the largest edge weight (Eq. 13's normalisation)
    double direct_energy = 0.0;     // mean Eq. 13 energy of the direct paths s_a -> s_b
    double path_energy = 0.0;       // mean Eq. 13 energy of the annealed paths
    double path_steps = 0.0;        // mean steps of the annealed paths
    int still_samples = 0;          // samples with no path (no node of their type besides them)
    int anneal_bound_hits = 0;      // paths whose annealing still accepted moves at its bound
    int sweep_bound_hits = 0;       // frames whose Jacobi solve still moved at its bound
    double mean_speed = 0.0;        // mean sample displacement per frame, in mean spacings
    double seconds = 0.0;
    std::vector<std::string> notes; // one line per remark worth telling a user (bounds hit)
};

// The still as an animation of options.frames frames whose frame 0 is the still (its
// elements, ids and structure kept; time stamps from the samples' time, one unit apart).
// A still with multi-sample elements (threads, sheets, rigid bodies) moves on two levels:
// the elements' centroids as above, each element's shape along an annealed path through
// the graph of the still's element shapes (threads and sheets kept at their rest lengths,
// rigid elements turned only); see docs/dynamic.md.
// Throws Error(option) naming the field for a bad option (graph_motion_option_table),
// Error(input) for an invalid still, or one with fewer than 2 samples (2 elements when some
// element has several samples).
Animation enrich_by_graph(const Exemplar& still, const GraphMotionOptions& options = {},
                          GraphMotionStats* stats = nullptr);

// A short clip (an animation of F frames) continued to options.frames frames by graph
// synthesis: frames 0 .. F - 1 are the clip's, the later ones walk every sample's path from
// its neighbourhood at the clip's last frame through the graph of the neighbourhoods of all
// the clip's frames (a still is a clip of one frame: enrich_by_graph), at the clip's frame
// interval (one unit for a still). Threads, sheets and rigid elements continue from the
// last frame's shapes. A clip of options.frames frames or more is returned as it is.
// Throws as enrich_by_graph, naming the exemplar.
Animation extend_by_graph(const Animation& clip, const GraphMotionOptions& options = {},
                          GraphMotionStats* stats = nullptr);

// One row per GraphMotionOptions field (tessera/option_table.hpp).
const OptionTable<GraphMotionOptions>& graph_motion_option_table();

// DynamicOptions::graph_frames resolved for an exemplar: the frames graph synthesis gives
// it, or 0 when synthesize_dynamic uses the exemplar as it is (-1 = automatic: a one-frame
// exemplar gets 24 frames).
int graph_frames_for(const Animation& exemplar, const DynamicOptions& options);

}  // namespace tessera
