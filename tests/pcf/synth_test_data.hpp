// Exemplars for the synthesis tests.
#pragma once

#include <algorithm>
#include <vector>

#include "core/rng.hpp"
#include "tessera/exemplar.hpp"

namespace tessera::test {

// A hard-core (Poisson-disk) point set by dart throwing: up to n points at least
// `min_distance` apart in the box [0, size]^2.
inline Exemplar poisson_disk(int n, double size, double min_distance, std::uint64_t seed, double radius = 0.0) {
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {size, size, 0}, 2);
    ex.type_index("dot");
    const core::KeyedRng rng(seed, core::Purpose::test);
    std::vector<Vec3> points;
    for (std::uint64_t a = 0; a < 200000 && static_cast<int>(points.size()) < n; ++a) {
        const Vec3 p{size * rng.uniform(2 * a), size * rng.uniform(2 * a + 1), 0.0};
        const bool free = std::all_of(points.begin(), points.end(),
                                      [&](const Vec3& q) { return norm(p - q) >= min_distance; });
        if (free) points.push_back(p);
    }
    for (const Vec3& p : points) ex.add_element(0, {p}, radius);
    return ex;
}

}  // namespace tessera::test
