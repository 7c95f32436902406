// The symmetric Gaussian windows of the low-pass filter (low_pass.hpp) and its temporal pass
// (Dynamic Element Textures, section 5: "the filter kernel should maintain symmetry both
// spatially and temporally ... for samples near spatial or temporal domain boundaries, the
// filter size will need to shrink accordingly").
#include <cmath>

#include "analysis/low_pass.hpp"
#include "core/parallel.hpp"

namespace tessera::analysis {

std::vector<double> gaussian_half_window(int half_width, int radius) {
    std::vector<double> g(static_cast<size_t>(half_width) + 1, 1.0);
    const double sigma = 0.5 * radius;
    for (int k = 1; k <= half_width; ++k) g[k] = std::exp(-0.5 * k * k / (sigma * sigma));
    return g;
}

std::vector<Vec3> temporal_low_pass(const Animation& input, int temporal_radius, int threads) {
    const int frames = input.frame_count(), samples = input.sample_count();
    std::vector<Vec3> out(input.positions.size());
    // One job per frame: the frame's window is the same for every sample, and each job writes
    // only its frame's slots, so any thread count gives the same bits.
    core::parallel_for(frames, threads, [&](int begin, int end, int) {
        for (int f = begin; f < end; ++f) {
            const int h = symmetric_half_width(temporal_radius, f, frames);
            const std::vector<double> g = gaussian_half_window(h, temporal_radius);
            double total = g[0];
            for (int k = 1; k <= h; ++k) total += 2.0 * g[k];
            for (int s = 0; s < samples; ++s) {
                Vec3 sum = input.at(f, s) * g[0];
                // Both sides of each offset together: a motion linear in time cancels exactly.
                for (int k = 1; k <= h; ++k) sum += (input.at(f - k, s) + input.at(f + k, s)) * g[k];
                out[static_cast<size_t>(f) * samples + s] = sum / total;
            }
        }
    });
    return out;
}

}  // namespace tessera::analysis
