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
    const PhysicsReport bound = lower(measure(out), reference);
    const std::vector<Element> elements = out.elements;
    const std::vector<Sample> samples = out.samples;
    PhysicsOptions longer = options_;
    // The first step that meets the bound is kept and settling ends there: longer steps
    // pack the elements ever closer than the exemplar spaces them.
    for (int s = 0; s < kSettleSteps; ++s, longer.substeps *= 2) {
        ++steps_;
        if (!worse(step_physics(out, domain_, longer), bound)) return s + 1;
    }
    out.elements = elements;
    out.samples = samples;
    ++undone_;
    return 0;
}

}  // namespace tessera::det
