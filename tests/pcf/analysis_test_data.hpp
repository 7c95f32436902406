// Patterns for the PCF analysis tests: uniform random (Poisson) points, Poisson-disk
// points by dart throwing, and small hand-made exemplars with chosen classes and
// dependencies. Deterministic (counter-based random numbers).
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "tessera/exemplar.hpp"

namespace tessera::test {

// n uniform points of class `name` in [0, side]^2.
inline Exemplar poisson_points(int n, double side, std::uint64_t seed, const std::string& name = "p") {
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {side, side, 0}, 2);
    const int t = ex.type_index(name);
    const core::KeyedRng rng(seed, core::Purpose::test);
    for (int i = 0; i < n; ++i) ex.add_element(t, {Vec3{side * rng.uniform(2 * i), side * rng.uniform(2 * i + 1), 0}});
    return ex;
}

// Dart throwing: up to n points in [0, side]^2 at least `hard_core` apart, given radius.
inline void add_poisson_disk(Exemplar& ex, int type, int n, double side, double hard_core, std::uint64_t seed,
                             double radius = 0.0) {
    const core::KeyedRng rng(seed, core::Purpose::test);
    std::vector<Vec3> placed;
    for (std::uint64_t draw = 0; static_cast<int>(placed.size()) < n && draw < 400ull * n; ++draw) {
        const Vec3 p{side * rng.uniform(2 * draw), side * rng.uniform(2 * draw + 1), 0};
        bool ok = true;
        for (const Vec3& q : placed) ok = ok && (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y) >= hard_core * hard_core;
        if (ok) placed.push_back(p);
    }
    for (const Vec3& p : placed) ex.add_element(type, {p}, radius);
}

// Three classes a, b, c of uniform points (10 each by default) in a 10 x 10 box, with
// optional depends_on per class.
inline Exemplar three_classes(const std::vector<std::optional<std::vector<std::string>>>& deps = {},
                              const std::vector<int>& counts = {10, 10, 10}) {
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    const char* names[] = {"a", "b", "c"};
    const core::KeyedRng rng(7, core::Purpose::test);
    std::uint64_t draw = 0;
    for (int c = 0; c < 3; ++c) {
        const int t = ex.type_index(names[c]);
        if (c < static_cast<int>(deps.size())) ex.types[t].depends_on = deps[c];
        for (int i = 0; i < counts[c]; ++i, draw += 2)
            ex.add_element(t, {Vec3{10 * rng.uniform(draw), 10 * rng.uniform(draw + 1), 0}});
    }
    return ex;
}

}  // namespace tessera::test
