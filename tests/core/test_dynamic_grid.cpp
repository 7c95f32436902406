// The dynamic grid (core/dynamic_grid.hpp): queries after any sequence of inserts, moves and
// removes, anywhere (negative coordinates and block borders included), return exactly the
// points a brute-force scan finds.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "core/dynamic_grid.hpp"
#include "core/rng.hpp"

using namespace tessera;

namespace {

std::vector<int> brute_force(const std::vector<Vec3>& p, const std::vector<char>& present, const Vec3& c, double r,
                             int dimension) {
    std::vector<int> ids;
    for (size_t i = 0; i < p.size(); ++i) {
        if (!present[i]) continue;
        Vec3 d = p[i] - c;
        if (dimension == 2) d.z = 0.0;
        if (dot(d, d) <= r * r) ids.push_back(static_cast<int>(i));
    }
    return ids;
}

void check_against_brute_force(int dimension) {
    const core::KeyedRng rng(7, core::Purpose::test);
    std::uint64_t k = 0;
    auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * rng.uniform(k++); };
    auto point = [&] { return Vec3{uniform(-40, 40), uniform(-40, 40), dimension == 3 ? uniform(-40, 40) : 0.0}; };
    core::DynamicGrid grid(0.7, dimension);
    std::vector<Vec3> p;
    std::vector<char> present;
    for (int i = 0; i < 3000; ++i) {
        p.push_back(point());
        present.push_back(1);
        grid.insert(i, p.back());
    }
    for (int step = 0; step < 4000; ++step) {
        const int i = static_cast<int>(uniform(0, static_cast<double>(p.size()) - 1e-9));
        if (step % 3 == 0 && present[i]) {
            grid.remove(i);
            present[i] = 0;
        } else if (present[i]) {
            p[i] = p[i] + Vec3{uniform(-2, 2), uniform(-2, 2), dimension == 3 ? uniform(-2, 2) : 0.0};
            grid.move(i, p[i]);
        } else {
            p[i] = point();
            present[i] = 1;
            grid.insert(i, p[i]);
        }
    }
    std::vector<int> found;
    for (int q = 0; q < 300; ++q) {
        const Vec3 c = point();
        const double r = uniform(0.0, 9.0);
        grid.query(c, r, [&](int i) { return p[i]; }, found);
        ASSERT_EQ(found, brute_force(p, present, c, r, dimension)) << "query " << q;
        std::vector<int> visited;
        grid.for_each_within(c, r, [&](int i) { return p[i]; }, [&](int i) { visited.push_back(i); });
        std::sort(visited.begin(), visited.end());
        ASSERT_EQ(visited, found) << "query " << q;
    }
    EXPECT_EQ(grid.size(), static_cast<size_t>(std::count(present.begin(), present.end(), 1)));
}

}  // namespace

TEST(DynamicGrid, QueriesMatchBruteForceAfterInsertsMovesAndRemoves2D) { check_against_brute_force(2); }

TEST(DynamicGrid, QueriesMatchBruteForceAfterInsertsMovesAndRemoves3D) { check_against_brute_force(3); }
