// The least-squares assignment of graph synthesis (Eq. 7 over the blended neighbourhoods):
// at a frame every sample s has, for each of its tracks t (a neighbour s'), a predicted
// offset q_t ~ p(s') - p(s). The positions minimising sum_t |p(s') - p(s) - q_t|^2 over
// every sample's tracks are found by Jacobi sweeps, as the dynamic method's assignment: each
// sample moves halfway to the mean of the places its own tracks (p(s') - q_t) and the tracks
// of the neighbours that hold it (p(s) = p(owner) + q_t) give it, the others held where they
// were. Half a step: full Jacobi steps swing a bipartite cluster, such as two samples that
// see only each other, back and forth for ever (seen on two_class_2d: no convergence in 150
// sweeps); damped, every cluster converges.
// Only offsets are predicted, so the solve starts from the previous frame, which fixes the
// free translation; the still's neighbour pairs never change, so their index is built once.
#pragma once

#include <vector>

#include "dynamic/path_blend.hpp"
#include "tessera/domain.hpp"

namespace tessera::dynamic {

class FrameSolver {
public:
    // Indexes the tracks of every sample (tracks[s] for sample s).
    explicit FrameSolver(const std::vector<PathTracks>& tracks);

    // Tracks of all samples laid end to end: sample s owns [first(s), first(s + 1)).
    int first(int s) const { return first_[s]; }
    int track_count() const { return first_.back(); }

    // Moves `positions` towards the least-squares fit of `predicted` (one offset per track,
    // in first() order) by at most `sweeps` Jacobi sweeps, keeping samples in `domain`; stops
    // once no sample moves more than `tolerance`. Returns the sweeps made, or -1 when the
    // bound was hit with samples still moving.
    int solve(const std::vector<Vec3>& predicted, std::vector<Vec3>& positions, const Domain& domain, int sweeps,
              double tolerance, int threads) const;

private:
    std::vector<int> first_, neighbour_;
    // Per sample, the tracks (global indices) of other samples that follow it, and their owners.
    std::vector<int> held_first_, held_track_, owner_;
};

}  // namespace tessera::dynamic
