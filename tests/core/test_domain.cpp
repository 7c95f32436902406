#include <gtest/gtest.h>

#include "tessera/domain.hpp"
#include "tessera/error.hpp"

using namespace tessera;

TEST(Domain, RejectsZeroAndNegativeExtent) {
    EXPECT_THROW(Domain::box({0, 0, 0}, {0, 1, 0}, 2), Error);
    EXPECT_THROW(Domain::box({0, 0, 0}, {-1, 1, 0}, 2), Error);
    EXPECT_THROW(Domain::box({0, 0, 0}, {1, 1, 0}, 3), Error);
    EXPECT_NO_THROW(Domain::box({0, 0, 0}, {1, 1, 0}, 2));
}

TEST(Domain, TranslatedOverlapOfABox) {
    const Domain d = Domain::box({0, 0, 0}, {2, 3, 0}, 2);
    EXPECT_DOUBLE_EQ(d.measure(), 6.0);
    EXPECT_DOUBLE_EQ(d.translated_overlap({0.5, -1, 0}), 1.5 * 2.0);
    EXPECT_DOUBLE_EQ(d.translated_overlap({3, 0, 0}), 0.0);
}

TEST(Domain, ScaledKeepsLowerCorner) {
    const Domain d = Domain::box({1, 2, 3}, {2, 4, 5}, 3).scaled(3.0);
    EXPECT_EQ(d.bounds().lo, Vec3(1, 2, 3));
    EXPECT_EQ(d.bounds().hi, Vec3(4, 8, 9));
}

#include "core/spatial_grid.hpp"

TEST(SpatialGrid, FarAwayPointCoarsensInsteadOfOverflowing) {
    std::vector<Vec3> pts = {{0, 0, 0}, {0.5, 0, 0}, {1e16, 3e15, 0}};
    core::SpatialGrid grid;
    grid.build(pts, 0.1, 2);
    int found = 0;
    grid.for_each_within({0, 0, 0}, 1.0, [&](int, double) { ++found; });
    EXPECT_EQ(found, 2);
    EXPECT_EQ(grid.nearest({1e16, 3e15, 0}, 1e17, [](int) { return true; }), 2);
}
