// Tests of nearest_neighbor_distances: exact values on a small layout,
// translation invariance, and the fewer-than-two-elements convention.
#include <gtest/gtest.h>

#include <cmath>

#include "metrics/field_data.hpp"
#include "tessera/metrics.hpp"

using namespace tessera;

TEST(MetricsNearestNeighbors, ExactOnASmallLayout) {
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    const int t = ex.type_index("a"), u = ex.type_index("b");
    ex.add_element(t, {Vec3{1, 1, 0}});
    ex.add_element(u, {Vec3{1, 2, 0}});   // nearest of element 0, of another class
    ex.add_element(t, {Vec3{4, 6, 0}});   // nearest is element 1 at distance 5
    const auto s = nearest_neighbor_distances(ex);
    ASSERT_EQ(s.distances.size(), 3u);
    EXPECT_DOUBLE_EQ(s.distances[0], 1.0);
    EXPECT_DOUBLE_EQ(s.distances[1], 1.0);
    EXPECT_DOUBLE_EQ(s.distances[2], 5.0);
    EXPECT_DOUBLE_EQ(s.mean, 7.0 / 3.0);
    EXPECT_DOUBLE_EQ(s.min, 1.0);
    EXPECT_DOUBLE_EQ(s.max, 5.0);
    EXPECT_NEAR(s.stddev, std::sqrt((2 * (4.0 / 3) * (4.0 / 3) + (8.0 / 3) * (8.0 / 3)) / 3.0), 1e-12);
}

TEST(MetricsNearestNeighbors, TranslationInvariant) {
    const Exemplar ex = test::load_field_pattern("swedishpines");
    Exemplar moved = ex;
    const Vec3 shift{-1000.5, 250.25, 0.0};
    for (auto& e : moved.elements) e.position += shift;
    moved.domain = Domain::box(ex.domain.bounds().lo + shift, ex.domain.bounds().hi + shift, 2);
    const auto a = nearest_neighbor_distances(ex), b = nearest_neighbor_distances(moved);
    ASSERT_EQ(a.distances.size(), b.distances.size());
    for (size_t i = 0; i < a.distances.size(); ++i) EXPECT_NEAR(a.distances[i], b.distances[i], 1e-9);
    EXPECT_NEAR(a.mean, b.mean, 1e-9);
    EXPECT_NEAR(a.stddev, b.stddev, 1e-9);
}

TEST(MetricsNearestNeighbors, ThreeDimensions) {
    Exemplar ex;
    ex.dimension = 3;
    ex.domain = Domain::box({0, 0, 0}, {5, 5, 5}, 3);
    const int t = ex.type_index("a");
    ex.add_element(t, {Vec3{1, 1, 1}});
    ex.add_element(t, {Vec3{1, 1, 3}});
    ex.add_element(t, {Vec3{4, 4, 4}});
    const auto s = nearest_neighbor_distances(ex);
    EXPECT_DOUBLE_EQ(s.distances[0], 2.0);
    EXPECT_DOUBLE_EQ(s.distances[2], std::sqrt(9.0 + 9.0 + 1.0));
}

TEST(MetricsNearestNeighbors, SingleElementHasNoNeighbour) {
    Exemplar ex;
    ex.add_element(ex.type_index("a"), {Vec3{0.5, 0.5, 0}});
    const auto s = nearest_neighbor_distances(ex);
    ASSERT_EQ(s.distances.size(), 1u);
    EXPECT_TRUE(std::isinf(s.distances[0]));
    EXPECT_EQ(s.mean, 0.0);
}
