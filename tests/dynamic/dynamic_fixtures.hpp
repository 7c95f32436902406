// Animated exemplars with a known motion, built in code so that the tests know the truth.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "core/rng.hpp"
#include "tessera/animation.hpp"

namespace dynamic_test {

using tessera::Animation;
using tessera::Vec3;

// A jittered hexagonal lattice (spacing 1) of nx x ny particles translating at `velocity`
// per frame, each particle also circling with radius `wobble` (period 8 frames, own phase).
inline Animation drifting_lattice(int nx, int ny, int frames, Vec3 velocity, double wobble, std::uint64_t seed = 3) {
    const tessera::core::KeyedRng rng(seed, tessera::core::Purpose::test);
    tessera::Exemplar ex;
    ex.dimension = 2;
    const int type = ex.type_index("dot");
    std::vector<Vec3> base;
    std::vector<double> phase;
    std::uint64_t c = 0;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const double jx = rng.uniform(c++), jy = rng.uniform(c++);
            const Vec3 p{i + 0.5 * (j % 2) + 0.08 * (jx - 0.5), j * std::sqrt(3.0) / 2 + 0.08 * (jy - 0.5), 0};
            base.push_back(p);
            phase.push_back(2 * std::numbers::pi * rng.uniform(c++));
            ex.add_element(type, {p});
        }
    for (size_t e = 0; e < ex.elements.size(); ++e) ex.elements[e].id = e;
    ex.domain = tessera::Domain::box({-0.5, -0.5, 0}, {nx + 0.5, ny * std::sqrt(3.0) / 2 + 0.5, 0}, 2);
    Animation a;
    a.structure = ex;
    for (int f = 0; f < frames; ++f) {
        std::vector<Vec3> p(base.size());
        for (size_t s = 0; s < p.size(); ++s) {
            const double w = 2 * std::numbers::pi * f / 8.0 + phase[s];
            p[s] = base[s] + velocity * f + Vec3{wobble * std::cos(w), wobble * std::sin(w), 0};
        }
        a.add_frame(0.1 * f, p);
    }
    for (int s = 0; s < a.sample_count(); ++s) a.structure.samples[s].p = a.at(0, s);
    return a;
}

// A jittered cubic lattice of n^3 balls (spacing 1, each coordinate jittered uniformly by
// +-jitter/2) in the box [-0.5, n - 0.5]^3, element ids 0..n^3-1: a still 3D exemplar.
inline tessera::Exemplar jittered_cubic_lattice(int n, double jitter, std::uint64_t seed = 5) {
    tessera::Exemplar ex;
    ex.dimension = 3;
    const int type = ex.type_index("ball");
    const tessera::core::KeyedRng rng(seed, tessera::core::Purpose::test);
    std::uint64_t c = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                const double jx = rng.uniform(c++), jy = rng.uniform(c++), jz = rng.uniform(c++);
                ex.add_element(type, {{i + jitter * (jx - 0.5), j + jitter * (jy - 0.5), k + jitter * (jz - 0.5)}});
            }
    for (size_t e = 0; e < ex.elements.size(); ++e) ex.elements[e].id = e;
    ex.domain = tessera::Domain::box({-0.5, -0.5, -0.5}, {n - 0.5, n - 0.5, n - 0.5}, 3);
    return ex;
}

}  // namespace dynamic_test
