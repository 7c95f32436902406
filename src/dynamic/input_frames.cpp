// dynamic/input_frames.cpp — the exemplar's sample-frames, their neighbourhoods and grids.
#include "dynamic/input_frames.hpp"

#include <algorithm>
#include <cmath>

#include "core/parallel.hpp"

namespace tessera::dynamic {

void finish_group(std::vector<StEntry>& entries, int begin) {
    const auto first = entries.begin() + begin;
    std::sort(first, entries.end(), [](const StEntry& a, const StEntry& b) {
        const double da = squared_norm(a.offset), db = squared_norm(b.offset);
        return da != db ? da < db : a.sample < b.sample;
    });
    if (entries.end() - first > max_group) entries.erase(first + max_group, entries.end());
}

InputFrames::InputFrames(const Animation& exemplar, const StParams& params, int threads)
    : params_(params),
      samples_(exemplar.sample_count()),
      first_frame_(params.temporal - 1 - params.ahead),
      last_frame_(exemplar.frame_count() - 1 - params.ahead),
      frame_count_(exemplar.frame_count()) {
    const Exemplar& ex = exemplar.structure;
    sample_type_.resize(samples_);
    for (int s = 0; s < samples_; ++s) sample_type_[s] = ex.elements[ex.samples[s].element].type;
    frame_points_.resize(frame_count_);
    grids_.resize(frame_count_);
    for (int g = 0; g < frame_count_; ++g) {
        frame_points_[g].assign(exemplar.positions.begin() + static_cast<long>(g) * samples_,
                                exemplar.positions.begin() + static_cast<long>(g + 1) * samples_);
        grids_[g].build(frame_points_[g], params.input_radius, params.dimension);
    }
    const int usable = std::max(0, last_frame_ + 1 - first_frame_) * samples_;
    sample_.resize(usable), frame_.resize(usable), type_.resize(usable);
    motion_.resize(usable), position_.resize(usable);
    of_type_.assign(ex.types.size(), {});
    similar_.assign(usable, {});
    for (int id = 0; id < usable; ++id) {
        sample_[id] = id % samples_;
        frame_[id] = first_frame_ + id / samples_;
        type_[id] = sample_type_[sample_[id]];
        position_[id] = exemplar.at(frame_[id], sample_[id]);
        const int g = frame_[id], s = sample_[id];
        motion_[id] = g + 1 < frame_count_ ? exemplar.at(g + 1, s) - exemplar.at(g, s)
                      : g > 0              ? exemplar.at(g, s) - exemplar.at(g - 1, s)
                                           : Vec3{};
        of_type_[type_[id]].push_back(id);
    }
    // Neighbourhoods gathered in parallel into per-id buffers, then laid out flat in id order.
    std::vector<std::vector<StEntry>> gathered(usable);
    starts_.assign(static_cast<size_t>(usable) * (max_temporal + 1), 0);
    core::parallel_for(usable, threads, [&](int begin, int end, int) {
        for (int id = begin; id < end; ++id)
            gather(exemplar, id, gathered[id], starts_.data() + static_cast<size_t>(id) * (max_temporal + 1));
    });
    begin_.resize(usable + 1);
    begin_[0] = 0;
    for (int id = 0; id < usable; ++id) begin_[id + 1] = begin_[id] + static_cast<int>(gathered[id].size());
    entries_.reserve(begin_[usable]);
    for (auto& g : gathered) entries_.insert(entries_.end(), g.begin(), g.end());
}

// Group k: the samples within input_radius of the centre at frame g + time_offset(k) (full
// shape), or group 0 so and the centre's own sample at that frame for k >= 1 (compact shape).
void InputFrames::gather(const Animation& exemplar, int id, std::vector<StEntry>& out, int* start) const {
    const int s = sample_[id], g = frame_[id];
    const Vec3 centre = exemplar.at(g, s);
    for (int k = 0; k < params_.temporal; ++k) {
        start[k] = static_cast<int>(out.size());
        const int dt = time_offset(k, params_), frame = g + dt;
        if (k > 0 && params_.shape == NeighbourhoodShape::compact) {
            const Vec3 d = exemplar.at(frame, s) - centre;
            out.push_back({d, falloff(d, dt, params_), sample_type_[s], s});
            continue;
        }
        grids_[frame].for_each_within(centre, params_.input_radius, [&](int other, double) {
            if (k == 0 && other == s) return;
            const Vec3 d = exemplar.at(frame, other) - centre;
            out.push_back({d, falloff(d, dt, params_), sample_type_[other], other});
        });
        finish_group(out, start[k]);
    }
    for (int k = params_.temporal; k <= max_temporal; ++k) start[k] = static_cast<int>(out.size());
}

int InputFrames::nearest(int frame, const Vec3& p, int type, double max_distance) const {
    if (frame < first_frame_ || frame > last_frame_) return -1;
    const int s = grids_[frame].nearest(p, max_distance, [&](int i) { return sample_type_[i] == type; });
    return s < 0 ? -1 : id(s, frame);
}

}  // namespace tessera::dynamic
