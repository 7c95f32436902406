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
