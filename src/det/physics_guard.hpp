// det/physics_guard.hpp — the interleaved physics steps of section 5 (Figure 15), kept
// only when they help: a step that would raise the interpenetrating pairs or the
// floating elements of the arrangement is given a few more sub-steps to settle (the
// elements it pushed apart fall back onto their support), and undone if it still
// leaves either count higher than before it. So physics never leaves a scene worse
// than the search and assignment left it; the run's notes say how many were undone.
#pragma once

#include "tessera/domain.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/physics.hpp"

namespace tessera::det {

class PhysicsGuard {
public:
    PhysicsGuard(const PhysicsOptions& options, const Domain& domain) : options_(options), domain_(domain) {}

    // One guarded step on `out`; returns whether it was kept.
    bool step(Arrangement& out);
    // The last step, after the final repair: steps of 1, 2, 4 ... times the sub-steps
    // (cumulative, at most kSettleSteps) until the scene is no worse than `reference` (the
    // measure before the first step) nor than before the settling; undone if none gets
    // there. Returns the number of steps taken, 0 when undone.
    int settle(Arrangement& out, const PhysicsReport& reference);
    // The measure of `out` with the guard's gravity and tolerance.
    PhysicsReport measure(const Arrangement& out) const;

    int steps() const { return steps_; }
    int undone() const { return undone_; }

private:
    PhysicsOptions options_;
    const Domain& domain_;
    int steps_ = 0, undone_ = 0;
};

}  // namespace tessera::det
