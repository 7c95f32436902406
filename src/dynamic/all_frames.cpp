// dynamic/all_frames.cpp — the output of all-frame synthesis, its grids and neighbourhoods.
#include "dynamic/all_frames.hpp"

#include <algorithm>
#include <cmath>

#include "core/parallel.hpp"

namespace tessera::dynamic {

AllFrames::AllFrames(int frames, std::vector<int> sample_types, int matches, const StParams& params,
                     Periodic periodic)
    : params_(params), frames_(frames), matches_(matches), type_(std::move(sample_types)), periodic_(periodic) {
    const size_t n = type_.size() * static_cast<size_t>(frames);
    position_.assign(n, Vec3{});
    drift_.assign(n, Vec3{});
    flow_step_.assign(frames, Vec3{});
    images_.resize(frames);
    grids_.resize(frames);
    match_.assign(n * matches, -1);
    prior_match_ = match_;
    distance_.assign(n * matches, 0.0);
    omega_.assign(n * matches, 0.0);
    // Each of the N matched neighbourhoods pairs at most every entry: the spatial group's
    // and one trail entry per other group.
    stride_ = matches * (all_frames_group0 + params.temporal);
    predictions_.resize(n * stride_);
    prediction_count_.assign(n, 0);
}

Vec3 AllFrames::difference(const Vec3& a, const Vec3& b) const {
    Vec3 d = a - b;
    if (periodic_.on)
        for (int k = 0; k < params_.dimension; ++k) d[k] -= periodic_.extent[k] * std::round(d[k] / periodic_.extent[k]);
    return d;
}

// Frame f's positions with their periodic images, and the grid over them.
void AllFrames::build_images(int f) {
    PeriodicImages& im = images_[f];
    im.build(position_.data() + static_cast<size_t>(f) * size(), size(), periodic_, params_.radius, params_.dimension);
    grids_[f].build(im.points, params_.radius, params_.dimension);
}

void AllFrames::carry(const ObstacleFlow& flow, int threads) {
    core::parallel_for(size(), threads, [&](int begin, int end, int) {
        for (int s = begin; s < end; ++s)
            for (int f = 1; f < frames_; ++f) drift(f, s) = drift(f - 1, s) + flow.displacement(at(f - 1, s), flow_step_[f]);
    });
}

void AllFrames::index_frames(int threads) {
    core::parallel_for(frames_, threads, [&](int begin, int end, int) {
        for (int f = begin; f < end; ++f) build_images(f);
    });
}

void AllFrames::gather(int s, int f, StNeighbourhood& out) const {
    out.entries.clear();
    out.groups = params_.temporal;
    const Vec3 centre = at(f, s);
    for (int k = 0; k < out.groups; ++k) {
        out.start[k] = static_cast<int>(out.entries.size());
        const int dt = time_offset(k, params_), g = f + dt;
        if (k > 0) {
            if (g < 0 || g >= frames_) continue;  // beyond the animation: an empty group
            const Vec3 d = difference(at(g, s), centre) - (drift(g, s) - drift(f, s));
            out.entries.push_back({d, falloff(d, dt, params_), type_[s], s});
            continue;
        }
        const PeriodicImages& im = images_[f];
        grids_[f].for_each_within(centre, params_.radius, [&](int i, double) {
            const int o = im.sample[i];
            if (o == s) return;
            const Vec3 d = im.points[i] - centre;
            out.entries.push_back({d, falloff(d, 0, params_), type_[o], o});
        });
        finish_group(out.entries, out.start[k]);
        const int end = out.start[k] + all_frames_group0;
        if (static_cast<int>(out.entries.size()) > end) out.entries.resize(end);
    }
    for (int k = out.groups; k <= max_temporal; ++k) out.start[k] = static_cast<int>(out.entries.size());
}

}  // namespace tessera::dynamic
