// The exemplar animation indexed for search: every input sample-frame (s, g) whose causal
// window g - T + 1 .. g (non-causal: g - h .. g + h) lies in the exemplar gets its neighbourhood (st_neighbourhood.hpp),
// its continuation (s, g + 1), its motion to the next frame, and a k-coherence set; a grid
// per input frame answers "which input sample is nearest this point at frame g".
#pragma once

#include <vector>

#include "core/spatial_grid.hpp"
#include "dynamic/st_neighbourhood.hpp"
#include "tessera/animation.hpp"

namespace tessera::dynamic {

class InputFrames {
public:
    // Builds the neighbourhoods of every usable sample-frame and the per-frame grids.
    // The similarity sets are built separately (build_similarity) once the metric exists.
    InputFrames(const Animation& exemplar, const StParams& params, int threads);

    int size() const { return static_cast<int>(sample_.size()); }
    int first_frame() const { return first_frame_; }   // T - 1 (non-causal: h)
    int last_frame() const { return last_frame_; }     // the last frame with a whole window
    int frame_count() const { return frame_count_; }
    // The id of (sample, frame), or -1 when the frame's window is not in the exemplar.
    int id(int sample, int frame) const {
        if (frame < first_frame_ || frame > last_frame_) return -1;
        return (frame - first_frame_) * samples_ + sample;
    }
    int sample(int id) const { return sample_[id]; }
    int frame(int id) const { return frame_[id]; }
    int type(int id) const { return type_[id]; }
    // (s, g + 1), or -1 at the last usable frame; (s, g - 1), or -1 at the first.
    int next(int id) const { return frame_[id] < last_frame_ ? id + samples_ : -1; }
    int previous(int id) const { return frame_[id] > first_frame_ ? id - samples_ : -1; }
    // p(s, g + 1) - p(s, g), per frame; at the last frame the motion into it.
    const Vec3& motion(int id) const { return motion_[id]; }
    const Vec3& position(int id) const { return position_[id]; }
    const StEntry* entries(int id) const { return entries_.data() + begin_[id]; }
    const int* group_start(int id) const { return starts_.data() + static_cast<size_t>(id) * (max_temporal + 1); }
    // Ids of every usable sample-frame of a type, in id order.
    const std::vector<int>& of_type(int type) const { return of_type_[type]; }
    // Ids at input frame g of a type.
    // Nearest input sample at frame g to p with the given type, as an id; -1 if none
    // within `max_distance`.
    int nearest(int frame, const Vec3& p, int type, double max_distance) const;

    // k-coherence sets (Tong et al. 2002): the ids whose neighbourhoods are most similar.
    const std::vector<int>& similar(int id) const { return similar_[id]; }
    void set_similar(std::vector<std::vector<int>> similar) { similar_ = std::move(similar); }

private:
    void gather(const Animation& exemplar, int id, std::vector<StEntry>& out, int* start) const;

    StParams params_;
    int samples_ = 0, first_frame_ = 0, last_frame_ = 0, frame_count_ = 0;
    std::vector<int> sample_, frame_, type_, begin_, starts_;
    std::vector<Vec3> motion_, position_;
    std::vector<StEntry> entries_;
    std::vector<std::vector<int>> of_type_, similar_;
    std::vector<std::vector<Vec3>> frame_points_;   // positions per frame (the grids' storage)
    std::vector<core::SpatialGrid> grids_;
    std::vector<int> sample_type_;
};

}  // namespace tessera::dynamic
