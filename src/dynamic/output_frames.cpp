// dynamic/output_frames.cpp — the output's frames, grids and output neighbourhoods.
#include "dynamic/output_frames.hpp"

#include <algorithm>

namespace tessera::dynamic {

OutputFrames::OutputFrames(int dimension, std::vector<int> sample_types, int matches, const StParams& params,
                           Periodic periodic)
    : params_(params), matches_(matches), type_(std::move(sample_types)), periodic_(periodic) {
    params_.dimension = dimension;
    const size_t n = type_.size();
    current_.assign(n, Vec3{});
    current_shift_.assign(n, Vec3{});
    images_.assign(params.temporal, {});
    grids_.resize(params.temporal);
    match_.assign(n * matches, -1);
    distance_.assign(n * matches, 0.0);
    omega_.assign(n * matches, 0.0);
    // Every entry of the N matched neighbourhoods can make one prediction.
    const int per_match = params.shape == NeighbourhoodShape::compact ? max_group + params.temporal
                                                                        : max_group * params.temporal;
    prediction_stride_ = matches * per_match;
    predictions_.resize(n * prediction_stride_);
    prediction_count_.assign(n, 0);
}

void PeriodicImages::build(const Vec3* positions, int n, const Periodic& periodic, double radius, int dimension) {
    points.assign(positions, positions + n);
    sample.resize(n);
    for (int s = 0; s < n; ++s) sample[s] = s;
    if (!periodic.on) return;
    for (int s = 0; s < n; ++s) {
        // Per axis: -1, 0 or +1 periods, the shift that brings the point near the far face.
        int near[3] = {0, 0, 0};
        for (int a = 0; a < dimension; ++a) {
            const double x = positions[s][a] - periodic.lo[a];
            if (x < radius) near[a] = 1;
            else if (x > periodic.extent[a] - radius) near[a] = -1;
        }
        for (int mask = 1; mask < (1 << dimension); ++mask) {
            Vec3 shift;
            bool valid = true;
            for (int a = 0; a < dimension && valid; ++a)
                if (mask & (1 << a)) valid = near[a] != 0, shift[a] = near[a] * periodic.extent[a];
            if (!valid) continue;
            points.push_back(positions[s] + shift);
            sample.push_back(s);
        }
    }
}

void OutputFrames::build_images(int k, const std::vector<Vec3>& positions) {
    PeriodicImages& im = images_[k];
    im.build(positions.data(), static_cast<int>(positions.size()), periodic_, params_.radius, params_.dimension);
    grids_[k].build(im.points, params_.radius, params_.dimension);
}

void OutputFrames::index() {
    build_images(0, current_);
    if (params_.shape != NeighbourhoodShape::full) return;
    const int n = size();
    std::vector<Vec3> advanced(n);
    for (int k = 1; k < params_.temporal && k <= frames_done_; ++k) {
        for (int s = 0; s < n; ++s) advanced[s] = position(s, k);
        build_images(k, advanced);
    }
}

void OutputFrames::gather(int s, StNeighbourhood& out) const {
    out.entries.clear();
    out.groups = std::min(params_.temporal, frames_done_ + 1);
    const Vec3 centre = current_[s];
    for (int k = 0; k < out.groups; ++k) {
        out.start[k] = static_cast<int>(out.entries.size());
        if (k > 0 && params_.shape == NeighbourhoodShape::compact) {
            const Vec3 d = position(s, k) - centre;
            out.entries.push_back({d, falloff(d, k, params_), type_[s], s});
            continue;
        }
        const PeriodicImages& im = images_[k];
        grids_[k].for_each_within(centre, params_.radius, [&](int i, double) {
            const int o = im.sample[i];
            if (k == 0 && o == s) return;
            const Vec3 d = im.points[i] - centre;
            out.entries.push_back({d, falloff(d, k, params_), type_[o], o});
        });
        finish_group(out.entries, out.start[k]);
    }
    for (int k = out.groups; k <= max_temporal; ++k) out.start[k] = static_cast<int>(out.entries.size());
}

void OutputFrames::commit() {
    past_.insert(past_.end(), current_.begin(), current_.end());
    past_shift_.insert(past_shift_.end(), current_shift_.begin(), current_shift_.end());
    ++frames_done_;
}

}  // namespace tessera::dynamic
