// dynamic/output_frames.cpp — the output's frames, grids and output neighbourhoods.
#include "dynamic/output_frames.hpp"

#include <algorithm>

namespace tessera::dynamic {

OutputFrames::OutputFrames(int dimension, std::vector<int> sample_types, int matches, const StParams& params)
    : params_(params), matches_(matches), type_(std::move(sample_types)) {
    params_.dimension = dimension;
    const size_t n = type_.size();
    current_.assign(n, Vec3{});
    current_shift_.assign(n, Vec3{});
    advanced_.assign(params.temporal, {});
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

void OutputFrames::index() {
    grids_[0].build(current_, params_.radius, params_.dimension);
    if (params_.shape != NeighbourhoodShape::full) return;
    const int n = size();
    for (int k = 1; k < params_.temporal && k <= frames_done_; ++k) {
        advanced_[k].resize(n);
        for (int s = 0; s < n; ++s) advanced_[k][s] = position(s, k);
        grids_[k].build(advanced_[k], params_.radius, params_.dimension);
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
        const std::vector<Vec3>& points = k == 0 ? current_ : advanced_[k];
        grids_[k].for_each_within(centre, params_.radius, [&](int o, double) {
            if (k == 0 && o == s) return;
            const Vec3 d = points[o] - centre;
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
