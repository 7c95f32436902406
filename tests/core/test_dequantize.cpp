// Rounded exemplars (core/dequantize.hpp): the rounding step is found, a pattern's own
// lattice is not taken for rounding, and the copy moves each element within its rounding
// cell without bringing any pair closer than the data's closest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/dequantize.hpp"
#include "core/rng.hpp"
#include "quality_data.hpp"

using namespace tessera;

namespace {

// n points in the unit square, drawn uniformly and rounded to `q` (0: not rounded).
Exemplar rounded_points(int n, double q, std::uint64_t seed) {
    Exemplar ex;
    ex.dimension = 2;
    ex.domain = Domain::box({0, 0, 0}, {1, 1, 0}, 2);
    ex.type_index("dot");
    const core::KeyedRng rng(seed, core::Purpose::test);
    auto round_to = [&](double v) { return q > 0.0 ? std::round(v / q) * q : v; };
    for (int i = 0; i < n; ++i)
        ex.add_element(0, {Vec3{round_to(rng.uniform(2 * i)), round_to(rng.uniform(2 * i + 1)), 0}});
    return ex;
}

double closest_pair(const Exemplar& ex) {
    double d = 1e300;
    for (size_t i = 0; i < ex.elements.size(); ++i)
        for (size_t j = i + 1; j < ex.elements.size(); ++j)
            d = std::min(d, norm(ex.elements[i].position - ex.elements[j].position));
    return d;
}

}  // namespace

TEST(Dequantize, FindsTheRoundingStepOfRecordedData) {
    EXPECT_DOUBLE_EQ(core::coordinate_resolution(rounded_points(60, 0.01, 1)), 0.01);
    EXPECT_DOUBLE_EQ(core::coordinate_resolution(rounded_points(60, 0.02, 2)), 0.02);
    EXPECT_DOUBLE_EQ(core::coordinate_resolution(rounded_points(60, 0.0, 3)), 0.0);
    // The field data: Japanese pines to 0.01 of their window, Swedish pines to whole units.
    EXPECT_DOUBLE_EQ(core::coordinate_resolution(test::field_pattern("japanesepines")), 0.01);
    EXPECT_DOUBLE_EQ(core::coordinate_resolution(test::field_pattern("swedishpines")), 1.0);
}

TEST(Dequantize, ALatticeAtWholeCoordinatesIsThePatternNotRounding) {
    Exemplar lattice = rounded_points(0, 0.0, 1);
    lattice.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j) lattice.add_element(0, {Vec3{i + 0.0, j + 0.0, 0}});
    const double spacing = mean_nearest_neighbor_distance(lattice);
    EXPECT_DOUBLE_EQ(core::coordinate_resolution(lattice), 1.0);
    EXPECT_FALSE(core::is_rounded(1.0, spacing));
    const Exemplar same = core::dequantized(lattice, spacing, 7);
    for (size_t i = 0; i < lattice.elements.size(); ++i)
        EXPECT_EQ(same.elements[i].position, lattice.elements[i].position);
}

TEST(Dequantize, EachElementMovesWithinItsCellAndNoPairComesCloser) {
    const Exemplar ex = test::field_pattern("japanesepines");
    const double spacing = mean_nearest_neighbor_distance(ex);
    const Exemplar out = core::dequantized(ex, spacing, 3);
    ASSERT_EQ(out.elements.size(), ex.elements.size());
    int moved = 0;
    for (size_t i = 0; i < ex.elements.size(); ++i) {
        const Vec3 d = out.elements[i].position - ex.elements[i].position;
        EXPECT_LE(std::abs(d.x), 0.005 + 1e-12);
        EXPECT_LE(std::abs(d.y), 0.005 + 1e-12);
        EXPECT_EQ(out.samples[out.elements[i].first_sample].p, out.elements[i].position);
        moved += d.x != 0.0 || d.y != 0.0;
    }
    EXPECT_GT(moved, static_cast<int>(0.9 * ex.elements.size()));
    EXPECT_GE(closest_pair(out), closest_pair(ex) - 1e-12);
    EXPECT_EQ(core::coordinate_resolution(out), 0.0) << "still on the lattice";
}
