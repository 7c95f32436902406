// decompose_motion (tessera/motion_analysis.hpp): Dynamic Element Textures, section 5,
// Figures 6-7. "Perform a low pass filtering of spatial-temporal sample positions of a given
// input I to obtain the coarse spatial-temporal sample positions C, with the details D
// computed as their difference D = I - C." The filter (low_pass.hpp) is a temporal pass
// followed by a spatial pass along each element's topology (threads, sheets) or over the
// neighbouring particles, every window kept symmetric about its sample.
#include "analysis/low_pass.hpp"
#include "tessera/motion_analysis.hpp"
#include "tessera/option_table.hpp"

namespace tessera {

namespace {

// An animation with `source`'s structure and times and the given positions; its structure
// holds frame 0 (samples and element centroids), as an Animation's does.
Animation with_positions(const Animation& source, std::vector<Vec3> positions) {
    Animation out;
    out.structure = source.structure;
    out.times = source.times;
    out.positions = std::move(positions);
    out.structure = out.frame(0);
    return out;
}

}  // namespace

MotionSplit decompose_motion(const Animation& input, const LowPassOptions& options) {
    check_options(low_pass_option_table(), options);
    input.validate("animation");
    const std::vector<analysis::Layout> layouts = analysis::element_layouts(input.structure);
    const std::vector<Vec3> smoothed =
        analysis::temporal_low_pass(input, options.temporal_radius, options.threads);
    std::vector<Vec3> coarse(input.positions.size());
    analysis::grid_low_pass(input, layouts, smoothed, options.topology_radius, options.threads, coarse);
    const double radius = options.spatial_radius > 0.0 ? options.spatial_radius
                                                       : analysis::automatic_particle_radius(input, layouts);
    analysis::particle_low_pass(input, layouts, smoothed, radius, options.threads, coarse);
    std::vector<Vec3> detail(input.positions.size());
    for (size_t i = 0; i < detail.size(); ++i) detail[i] = input.positions[i] - coarse[i];
    return {with_positions(input, std::move(coarse)), with_positions(input, std::move(detail))};
}

}  // namespace tessera
