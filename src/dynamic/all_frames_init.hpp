// Initialization of all-frame synthesis of particles (section 4.1, "Initialization", all-
// frame sequencing): the patch-based initialization of the static method extended in time.
// The output domain is cut into patches the size of the neighbourhood (2 r); each receives
// the whole elements of a window of the exemplar's frame h (the first with a whole non-causal
// window), most constrained cells first, with quilting-style seams (det/init.hpp), and each
// copied element then follows its source's trajectory through the exemplar's frames: a
// spatio-temporal patch, so every frame holds the same elements.
#pragma once

#include <vector>

#include "dynamic/all_frames.hpp"
#include "dynamic/input_frames.hpp"
#include "tessera/animation.hpp"
#include "tessera/det.hpp"
#include "tessera/domain.hpp"
#include "tessera/dynamic.hpp"

namespace tessera::dynamic {

// Frame h of the output: the static patch copy. `source` receives, per output sample, the
// exemplar sample it was copied from.
Arrangement copy_first_frame(const Animation& exemplar, const Domain& domain, const DynamicOptions& options,
                             const StParams& params, int h, std::vector<int>& source);

// Fills every frame of `out` (out.flow_steps() set) from frame 0's positions `first` and
// the sources: frame f + 1 = frame f + the source's motion + the flow's displacement from
// frame f's place (round the obstacles; out.drift() records it), kept in the domain; the
// source's sample-frame is the sample-frame's first match. Temporal patches are chained: when the source reaches the exemplar's last frame, the element continues from the
// exemplar sample-frame of its type whose last two frame steps best match the element's own
// last two (the boundary compatibility of patch-based synthesis, in time), among frames
// 2 .. G / 2 so that the continuation runs long; the element keeps its identity throughout.
void copy_trajectories(const Animation& exemplar, const InputFrames& input, const std::vector<Vec3>& first,
                       const std::vector<int>& source, int h, const Domain& domain, const ObstacleFlow& flow,
                       bool wrap, AllFrames& out, int threads);

}  // namespace tessera::dynamic
