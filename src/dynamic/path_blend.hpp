// The morphable model of graph synthesis (Dynamic Element Textures, section 4.3): along a
// motion path the neighbourhood of s_a morphs through the path's nodes. Two parts:
//   tracks:  each neighbour s' of s_a follows one entry of every node, paired with it by the
//            Hungarian algorithm (Eq. 4's pairing), so that the blend moves each neighbour
//            continuously instead of mixing unrelated ones. Every node is paired with s_a's
//            own neighbourhood, not with the node before it: chained pairings let a track
//            drift a little further at each step and a track left unpaired (holding its
//            place) end up on another's, two neighbours predicted at one place; measured on
//            poisson_disk_2d, the closest pair of the enriched frames fell to 0.28 of the
//            still's with chained pairings and stays at 0.70 with this one. Consecutive nodes
//            still move a track continuously: both of its entries lie within a spacing of
//            its place in the still;
//   weights: the blending weights of the path's nodes over time, the nodes taken as data
//            points of a fourth-order (cubic) B-spline that passes through them.
#pragma once

#include <vector>

#include "dynamic/input_frames.hpp"
#include "dynamic/st_metric.hpp"

namespace tessera::dynamic {

// Cardinal weights of the natural interpolating uniform cubic B-spline through `nodes` data
// points at parameters 0, 1, ..., nodes - 1: C(u) = sum_j w_j(u) d_j passes through d_j at
// u = j, is C2, and has zero curvature at its ends (the "natural" end condition, so that a
// path of two nodes is a straight line at constant speed). The weights sum to 1, so a blend
// of offsets is an offset; some are slightly negative between nodes, as any C2
// interpolation's.
class SplineBlend {
public:
    explicit SplineBlend(int nodes);
    int nodes() const { return nodes_; }
    // w_0..w_{nodes-1} at u in [0, nodes - 1].
    void weights(double u, double* w) const;

private:
    int nodes_ = 1;
    // control[k * nodes_ + j]: control point k (of nodes_ + 2, ghost ends included) as a
    // combination of the data points j.
    std::vector<double> control_;
};

// The blends of paths of 1 .. `nodes` nodes (splines[k - 1] has k).
std::vector<SplineBlend> splines_up_to(int nodes);

// The neighbours of one sample followed along its path.
struct PathTracks {
    int nodes = 1;               // path nodes, s_0 .. s_n
    std::vector<int> neighbour;  // per track: the still's neighbour sample s' it moves
    std::vector<Vec3> offset;    // offset[t * nodes + i]: the offset of track t at path node i
    int tracks() const { return static_cast<int>(neighbour.size()); }
};

// Tracks of sample `own` (its spatial neighbourhood) along `path` (samples; path[0] is the
// sample itself). Each node's entries (gathered within the input radius, so that a neighbour
// near the radius finds its partner) are paired with `own`; a track left unpaired at a node
// keeps its place in the still there, rather than move to an entry it does not resemble.
PathTracks path_tracks(const InputFrames& frames, const StNeighbourhood& own, const std::vector<int>& path,
                       const StParams& params, MetricScratch& scratch);

// The blended offsets of every track at weights w (one per path node).
void blend_tracks(const PathTracks& tracks, const double* w, Vec3* out);

}  // namespace tessera::dynamic
