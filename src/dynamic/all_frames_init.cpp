// dynamic/all_frames_init.cpp — spatio-temporal patch copy for all-frame synthesis.
#include "dynamic/all_frames_init.hpp"

#include <algorithm>
#include <limits>

#include "core/parallel.hpp"
#include "det/init.hpp"
#include "det/input_index.hpp"
#include "det/session_steps.hpp"
#include "dynamic/all_frames_solve.hpp"

namespace tessera::dynamic {

namespace {

struct Source {
    int sample = -1, frame = 0;  // the exemplar sample followed and the frame it is at
};

int type_of(const Exemplar& ex, int sample) { return ex.elements[ex.samples[sample].element].type; }

Vec3 step_into(const Animation& exemplar, int frame, int sample) {
    return exemplar.at(frame, sample) - exemplar.at(frame - 1, sample);
}

// The next temporal patch (see the header): the exemplar sample-frame (j, g) whose steps into
// g and g - 1 best match the element's last two steps `last`, `before`. Ties keep the lower
// (g, j). Bounded: one scan of the type's samples over half the exemplar's frames.
Source continuation(const Animation& exemplar, const std::vector<int>& of_type, const Vec3& last,
                    const Vec3& before) {
    const int frames = exemplar.frame_count();
    Source best{of_type.front(), std::min(2, frames - 1)};
    double best_cost = std::numeric_limits<double>::infinity();
    for (int g = 2; g <= std::max(2, frames / 2) && g + 1 < frames; ++g)
        for (int j : of_type) {
            const double cost =
                squared_norm(step_into(exemplar, g, j) - last) + squared_norm(step_into(exemplar, g - 1, j) - before);
            if (cost < best_cost) best_cost = cost, best = {j, g};
        }
    return best;
}

void copy_element(const Animation& exemplar, const InputFrames& input, const std::vector<int>& of_type,
                  const Vec3& first, int source, int h, const Domain& domain, const ObstacleFlow& flow, bool wrap,
                  AllFrames& out, int s) {
    const int frames = exemplar.frame_count();
    Source at{source, h};
    out.at(0, s) = first;
    out.match(out.index(s, 0))[0] = input.id(at.sample, at.frame);
    Vec3 last, before;  // the element's last two detail steps
    for (int f = 1; f < out.frames(); ++f) {
        if (at.frame + 1 >= frames) at = continuation(exemplar, of_type, last, before);
        ++at.frame;
        const Vec3 step = step_into(exemplar, at.frame, at.sample);
        before = last, last = step;
        const Vec3 carried = flow.displacement(out.at(f - 1, s), out.flow_steps()[f]);
        out.drift(f, s) = out.drift(f - 1, s) + carried;
        Vec3 p = out.at(f - 1, s) + step + carried;
        keep_inside_domain(p, domain, wrap);
        out.at(f, s) = p;
        out.match(out.index(s, f))[0] = input.id(at.sample, at.frame);
    }
}

}  // namespace

Arrangement copy_first_frame(const Animation& exemplar, const Domain& domain, const DynamicOptions& options,
                             const StParams& params, int h, std::vector<int>& source) {
    DetOptions det;
    det.seed = options.seed;
    det.threads = options.threads;
    det.patch_size = 2.0 * params.radius;  // the neighbourhood's size, as the paper sets it
    const Exemplar frame = exemplar.frame(h);
    const det::Params det_params = det::resolve_params(frame, det);
    det::InitResult init = det::initialize_patches(frame, det::InputIndex{}, domain, det_params, det);
    source = init.source_sample;
    det::number_compactly(init.arrangement);  // the patch copy leaves its new elements unnumbered
    return std::move(init.arrangement);
}

void copy_trajectories(const Animation& exemplar, const InputFrames& input, const std::vector<Vec3>& first,
                       const std::vector<int>& source, int h, const Domain& domain, const ObstacleFlow& flow,
                       bool wrap, AllFrames& out, int threads) {
    const Exemplar& ex = exemplar.structure;
    std::vector<std::vector<int>> of_type(ex.types.size());
    for (int j = 0; j < exemplar.sample_count(); ++j) of_type[type_of(ex, j)].push_back(j);
    core::parallel_for(
        out.size(), threads,
        [&](int begin, int end, int) {
            for (int s = begin; s < end; ++s)
                copy_element(exemplar, input, of_type[type_of(ex, source[s])], first[s], source[s], h, domain, flow,
                             wrap, out, s);
        },
        8);
}

}  // namespace tessera::dynamic
