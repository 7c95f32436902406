// The output animation of all-frame synthesis (section 4.1, "all-frame sequencing"): every
// frame of every element at once, a grid per frame (with its periodic images under wrap),
// each sample's displacement by the flow up to each frame (so that neighbourhoods compare
// the detail motion, the output's motion less the global flow, with the exemplar's), and
// each sample-frame's matches and predictions. Sample-frame (s, f) has index f * size() + s.
#pragma once

#include <vector>

#include "core/spatial_grid.hpp"
#include "dynamic/obstacle_flow.hpp"
#include "dynamic/output_frames.hpp"
#include "dynamic/st_neighbourhood.hpp"

namespace tessera::dynamic {

// Spatial entries kept per output neighbourhood in all-frame synthesis: the radius holds
// the 1-ring (about 6 in 2D, 12 in 3D); more than this many are the farthest and dropped.
constexpr int all_frames_group0 = 16;

class AllFrames {
public:
    AllFrames(int frames, std::vector<int> sample_types, int matches, const StParams& params, Periodic periodic);

    int size() const { return static_cast<int>(type_.size()); }
    int frames() const { return frames_; }
    int matches() const { return matches_; }
    int type(int s) const { return type_[s]; }
    int index(int s, int f) const { return f * size() + s; }

    Vec3& at(int f, int s) { return position_[static_cast<size_t>(f) * type_.size() + s]; }
    const Vec3& at(int f, int s) const { return position_[static_cast<size_t>(f) * type_.size() + s]; }
    std::vector<Vec3>& positions() { return position_; }
    // The far flow's step from frame f - 1 to frame f (index 0 unused; set by the caller).
    std::vector<Vec3>& flow_steps() { return flow_step_; }
    const std::vector<Vec3>& flow_steps() const { return flow_step_; }
    // How far the flow carried sample s from frame 0 to frame f along its path.
    Vec3& drift(int f, int s) { return drift_[static_cast<size_t>(f) * type_.size() + s]; }
    const Vec3& drift(int f, int s) const { return drift_[static_cast<size_t>(f) * type_.size() + s]; }
    // The drift along the current paths: each frame's step is the flow's displacement from
    // the sample's place at the frame before (ObstacleFlow::displacement, which bends round
    // the domain's obstacles; the step itself where the flow is uniform).
    void carry(const ObstacleFlow& flow, int threads);

    // a - b, through the periodic border when wrapped (the nearest image).
    Vec3 difference(const Vec3& a, const Vec3& b) const;
    // Rebuilds every frame's grid over the current positions.
    void index_frames(int threads);
    // The temporal-non-causal neighbourhood of (s, f) (Figure 3, bottom; compact shape):
    // group 0 the spatial neighbours at f, group k >= 1 the sample itself at f + time_offset(k)
    // less the sample's drift between the two frames; groups beyond the output's first or
    // last frame are empty.
    void gather(int s, int f, StNeighbourhood& out) const;
    // Calls fn(s') for each sample within `radius` of (s, f) at frame f (not s).
    template <class Fn>
    void for_each_neighbour(int s, int f, double radius, Fn&& fn) const {
        const PeriodicImages& im = images_[f];
        grids_[f].for_each_within(at(f, s), radius, [&](int i, double) {
            if (im.sample[i] != s) fn(im.sample[i]);
        });
    }

    // Matches (ids into InputFrames, best first, -1 = none) per sample-frame; the search reads
    // prior_match (the previous round's, stable while others are rewritten).
    void snapshot_matches() { prior_match_ = match_; }
    int* match(int i) { return match_.data() + static_cast<size_t>(i) * matches_; }
    const int* prior_match(int i) const { return prior_match_.data() + static_cast<size_t>(i) * matches_; }
    double* distance(int i) { return distance_.data() + static_cast<size_t>(i) * matches_; }
    double* omega(int i) { return omega_.data() + static_cast<size_t>(i) * matches_; }

    // Predictions of sample-frame i (Prediction::sample = s', group = k: s' at frame
    // f + time_offset(k)).
    Prediction* predictions(int i) { return predictions_.data() + static_cast<size_t>(i) * stride_; }
    const Prediction* predictions(int i) const { return predictions_.data() + static_cast<size_t>(i) * stride_; }
    int& prediction_count(int i) { return prediction_count_[i]; }
    int prediction_count(int i) const { return prediction_count_[i]; }
    int prediction_stride() const { return stride_; }

private:
    void build_images(int f);

    StParams params_;
    int frames_ = 0, matches_ = 1, stride_ = 0;
    std::vector<int> type_;
    std::vector<Vec3> position_, drift_, flow_step_;
    Periodic periodic_;
    std::vector<PeriodicImages> images_;
    std::vector<core::SpatialGrid> grids_;
    std::vector<int> match_, prior_match_;
    std::vector<double> distance_, omega_;
    std::vector<Prediction> predictions_;
    std::vector<int> prediction_count_;
};

}  // namespace tessera::dynamic
