// Checks the dynamic tests share: the velocity statistics of an animation, and that every
// frame of an output keeps a lattice exemplar's arrangement (PCF, closest pair, hexatic
// order) inside its box.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <vector>

#include "tessera/animation.hpp"
#include "tessera/metrics.hpp"

namespace dynamic_test {

struct MotionStats {
    tessera::Vec3 mean;
    double speed_sd = 0.0, largest_step = 0.0;
};

// Per-frame velocities of every sample between frames [from, to).
inline MotionStats motion_stats(const tessera::Animation& a, int from, int to) {
    std::vector<tessera::Vec3> v;
    for (int f = std::max(from, 1); f < to; ++f)
        for (int s = 0; s < a.sample_count(); ++s) v.push_back(a.at(f, s) - a.at(f - 1, s));
    MotionStats m;
    for (const tessera::Vec3& x : v) m.mean += x;
    m.mean = m.mean / static_cast<double>(v.size());
    double var = 0.0;
    for (const tessera::Vec3& x : v)
        var += tessera::squared_norm(x - m.mean), m.largest_step = std::max(m.largest_step, tessera::norm(x));
    m.speed_sd = std::sqrt(var / static_cast<double>(v.size()));
    return m;
}

inline double closest_pair(const tessera::Exemplar& frame) {
    return tessera::nearest_neighbor_distances(frame, 1).min;
}

// Frames `frames` of `out` against the exemplar's frame 2: PCF error under max(0.2, twice
// the first frame's), closest pair above 0.6 of the exemplar's, |psi6| above 0.6, every
// particle inside `box`.
inline void expect_lattice_kept(const tessera::Animation& exemplar, const tessera::Animation& out,
                                std::initializer_list<int> frames, const tessera::Domain& box) {
    const tessera::Exemplar in_frame = exemplar.frame(2);
    const double static_error = tessera::pcf_relative_error(in_frame, out.frame(0));
    for (int f : frames) {
        const tessera::Exemplar frame = out.frame(f);
        EXPECT_LT(tessera::pcf_relative_error(in_frame, frame), std::max(0.2, 2.0 * static_error)) << "frame " << f;
        EXPECT_GT(closest_pair(frame), 0.6 * closest_pair(in_frame)) << "frame " << f;
        EXPECT_GT(tessera::mean_psi6(frame), 0.6) << "frame " << f;
        for (const tessera::Sample& s : frame.samples) EXPECT_TRUE(box.inside(s.p));
    }
}

}  // namespace dynamic_test
