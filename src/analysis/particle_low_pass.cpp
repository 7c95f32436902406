// The low-pass filter of particles (Dynamic Element Textures, section 5, Figure 6: a group's
// coarse motion is the motion of its neighbourhood, the details what each particle does on
// its own). A particle sample at frame f is averaged with the particle samples of other
// elements within the radius at frame f, each taken through the temporal pass (their own
// positions at frames f - h .. f + h: the kernel is spatio-temporal), with Gaussian weights
// of their distance at frame f that fall to zero at the disk's edge (edge_gaussian_weight).
//
// Near the domain's boundary the disk is shrunk to the sample's distance to the boundary of
// the domain's bounding box, so that it never reaches past the boundary: the neighbours then
// lie on every side, and a sample next to an edge is not pulled inwards by the neighbours it
// has on one side only. A rigid motion of a lattice that fills the box comes out exactly.
#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/low_pass.hpp"
#include "core/parallel.hpp"
#include "core/spatial_grid.hpp"

namespace tessera::analysis {

namespace {

struct Particles {
    std::vector<int> samples;  // the particle samples, in sample order
    std::vector<int> element;  // their elements
};

Particles particle_samples(const Animation& input, const std::vector<Layout>& layouts) {
    Particles p;
    const std::vector<Element>& elements = input.structure.elements;
    for (size_t e = 0; e < elements.size(); ++e) {
        if (layouts[e].kind != Kind::particle) continue;
        for (int k = 0; k < elements[e].sample_count; ++k) {
            p.samples.push_back(elements[e].first_sample + k);
            p.element.push_back(static_cast<int>(e));
        }
    }
    return p;
}

// Distance from p to the boundary of the box, positive inside (2D: x and y only).
double distance_to_box(const Box& box, const Vec3& p, int dimension) {
    double d = std::numeric_limits<double>::infinity();
    for (int k = 0; k < dimension; ++k) d = std::min({d, p[k] - box.lo[k], box.hi[k] - p[k]});
    return d;
}

std::vector<Vec3> frame_points(const Animation& input, const Particles& particles, int f) {
    std::vector<Vec3> points(particles.samples.size());
    for (size_t i = 0; i < points.size(); ++i) points[i] = input.at(f, particles.samples[i]);
    return points;
}

}  // namespace

double automatic_particle_radius(const Animation& input, const std::vector<Layout>& layouts) {
    const Particles particles = particle_samples(input, layouts);
    const int n = static_cast<int>(particles.samples.size());
    if (n < 2) return 0.0;
    const std::vector<Vec3> points = frame_points(input, particles, 0);
    const int d = input.structure.dimension;
    const Box box = input.structure.domain.bounds();
    core::SpatialGrid grid;
    grid.build(points, std::pow(input.structure.domain.measure() / n, 1.0 / d), d);
    const double reach = 2.0 * norm(box.size()) + 1.0;
    double sum = 0.0;
    int counted = 0;
    for (int i = 0; i < n; ++i) {
        const int j = grid.nearest(points[i], reach,
                                   [&](int k) { return particles.element[k] != particles.element[i]; });
        if (j < 0) continue;
        const Vec3 diff = points[j] - points[i];
        sum += d == 2 ? std::hypot(diff.x, diff.y) : norm(diff);
        ++counted;
    }
    return counted ? 2.0 * sum / counted : 0.0;
}

namespace {

// The particle samples of frame f: each averaged over the disk about it at that frame.
void particle_frame(const Animation& input, const Particles& particles, const std::vector<Vec3>& smoothed,
                    double radius, int f, std::vector<Vec3>& coarse) {
    const int d = input.structure.dimension;
    const Box box = input.structure.domain.bounds();
    const double sigma2 = 0.25 * radius * radius;
    const std::vector<Vec3> points = frame_points(input, particles, f);
    core::SpatialGrid grid;
    grid.build(points, radius, d);
    const size_t base = static_cast<size_t>(f) * input.sample_count();
    for (size_t i = 0; i < points.size(); ++i) {
        const double r = std::clamp(distance_to_box(box, points[i], d), 0.0, radius);
        Vec3 sum;
        double total = 0.0;
        grid.for_each_within(points[i], r, [&](int j, double d2) {
            if (j != static_cast<int>(i) && particles.element[j] == particles.element[i]) return;
            const double w = edge_gaussian_weight(d2, r * r, sigma2);
            sum += smoothed[base + particles.samples[j]] * w;
            total += w;
        });
        // A disk shrunk to nothing (a sample on the box's boundary) leaves the sample alone.
        const size_t slot = base + particles.samples[i];
        coarse[slot] = total > 0.0 ? sum / total : smoothed[slot];
    }
}

}  // namespace

void particle_low_pass(const Animation& input, const std::vector<Layout>& layouts,
                       const std::vector<Vec3>& smoothed, double radius, int threads,
                       std::vector<Vec3>& coarse) {
    const Particles particles = particle_samples(input, layouts);
    const int frames = input.frame_count(), samples = input.sample_count();
    if (!(radius > 0.0)) {  // fewer than two particles: nothing to average across
        for (int f = 0; f < frames; ++f)
            for (int s : particles.samples)
                coarse[static_cast<size_t>(f) * samples + s] = smoothed[static_cast<size_t>(f) * samples + s];
        return;
    }
    // One job per frame: its grid over the frame's particle positions, and only its slots written.
    core::parallel_for(frames, threads, [&](int begin, int end, int) {
        for (int f = begin; f < end; ++f) particle_frame(input, particles, smoothed, radius, f, coarse);
    });
}

}  // namespace tessera::analysis
