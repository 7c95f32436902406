// Tests of the 2D polygon domain: even-odd inside with holes, exact measure,
// closest_inside, the conservative distance_to_boundary, set covariance, validation.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tessera/domain.hpp"
#include "tessera/error.hpp"

using namespace tessera;

namespace {

// A 10 x 10 square with a 4 x 4 square hole in its middle.
Domain square_with_hole() {
    return Domain::polygon({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{3, 3}, {3, 7}, {7, 7}, {7, 3}}});
}

// True distance to the boundary of square_with_hole (for points inside it).
double true_distance(const Vec3& p) {
    const double outer = std::min({p.x, 10 - p.x, p.y, 10 - p.y});
    const double dx = std::max({3 - p.x, 0.0, p.x - 7}), dy = std::max({3 - p.y, 0.0, p.y - 7});
    return std::min(outer, std::hypot(dx, dy));
}

}  // namespace

TEST(DomainPolygon, PointsInTheHoleAreOutside) {
    const Domain d = square_with_hole();
    EXPECT_EQ(d.kind(), Domain::Kind::polygon);
    EXPECT_TRUE(d.inside({1, 1, 0}));
    EXPECT_TRUE(d.inside({8, 5, 0}));
    EXPECT_FALSE(d.inside({5, 5, 0}));
    EXPECT_FALSE(d.inside({11, 5, 0}));
    EXPECT_DOUBLE_EQ(d.occupancy({5, 5, 0}), 0.0);
    EXPECT_DOUBLE_EQ(d.occupancy({1, 5, 0}), 1.0);
}

TEST(DomainPolygon, MeasureIsOuterMinusHoles) {
    EXPECT_DOUBLE_EQ(square_with_hole().measure(), 100.0 - 16.0);
    EXPECT_DOUBLE_EQ(square_with_hole().scaled(2.0).measure(), 4 * 84.0);
}

TEST(DomainPolygon, ClosestInsideLandsInsideOnTheBoundary) {
    const Domain d = square_with_hole();
    for (const Vec3& p : {Vec3(5, 5.5), Vec3(-2, 4), Vec3(12, 12), Vec3(4, 6.9)}) {
        const Vec3 q = d.closest_inside(p);
        EXPECT_TRUE(d.inside(q)) << p.x << "," << p.y;
        EXPECT_LT(true_distance(q), 1e-6);
    }
    EXPECT_NEAR(d.closest_inside({5, 5.5, 0}).y, 7.0, 1e-6);
    const Vec3 in{1, 2, 0};
    EXPECT_EQ(d.closest_inside(in), in);
}

TEST(DomainPolygon, DistanceToBoundaryNeverExceedsTheTrueDistance) {
    const Domain d = square_with_hole();
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.0, 10.0);
    for (int i = 0; i < 5000; ++i) {
        const Vec3 p{u(rng), u(rng), 0};
        if (!d.inside(p)) {
            EXPECT_LE(d.distance_to_boundary(p), 0.0);
            continue;
        }
        EXPECT_LE(d.distance_to_boundary(p), true_distance(p) + 1e-12);
        EXPECT_NEAR(d.distance_to_boundary(p), true_distance(p), 1e-9);  // polygons are exact
    }
}

TEST(DomainPolygon, TranslatedOverlapMatchesMonteCarlo) {
    const Domain d = square_with_hole();
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.0, 10.0);
    for (const Vec3& shift : {Vec3(0, 0), Vec3(1.3, 0.4), Vec3(-2.5, 3.1), Vec3(4, -4)}) {
        const int n = 200000;
        int hits = 0;
        for (int i = 0; i < n; ++i) {
            const Vec3 p{u(rng), u(rng), 0};
            hits += d.inside(p) && d.inside(p - shift);
        }
        const double mc = 100.0 * hits / n;
        EXPECT_NEAR(d.translated_overlap(shift), mc, 0.02 * mc) << shift.x << "," << shift.y;
    }
    EXPECT_DOUBLE_EQ(d.translated_overlap({11, 0, 0}), 0.0);
}

TEST(DomainPolygon, RejectsBadRings) {
    const auto domain_error = [](auto make) {
        try {
            make();
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::domain) << e.what();
            return std::string(e.what());
        }
        ADD_FAILURE() << "no error";
        return std::string();
    };
    EXPECT_NE(domain_error([] { Domain::polygon({{0, 0}, {1, 0}}); }).find("at least 3"), std::string::npos);
    EXPECT_NE(domain_error([] { Domain::polygon({{0, 0}, {1, 0}, {2, 0}}); }).find("zero area"), std::string::npos);
    EXPECT_NE(domain_error([] { Domain::polygon({{0, 0}, {NAN, 0}, {2, 2}}); }).find("non-finite"), std::string::npos);
    // A bow tie.
    EXPECT_NE(domain_error([] { Domain::polygon({{0, 0}, {4, 4}, {4, 0}, {0, 2}}); }).find("intersects itself"),
              std::string::npos);
    EXPECT_NE(domain_error([] { Domain::polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{3, 1}, {5, 1}, {5, 2}}}); })
                  .find("crosses"),
              std::string::npos);
}

TEST(DomainPolygon, ScaledKeepsLowerCornerAndShape) {
    const Domain d = square_with_hole().scaled(0.5);
    EXPECT_EQ(d.bounds().hi, Vec3(5, 5, 0));
    EXPECT_FALSE(d.inside({2.5, 2.5, 0}));
    EXPECT_TRUE(d.inside({0.5, 2.5, 0}));
    EXPECT_NEAR(d.distance_to_boundary({0.5, 2.5, 0}), 0.5, 1e-12);
}
