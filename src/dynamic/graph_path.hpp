// Motion paths of graph synthesis (Dynamic Element Textures, section 4.3, "Path
// computation"): from a node s_a to s_b, the farthest of its immediate neighbours, the path
// s_0 = s_a, ..., s_n = s_b that minimises Eq. 13,
//   E = sum_{i<n} |n(s_{i+1}) - n(s_i)|^2 / delta
//       + alpha (1 - sum_{0<=i,j<=n} |n(s_i) - n(s_j)|^2 / (delta n (n + 1))),
// smooth steps (first term) through diverse nodes (second term: one minus the mean distance
// between the path's nodes, normalised). |n(a) - n(b)|^2 is the edge weight (Eq. 4).
//
// n is fixed, as the paper's path s_0..s_n: over paths of any length, Eq. 13 prefers the
// direct one s_a -> s_b almost always (a step in the middle pays off only when a node lies
// between the two, d(a,m) + d(m,b) < 0.8 d(a,b) for one interior node, and the space of
// neighbourhoods has few: on poisson_disk_2d the best m gives 1.37 d(a,b) on average), and
// every motion would be one morph. The lengths are free in AnnealSettings for the tests.
#pragma once

#include <cstdint>
#include <vector>

#include "dynamic/graph_nodes.hpp"
#include "tessera/graph_motion.hpp"

namespace tessera::dynamic {

constexpr int max_path_steps = 16;  // bound on GraphMotionOptions::path_length (its table's)

// Eq. 13 for the path `nodes` (samples, s_0 first); 0 for a path of one node.
double path_energy(const NeighbourhoodGraph& graph, const std::vector<int>& nodes, double alpha);

struct AnnealSettings {
    int min_steps = 6;       // n at least (= max_steps: the paper's fixed n)
    int max_steps = 6;       // n at most
    double alpha = 0.5;      // Eq. 13
    int iterations = 1000;   // the bound of the annealing
    std::uint64_t seed = 1;
};

struct MotionPath {
    std::vector<int> nodes;      // s_0 = s_a ... s_n = s_b; {s_a} alone when s_a has no neighbour
    double energy = 0.0;         // Eq. 13 of `nodes`
    double direct_energy = 0.0;  // Eq. 13 of the direct path {s_a, s_b}
    bool at_bound = false;       // the annealing still accepted moves when its iterations ran out
};

// Simulated annealing over paths a -> s_b of min_steps to max_steps steps, from the direct
// path grown by random insertions to min_steps: moves replace, insert or remove an interior
// node (at the length bounds insert and remove relocate one: remove a node, insert another;
// a new node is an immediate neighbour of one of its path neighbours, and no node appears
// twice), accepted by the Metropolis rule under a geometric cooling from T0 = half the
// direct step's normalised weight to T0 / 1000 over `iterations` steps; it stops early once
// no move has been accepted for an eighth of them (frozen). Returns the best path seen.
// Random draws keyed by (seed, a): the same path whatever thread makes it.
MotionPath anneal_path(const NeighbourhoodGraph& graph, int a, const AnnealSettings& settings);

// An animation longer than one path's walk chains paths: `chains` annealed paths end to end,
// each from the last node of the one before (its s_b), so that a long enrichment keeps the
// pace of a short one instead of stretching one path over all its frames. Energies and the
// bound flag are those of the chain's paths summed and or-ed.
MotionPath chained_path(const NeighbourhoodGraph& graph, int a, const AnnealSettings& settings, int chains);

// Chains for `new_frames` frames: one path step per kFramesPerStep frames (24 frames of a
// still walk one path of 6 steps), at least 1, at most kMaxChains (beyond, the steps slow).
constexpr int kFramesPerStep = 4;
constexpr int kMaxChains = 8;
int path_chains(int new_frames, int path_length);

// The paths' means into `stats` (energies, steps of the paths of two nodes or more), their
// annealing bound hits, and the samples or elements left without a path.
void add_path_stats(const std::vector<MotionPath>& paths, GraphMotionStats& stats);

}  // namespace tessera::dynamic
