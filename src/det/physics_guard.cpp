// det/physics_guard.cpp — guarded interleaved physics (physics_guard.hpp).
#include "det/physics_guard.hpp"

#include <algorithm>
#include <vector>

namespace tessera::det {
namespace {

constexpr int kSettleRounds = 1;  // extra step_physics calls a step may take to settle
constexpr int kSettleSteps = 5;   // final settling: steps of 1, 2, 4, 8, 16 times the sub-steps

bool worse(const PhysicsReport& after, const PhysicsReport& before) {
    return after.interpenetrating_pairs > before.interpenetrating_pairs || after.floating > before.floating;
}

bool better(const PhysicsReport& after, const PhysicsReport& before) {
    return !worse(after, before) &&
           (after.interpenetrating_pairs < before.interpenetrating_pairs || after.floating < before.floating);
}

// The element-wise best of two measures: what a result must not exceed to beat both.
PhysicsReport lower(const PhysicsReport& a, const PhysicsReport& b) {
    PhysicsReport r = a;
    r.interpenetrating_pairs = std::min(a.interpenetrating_pairs, b.interpenetrating_pairs);
    r.floating = std::min(a.floating, b.floating);
    return r;
}

}  // namespace

PhysicsReport PhysicsGuard::measure(const Arrangement& out) const {
    return measure_physics(out, domain_, options_.gravity, options_.tolerance);
}

bool PhysicsGuard::step(Arrangement& out) {
    ++steps_;
    const PhysicsReport before = measure(out);
    // step_physics moves samples, positions and orientations only.
    const std::vector<Element> elements = out.elements;
    const std::vector<Sample> samples = out.samples;
    PhysicsReport after = step_physics(out, domain_, options_);
    for (int round = 0; round < kSettleRounds && worse(after, before); ++round) after = step_physics(out, domain_, options_);
    if (!worse(after, before)) return true;
    out.elements = elements;
    out.samples = samples;
    ++undone_;
    return false;
}

int PhysicsGuard::settle(Arrangement& out, const PhysicsReport& reference) {
    PhysicsReport current = measure(out);
    const PhysicsReport bound = lower(current, reference);
    std::vector<Element> kept_elements = out.elements;
    std::vector<Sample> kept_samples = out.samples;
    PhysicsReport kept = current;
    bool kept_meets_bound = !worse(current, bound);
    int kept_steps = 0;
    PhysicsOptions longer = options_;
    for (int s = 0; s < kSettleSteps; ++s, longer.substeps *= 2) {
        ++steps_;
        current = step_physics(out, domain_, longer);
        // Keep a step that improves on the last kept state, or that first meets the bound.
        const bool meets = !worse(current, bound);
        if ((meets && !kept_meets_bound) || (meets && better(current, kept))) {
            kept_elements = out.elements, kept_samples = out.samples, kept = current;
            kept_meets_bound = true;
            kept_steps = s + 1;
        } else if (kept_meets_bound) {
            break;  // settled: a longer step no longer helps
        }
    }
    out.elements = std::move(kept_elements);
    out.samples = std::move(kept_samples);
    if (kept_steps == 0) ++undone_;
    return kept_steps;
}

}  // namespace tessera::det
