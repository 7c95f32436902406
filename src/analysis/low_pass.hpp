// The pieces of the motion analysis (tessera/motion_analysis.hpp; Dynamic Element Textures,
// section 5, Figures 6-7): the symmetric Gaussian windows, the elements' layouts by topology,
// and the three passes of the low-pass filter. Positions are frame-major, as in
// Animation::positions: values[f * samples + s].
//
// The filter weight of a neighbour sample-frame is separable, w = g_space * g_time, so the
// filter runs as a temporal pass over every sample (the window of the centre's frame), then a
// spatial pass over the temporally filtered positions: along the topology for threads and
// sheets, over other elements at the same frame for particles.
#pragma once

#include <cmath>
#include <vector>

#include "tessera/animation.hpp"

namespace tessera::analysis {

// The half-width of a window about index i of n (0 <= i < n) that `radius` asks for, shrunk
// so that the window holds as many indices on each side: min(radius, i, n - 1 - i). A window
// that stops at one end only would weigh one side more and pull the sample towards it.
inline int symmetric_half_width(int radius, int i, int n) {
    const int h = radius < i ? radius : i;
    return h < n - 1 - i ? h : n - 1 - i;
}

// One side of a symmetric Gaussian window: g[k] = exp(-k^2 / (2 sigma^2)), k = 0..half_width,
// with sigma = radius / 2 (the nominal radius, not the shrunk half-width: a window cut short
// near an end keeps the kernel's shape and only loses its tails). radius 0: {1}.
std::vector<double> gaussian_half_window(int half_width, int radius);

// A particle neighbour's weight at squared distance d2 in a disk of squared radius r2: the
// Gaussian of the nominal radius (sigma2 = (radius / 2)^2) less its value at the disk's edge,
// exp(-d2 / 2 sigma2) - exp(-r2 / 2 sigma2), written with expm1 so that a small disk keeps its
// precision. Zero at the edge, so a neighbour entering or leaving the disk from one frame to
// the next moves the average continuously. With the bare Gaussian cut at the edge it jumped:
// on swirl_particles_2d (the input's accelerations 0.018 per frame squared) the coarse
// animation's reached 0.54, 0.16 with this weight (near the box, where the disk is small).
inline double edge_gaussian_weight(double d2, double r2, double sigma2) {
    const double a = 0.5 * d2 / sigma2, b = 0.5 * r2 / sigma2;
    return -std::exp(-a) * std::expm1(a - b);
}

// How an element's samples hang together for the filter and for recombination.
enum class Kind { particle, grid };
struct Layout {
    Kind kind = Kind::particle;
    ElementTopology topology = ElementTopology::none;  // none, thread or sheet
    // A thread is 1 x n, a sheet rows x columns (sample id = row x columns + column); a
    // particle element 1 x its sample count.
    int rows = 1, columns = 1;
};
// The layout of every element of `data`, by its type's effective topology.
std::vector<Layout> element_layouts(const Exemplar& data);
const char* topology_word(ElementTopology topology);

// The temporal pass: every sample's position at frame f averaged over frames f - h .. f + h
// with h = symmetric_half_width(temporal_radius, f, frames).
std::vector<Vec3> temporal_low_pass(const Animation& input, int temporal_radius, int threads);

// Threads and sheets: the temporally filtered positions `smoothed` averaged along the
// element's grid, rows and columns each with their own symmetric half-width. Writes the
// element's samples of every frame of `coarse`.
void grid_low_pass(const Animation& input, const std::vector<Layout>& layouts,
                   const std::vector<Vec3>& smoothed, int topology_radius, int threads,
                   std::vector<Vec3>& coarse);

// Particles: `smoothed` averaged over the particle samples of other elements (and the sample
// itself) within the radius at the same frame, the radius shrunk to the sample's distance to
// the boundary of the domain's bounding box. Writes the particle samples of `coarse`.
void particle_low_pass(const Animation& input, const std::vector<Layout>& layouts,
                       const std::vector<Vec3>& smoothed, double radius, int threads,
                       std::vector<Vec3>& coarse);

// The automatic particle radius: 2 x the mean distance from each particle sample of frame 0
// to the nearest particle sample of another element; 0 when there are fewer than two.
double automatic_particle_radius(const Animation& input, const std::vector<Layout>& layouts);

}  // namespace tessera::analysis
