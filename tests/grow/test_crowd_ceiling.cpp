// The count ceiling of growth (src/grow/crowd_ceiling.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "grow/crowd_ceiling.hpp"
#include "quality_data.hpp"

namespace tessera {
namespace {

// A jittered square lattice of n x n points in [0, n]^2: regular at every scale.
Exemplar lattice(int n) {
    Exemplar ex;
    ex.dimension = 2;
    ex.types.resize(1);
    ex.types[0].name = "dot";
    ex.domain = Domain::box({0, 0, 0}, {double(n), double(n), 0}, 2);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            ex.add_element(0, {Vec3{i + 0.5 + 0.1 * std::sin(7.0 * i + j), j + 0.5 + 0.1 * std::cos(3.0 * j + i), 0}});
    return ex;
}

TEST(CrowdCeiling, ARegularPatternGetsACeilingNearItsMeanCount) {
    const Exemplar ex = lattice(30);
    const grow::CrowdCeiling c = grow::exemplar_crowd_ceiling(ex, 1.0);
    ASSERT_TRUE(c.active());
    EXPECT_DOUBLE_EQ(c.radius, 4.0);
    const double mean = M_PI * 16.0;  // one point per unit area
    EXPECT_GT(c.limit, 0.95 * mean);
    EXPECT_LT(c.limit, 1.1 * mean);
    EXPECT_TRUE(c.allows(static_cast<int>(std::floor(c.limit))));
    EXPECT_FALSE(c.allows(static_cast<int>(std::floor(c.limit)) + 1));
}

TEST(CrowdCeiling, ARandomOrClusteredPatternGetsNone) {
    // Japanese pines: counts vary more than a Poisson pattern's.
    const Exemplar ex = test::field_pattern("japanesepines");
    EXPECT_FALSE(grow::exemplar_crowd_ceiling(ex, ex.elements.size() / ex.domain.measure()).active());
}

TEST(CrowdCeiling, MultiSampleOrTinyExemplarsGetNone) {
    Exemplar ex = lattice(2);  // four points: too few counted
    EXPECT_FALSE(grow::exemplar_crowd_ceiling(ex, 1.0).active());
    Exemplar sticks = lattice(20);
    sticks.add_element(0, {Vec3{1, 1, 0}, Vec3{1.2, 1, 0}});
    EXPECT_FALSE(grow::exemplar_crowd_ceiling(sticks, 1.0).active());
}

}  // namespace
}  // namespace tessera
