// The output animation while it is made frame by frame: the finished frames (fixed: the
// neighbourhoods are temporal-causal), the frame being optimised, the flow displacement each
// sample has accumulated (so that neighbourhoods compare the detail motion, the output's
// motion less the global flow, with the exemplar's), and each sample's current matches.
#pragma once

#include <vector>

#include "core/spatial_grid.hpp"
#include "dynamic/st_neighbourhood.hpp"

namespace tessera::dynamic {

// What one search leaves for the assignment: per sample, pairs (a neighbour s' in group k
// paired with an input entry) that predict the sample's position, with their weights.
struct Prediction {
    int sample = -1;   // s'
    int group = 0;     // k
    // Where the pair puts s, relative to where s is: (p(s') - p(s)) - (p(s'_i) - p(s_i)),
    // the output entry's offset less its partner's (Eq. 6). The neighbour s' sees the same
    // pair from its side as the opposite displacement. Offsets, not positions, so that a
    // neighbour seen through the periodic border (wrap) predicts the right place.
    Vec3 displacement;
    double weight = 0; // omega_j (Eq. 12) x the pair's falloff (Eq. 9)
};

// The periodic box of a wrapped domain: neighbourhoods see across its faces.
struct Periodic {
    bool on = false;
    Vec3 lo, extent;
};

// The points a frame's grid holds: the samples' positions, then with wrap their copies
// shifted by one period along each axis (and each pair of axes, for the corners) wherever a
// copy falls within `radius` of the box; sample[i] = the sample point i stands for.
struct PeriodicImages {
    std::vector<Vec3> points;
    std::vector<int> sample;
    void build(const Vec3* positions, int n, const Periodic& periodic, double radius, int dimension);
};

class OutputFrames {
public:
    OutputFrames(int dimension, std::vector<int> sample_types, int matches, const StParams& params,
                 Periodic periodic = {});

    int size() const { return static_cast<int>(type_.size()); }
    int frame() const { return frames_done_; }   // the frame being made
    int type(int s) const { return type_[s]; }
    int matches() const { return matches_; }

    // The frame being made.
    std::vector<Vec3>& current() { return current_; }
    const std::vector<Vec3>& current() const { return current_; }
    std::vector<Vec3>& current_shift() { return current_shift_; }
    // Sample s as it stood k frames back, moved on by the flow since (k = 0: its current place).
    Vec3 position(int s, int k) const {
        if (k == 0) return current_[s];
        const size_t i = static_cast<size_t>(frames_done_ - k) * type_.size() + s;
        return past_[i] + (current_shift_[s] - past_shift_[i]);
    }
    const Vec3& past(int frame, int s) const { return past_[static_cast<size_t>(frame) * type_.size() + s]; }
    const Vec3& past_shift(int frame, int s) const { return past_shift_[static_cast<size_t>(frame) * type_.size() + s]; }

    // Rebuilds the grids over the current positions and (full shape) the advanced past ones.
    void index();
    // Gathers the neighbourhood of s in the frame being made (groups: min(T, frame + 1)).
    void gather(int s, StNeighbourhood& out) const;
    // Calls fn(s') for each sample within `radius` of s at the current frame (not s), through
    // the periodic border too.
    template <class Fn>
    void for_each_neighbour(int s, double radius, Fn&& fn) const {
        grids_[0].for_each_within(current_[s], radius, [&](int i, double) {
            const int o = images_[0].sample[i];
            if (o != s) fn(o);
        });
    }

    // Stores the frame being made as finished and starts the next one at the same positions.
    void commit();

    // Matches of the last search: ids into InputFrames, best first; -1 = none.
    // A search reads the matches as they stood before it (prior_match: its neighbours' are
    // being rewritten by other threads) and writes match().
    void snapshot_matches() { prior_match_ = match_; }
    const int* prior_match(int s) const { return prior_match_.data() + static_cast<size_t>(s) * matches_; }
    int* match(int s) { return match_.data() + static_cast<size_t>(s) * matches_; }
    const int* match(int s) const { return match_.data() + static_cast<size_t>(s) * matches_; }
    double* distance(int s) { return distance_.data() + static_cast<size_t>(s) * matches_; }
    const double* distance(int s) const { return distance_.data() + static_cast<size_t>(s) * matches_; }
    double* omega(int s) { return omega_.data() + static_cast<size_t>(s) * matches_; }
    const double* omega(int s) const { return omega_.data() + static_cast<size_t>(s) * matches_; }

    Prediction* predictions(int s) { return predictions_.data() + static_cast<size_t>(s) * prediction_stride_; }
    const Prediction* predictions(int s) const { return predictions_.data() + static_cast<size_t>(s) * prediction_stride_; }
    int& prediction_count(int s) { return prediction_count_[s]; }
    int prediction_count(int s) const { return prediction_count_[s]; }
    int prediction_stride() const { return prediction_stride_; }

private:
    StParams params_;
    int matches_ = 1, frames_done_ = 0, prediction_stride_ = 0;
    std::vector<int> type_;
    std::vector<Vec3> current_, current_shift_, past_, past_shift_;
    // Per group k: the points its grid holds (the samples' positions, advanced past ones for
    // k >= 1, with their periodic images) and their samples.
    void build_images(int k, const std::vector<Vec3>& positions);
    Periodic periodic_;
    std::vector<PeriodicImages> images_;
    std::vector<core::SpatialGrid> grids_;      // per k, over images_[k].points
    std::vector<int> match_, prior_match_;
    std::vector<double> distance_, omega_;
    std::vector<Prediction> predictions_;
    std::vector<int> prediction_count_;
};

}  // namespace tessera::dynamic
