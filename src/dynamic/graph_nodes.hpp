// The neighbourhood graph of graph synthesis (Dynamic Element Textures, section 4.3, "Graph
// construction"): nodes are the spatial neighbourhoods of a still's samples, an edge between
// two nodes weighs their neighbourhood distance (Eq. 4), and delta is the largest weight.
//
// The graph is complete, as the paper's, but over a bounded pool of nodes: every sample is a
// row (it starts a path and needs its distances), at most `max_nodes` samples are columns
// (nodes a path may pass through). A still of a few hundred samples is its own pool, O(n^2)
// pairings; a larger one keeps O(samples x max_nodes).
#pragma once

#include <cstdint>
#include <vector>

#include "dynamic/input_frames.hpp"
#include "dynamic/st_metric.hpp"

namespace tessera::dynamic {

// The neighbourhood of sample s as an output neighbourhood: the entries of its input one
// (gathered within the input radius, nearest first) that lie within `radius`.
StNeighbourhood spatial_neighbourhood(const InputFrames& frames, int sample, double radius);

// The symmetric edge weight of Eq. 4 between two samples' neighbourhoods: the mean of the
// two directed distances (each pairs one side's entries within the radius with the other's
// within the input radius; unpaired entries cost the cap), so that an entry near the radius
// on one side is not counted as missing. Infinite between samples of different types: a
// neighbourhood is seen from its centre, and a centre of another type sees another pattern.
double edge_weight(const InputFrames& frames, const std::vector<StNeighbourhood>& own, int a, int b,
                   const StParams& params, MetricScratch& scratch);

class NeighbourhoodGraph {
public:
    NeighbourhoodGraph(const InputFrames& frames, const StParams& params, int max_nodes, int k, std::uint64_t seed,
                       int threads);
    // A complete graph over n nodes from their edge weights (n x n, row-major, symmetric;
    // infinite between nodes that may not be joined): the element shapes of a still of
    // threads, sheets or rigid elements (graph_shapes.hpp).
    NeighbourhoodGraph(int n, std::vector<double> weights, int k, int threads);

    int samples() const { return samples_; }
    // The nodes (samples) a path may pass through, ascending.
    const std::vector<int>& nodes() const { return pool_; }
    bool is_node(int sample) const { return column_[sample] >= 0; }
    // Edge weight between samples a and b, one of them a node (or a == b: 0).
    double weight(int a, int b) const {
        if (a == b) return 0.0;
        if (column_[b] >= 0) return d_[static_cast<size_t>(a) * pool_.size() + column_[b]];
        return d_[static_cast<size_t>(b) * pool_.size() + column_[a]];
    }
    // delta: the largest finite edge weight (Eq. 13's normalisation).
    double delta() const { return delta_; }
    // The k nearest nodes of sample a (its type, itself excluded), nearest first.
    const std::vector<int>& nearest(int a) const { return nearest_[a]; }
    // s_b: the immediate neighbour of a with the largest edge weight; -1 when a has none.
    int far_neighbour(int a) const { return nearest_[a].empty() ? -1 : nearest_[a].back(); }

private:
    void choose_pool(const InputFrames& frames, int max_nodes, std::uint64_t seed);

    int samples_ = 0;
    std::vector<int> pool_, column_;
    std::vector<double> d_;  // samples x pool, row-major
    double delta_ = 0.0;
    std::vector<std::vector<int>> nearest_;
};

}  // namespace tessera::dynamic
