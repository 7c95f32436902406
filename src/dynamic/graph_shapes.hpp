// Graph synthesis for a still of multi-sample elements (Dynamic Element Textures, section
// 4.3; Figure 12 animates a willow's branches, threads traced on one photo). A thread's or a
// sheet's samples have their neighbourhood along the element first (the topology constraint
// of section 3.2: the samples pair by their place on the element's grid, no matching), so
// here a node is a whole element's shape: its samples' offsets from its centroid, in the
// still's orientation, as Eq. 4 compares offsets. Two shapes of one type and sample count
// weigh the mean squared distance of their topology-paired offsets; others are not joined.
// The motion is then the sample-level method's, on two levels:
//   - where: the elements' centroids, a still of particles, enriched by enrich_by_graph;
//   - how: every element's shape walks an annealed path (Eq. 13) through the graph of
//     shapes, blended by the same interpolating cubic B-spline; threads and sheets are then
//     projected back to their rest lengths (element_lengths.hpp: a sheet's diagonals too, so
//     no quad folds), and a rigid element (multi-sample, topology none) keeps its own shape,
//     turned by the best fit (Kabsch) onto the blended one.
// Frame 0 is the still, bit for bit.
#pragma once

#include "tessera/graph_motion.hpp"

namespace tessera::dynamic {

// The still (with some multi-sample element, at least 2 elements) as options.frames frames.
Animation enrich_elements_by_graph(const Exemplar& still, const GraphMotionOptions& options, GraphMotionStats& stats);

}  // namespace tessera::dynamic
