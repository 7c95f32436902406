// tessera/dynamic.hpp — dynamic element textures: synthesis in space and time.
//
// Implements Ma, Wei, Lefebvre and Tong, "Dynamic Element Textures" (SIGGRAPH 2013),
// section 3 and 4: spatio-temporal samples u(s) = (p(s), t(s)) (Eq. 1), neighbourhoods of
// relative differences (Eq. 2-3) matched exactly by the Hungarian algorithm among samples of
// equal time offset (Eq. 4), temporal-causal neighbourhoods of the compact shape (spatial
// neighbours plus the sample's own temporal trail) or the full shape, frame-by-frame
// synthesis (the first frame by the static method's patch initialization and
// search/assign, each later frame advected by the matched input velocities and then
// optimised by search and the least-squares assignment of Eq. 6-7, parallelised
// Jacobi-style), and smooth synthesis (Eq. 8-12: Gaussian falloff, N best matches blended).
// Output constraints: the domain shape (elements kept inside it) and a global flow.
//
// Docs: docs/dynamic.md. Options: tessera/option_table.hpp (dynamic_option_table).
#pragma once

#include <cstdint>

#include "tessera/animation.hpp"
#include "tessera/det.hpp"
#include "tessera/domain.hpp"
#include "tessera/progress.hpp"

namespace tessera {

// Neighbourhood shape of Figure 3 (right): spatial neighbours at the sample's own frame
// plus its 1D temporal trail (compact), or every sample within the spatial radius at every
// frame of the temporal window (full).
enum class NeighbourhoodShape { compact, full };

// Sequencing (section 4.1): frame by frame (temporal-causal neighbourhoods, each frame
// advected from the last) or all frames together (spatio-temporal patch copy, then search
// and assignment over every frame at once with temporal-non-causal neighbourhoods).
enum class Sequencing { frame, all };

struct DynamicOptions {
    // Output frames; 0 = as many as the exemplar has (at least 2).
    int frames = 0;
    // Spatial neighbourhood radius in the exemplar's units; 0 = automatic: 1.5 x the
    // exemplar's mean nearest-neighbour distance (the 1-ring, as the paper's section 6 and
    // Table 2 advise).
    double radius = 0.0;
    // Frames in a neighbourhood, the sample's own included (Table 2: 1 to 10).
    int temporal_size = 3;
    NeighbourhoodShape shape = NeighbourhoodShape::compact;
    // Smooth synthesis (section 4.2): the spatial falloff sigma_p, in neighbourhood radii,
    // and the temporal falloff sigma_t, in frames, of the Gaussian kernel of Eq. 10;
    // 0 = no falloff (the paper's infinity).
    double sigma_p = 0.0;
    double sigma_t = 0.0;
    // N best input matches blended by Eq. 11-12; 1 = the basic algorithm (section 4.1).
    int matches = 2;
    // Search + assignment rounds per frame (sequencing all: rounds over all frames).
    int iterations = 2;
    Sequencing sequencing = Sequencing::frame;
    // Search: k-coherence (the matches' own continuations, their neighbours' shifted
    // matches and random input samples) or an exhaustive scan of every input sample.
    SearchMode search = SearchMode::kcoherence;
    // Random input samples tried per output sample and search besides the coherent ones.
    int random_candidates = 2;
    // Weight of a type mismatch between paired neighbours, in squared length units;
    // negative = automatic: (mean nearest-neighbour distance)^2.
    double alpha = -1.0;
    // Global flow (units per unit of time) added to every element's motion: the coarse
    // motion the exemplar's detail motion rides on.
    Vec3 flow;
    // Degrees per unit of time the flow turns about the z axis (a school of fish wheeling);
    // 0 = a steady flow.
    double flow_turn = 0.0;
    // An element the motion carries out of the domain re-enters on the opposite side of the
    // domain's bounding box (periodic: a steady flow keeps the domain filled); off = it is put
    // back at the nearest point inside.
    bool wrap = false;
    // Physics sub-step (section 4.4, Figure 5): frame by frame after each frame's advection,
    // and again after its last assignment (all frames together: on every frame after each
    // round's assignment), the particles go through a Bullet step, as spheres of half the
    // exemplar's closest-pair distance without gravity, which pushes apart the ones that
    // collided and out of the domain's obstacles the ones that went into them.
    bool physics = false;
    // Frame by frame, voids wider than any the exemplar holds (a flow opens them, past an
    // obstacle above all) are closed from their rim, a tenth of a spacing at a time
    // (dynamic/void_closing.hpp); true = leave them (the paper's method as it is).
    bool keep_voids = false;
    // Graph synthesis (section 4.3, tessera/graph_motion.hpp): motion for a still, more for a
    // short clip. -1 = automatic (a one-frame exemplar is enriched to 24 frames), 0 = off,
    // N >= 2 = the exemplar continued to N frames (extend_by_graph: a clip of F < N frames
    // keeps its own and walks on from its last frame; one of N frames or more is kept).
    int graph_frames = -1;
    // All-frame synthesis on a coarse motion (synthesize_on_coarse): the width of the grid
    // neighbourhood of threads and sheets in samples (half-width size / 2: 7 = the paper's 7 x 7), and how the
    // exemplar is split into coarse and detail motion (section 5): the low-pass kernel's
    // half-width along the elements in samples and in frames.
    int topology_size = 7;
    int split_samples = 3;
    int split_frames = 2;
    // Weight of each sample of another element in a thread's or sheet's neighbourhood (the
    // Hungarian part beside the grid part: its detail relative to the centre's, paired by
    // place), against a grid entry's 1; 0 = the grid part alone.
    double cross_weight = 1.0;
    // Worker threads; 0 = all hardware threads. Results are byte-identical for every value.
    int threads = 0;
    // Seed of every random draw (counter-based, keyed by frame and world position).
    std::uint64_t seed = 1;
};

struct AnimatedArrangement : Animation {
    RunStats stats;
};

// Synthesizes an animation of `exemplar` over `domain` frame by frame (or, with sequencing
// all, every frame together: particles and agents only, the compact shape). Throws Error(input)
// for an invalid exemplar (Animation::validate) or one with multi-sample elements (threads
// and sheets follow a coarse motion: synthesize_on_coarse), Error(option) for a bad option (checked against
// dynamic_option_table), Error(domain) for a domain of another dimension, Cancelled when
// `progress` returns false (stages "first frame" and "frame").
AnimatedArrangement synthesize_dynamic(const Animation& exemplar, const Domain& domain,
                                       const DynamicOptions& options = {}, const Progress& progress = {});

// All-frame synthesis on a coarse motion given for whole elements (section 4.1, all-frame
// sequencing; Figures 10 and 13): the output has `coarse`'s elements, frames and times, and
// each sample is its coarse position plus a detail motion synthesized from the exemplar's.
// The exemplar is split into coarse and detail motion (section 5, motion_analysis.hpp); the
// details, in the local frame of the coarse geometry (along a thread, across it, a sheet's
// normal), are initialized by copying whole exemplar elements over windows of frames and
// optimised by search and Jacobi assignment over temporal-non-causal grid neighbourhoods
// (threads: topology_size samples along the thread; sheets: topology_size^2 on the sheet;
// particles: the trail only), then threads and sheets are held to their rest lengths.
// Throws Error(input) for an invalid exemplar or coarse motion, a coarse type the exemplar
// lacks or has with another topology, multi-sample elements of topology none; Error(option)
// for a bad option; Cancelled when `progress` returns false (stage "iteration").
AnimatedArrangement synthesize_on_coarse(const Animation& exemplar, const Animation& coarse,
                                         const DynamicOptions& options = {}, const Progress& progress = {});

}  // namespace tessera
