// Animations with a known motion for the tests of the motion analysis (decompose_motion,
// recombine_motion): lattices, threads and sheets whose positions are given by a formula, so
// that the tests know what is coarse and what is detail.
#pragma once

#include <algorithm>
#include <functional>
#include <vector>

#include "tessera/animation.hpp"

namespace motion_test {

using tessera::Animation;
using tessera::Vec3;

// Sample position of (element, sample id, frame).
using Motion = std::function<Vec3(int element, int sample, int frame)>;

// `count` elements of type `type_name` with `samples` samples each (topology given; a sheet
// has `columns` columns), placed by `motion` in `frames` frames 0.1 apart, in `domain`.
inline Animation animation_of(const std::string& type_name, tessera::ElementTopology topology, int columns,
                              int count, int samples, int frames, const Motion& motion,
                              const tessera::Domain& domain) {
    tessera::Exemplar ex;
    ex.dimension = domain.dimension();
    const int type = ex.type_index(type_name);
    ex.types[type].topology = topology;
    ex.types[type].sheet_columns = columns;
    for (int e = 0; e < count; ++e) {
        std::vector<Vec3> p;
        for (int k = 0; k < samples; ++k) p.push_back(motion(e, k, 0));
        ex.add_element(type, p);
        ex.elements.back().id = static_cast<std::uint64_t>(e);
    }
    ex.update_positions();
    ex.domain = domain;
    Animation a;
    a.structure = ex;
    for (int f = 0; f < frames; ++f) {
        std::vector<Vec3> p;
        for (int e = 0; e < count; ++e)
            for (int k = 0; k < samples; ++k) p.push_back(motion(e, k, f));
        a.add_frame(0.1 * f, p);
    }
    a.validate("test animation");
    return a;
}

// A square lattice (spacing 1) of nx x ny particles at (i + 0.5, j + 0.5) in the box
// [0, nx] x [0, ny], translated by `velocity` per frame: a rigid motion at constant velocity.
inline Animation translating_lattice(int nx, int ny, int frames, Vec3 velocity) {
    return animation_of(
        "dot", tessera::ElementTopology::none, 0, nx * ny, 1, frames,
        [=](int e, int, int f) {
            return Vec3{e % nx + 0.5, e / nx + 0.5, 0} + velocity * f;
        },
        tessera::Domain::box({0, 0, 0}, {double(nx), double(ny), 0}, 2));
}

// Elements of `b` appended to `a` (same dimension and domain): a mixed animation.
inline Animation merged(const Animation& a, const Animation& b) {
    Animation out = a;
    tessera::Exemplar& ex = out.structure;
    std::vector<int> type_of(b.structure.types.size());
    for (size_t t = 0; t < b.structure.types.size(); ++t) {
        type_of[t] = static_cast<int>(ex.types.size());
        ex.types.push_back(b.structure.types[t]);
    }
    const int first_id = static_cast<int>(ex.elements.size());
    for (const tessera::Element& e : b.structure.elements) {
        std::vector<Vec3> p;
        for (int k = 0; k < e.sample_count; ++k) p.push_back(b.structure.samples[e.first_sample + k].p);
        ex.add_element(type_of[e.type], p);
        ex.elements.back().id = static_cast<std::uint64_t>(first_id) + e.id;
    }
    out.positions.clear();
    for (int f = 0; f < a.frame_count(); ++f) {
        for (int s = 0; s < a.sample_count(); ++s) out.positions.push_back(a.at(f, s));
        for (int s = 0; s < b.sample_count(); ++s) out.positions.push_back(b.at(f, s));
    }
    out.validate("merged test animation");
    return out;
}

inline double max_norm(const std::vector<Vec3>& v) {
    double m = 0.0;
    for (const Vec3& p : v) m = std::max(m, tessera::norm(p));
    return m;
}

inline double max_difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    double m = 0.0;
    for (size_t i = 0; i < a.size(); ++i) m = std::max(m, tessera::norm(a[i] - b[i]));
    return m;
}

}  // namespace motion_test
