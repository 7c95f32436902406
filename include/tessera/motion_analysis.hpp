// tessera/motion_analysis.hpp — the analysis of Dynamic Element Textures (Ma et al. 2013),
// section 5, Figures 6-7: an animation split into a coarse motion and the details on top of
// it, and the recombination of the coarse motion of one animation with the details of
// another (the detail motion of hair applied to a novel coarse motion).
//
// The coarse animation C is a low-pass filter of the spatio-temporal sample positions of the
// input I; the details are D = I - C, so that C + D gives I back. The filter is a separable
// Gaussian, w = g_space * g_time, normalised, whose window is kept symmetric about every
// sample: near a temporal end (the first and last frames), near a thread's ends or a sheet's
// borders, and near the domain's boundary for particles, it shrinks to what lies on both
// sides. A one-sided window would pull a sample towards its inner side, and a uniform motion
// would leak into the details there; a symmetric one reproduces motion that is linear in time
// and threads / sheets that are linear along their index exactly (docs/dynamic.md, "Analysis:
// coarse and detail motion").
#pragma once

#include "tessera/animation.hpp"

namespace tessera {

struct LowPassOptions {
    // Particles (topology none): Gaussian kernel radius in the exemplar's length units over
    // samples of other elements at the same frame; 0 = automatic (2 x the mean
    // nearest-neighbour distance of frame 0).
    double spatial_radius = 0.0;
    // Threads and sheets: kernel half-width in samples along the element's own topology
    // (thread index; sheet rows and columns).
    int topology_radius = 3;
    // Kernel half-width in frames.
    int temporal_radius = 2;
    // Worker threads; 0 = all. The result is byte-identical for any count.
    int threads = 0;
};

struct MotionSplit {
    Animation coarse;  // the low-passed positions, same structure and times as the input
    Animation detail;  // positions hold I - C (offset vectors), same structure and times as the input
};

// Splits `input` into its coarse motion and details (section 5). Throws Error(option) naming
// the option for an option outside its range (low_pass_option_table()), Error(input) when
// `input` breaks the animation model (Animation::validate).
MotionSplit decompose_motion(const Animation& input, const LowPassOptions& options = {});

// coarse + detail; detail may come from another animation: frame f uses detail frame
// f mod detail.frame_count(); the i-th element of a topology kind (none, thread, sheet) in
// coarse uses the detail's element (i mod its element count of that kind) of the same kind;
// a thread / sheet with a different sample count is resampled linearly along its index
// (rows / columns), a particle element's sample k uses detail sample k mod its sample count.
// Output has coarse's structure and times. Throws Error(input) when the two differ in
// dimension or coarse has elements of a topology kind that detail has none of.
Animation recombine_motion(const Animation& coarse, const Animation& detail);

}  // namespace tessera
