// Tests of mean_psi6: 1 on a perfect hexagonal lattice, low for uniform random
// points, translation invariant, and an option error in 3D.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.hpp"
#include "metrics/field_data.hpp"
#include "tessera/error.hpp"
#include "tessera/metrics.hpp"

using namespace tessera;

namespace {

// Triangular (hexagonal) lattice of spacing a filling the box [0, w] x [0, h].
Exemplar hex_lattice(double a, double w, double h, Vec3 offset = {}) {
    Exemplar ex;
    ex.domain = Domain::box(offset, offset + Vec3{w, h, 0}, 2);
    const int t = ex.type_index("cell");
    const double row = a * std::sqrt(3.0) / 2.0;
    for (int j = 0; j * row <= h; ++j)
        for (int i = -1; i * a <= w + a; ++i) {
            const Vec3 p{(i + 0.5 * (j % 2)) * a + 0.25 * a, j * row + 0.1 * a, 0};
            if (p.x >= 0 && p.x <= w && p.y <= h) ex.add_element(t, {p + offset});
        }
    return ex;
}

}  // namespace

TEST(MetricsPsi6, PerfectHexagonalLatticeIsOne) {
    const Exemplar ex = hex_lattice(1.0, 30.0, 25.0);
    EXPECT_NEAR(mean_psi6(ex), 1.0, 1e-9);
    const Exemplar moved = hex_lattice(1.0, 30.0, 25.0, {-512.5, 77.125, 0});
    EXPECT_NEAR(mean_psi6(moved), 1.0, 1e-9);
}

TEST(MetricsPsi6, UniformRandomPointsAreLow) {
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {1, 1, 0}, 2);
    const int t = ex.type_index("p");
    const core::KeyedRng rng(11, core::Purpose::test);
    for (int i = 0; i < 3000; ++i) ex.add_element(t, {Vec3{rng.uniform(2 * i), rng.uniform(2 * i + 1), 0}});
    const double psi = mean_psi6(ex);
    EXPECT_LT(psi, 0.5);
    EXPECT_GT(psi, 0.2);
}

TEST(MetricsPsi6, TranslationInvariantOnFieldData) {
    const Exemplar ex = test::load_field_pattern("cells");
    Exemplar moved = ex;
    const Vec3 shift{40.5, -3.25, 0};
    for (auto& e : moved.elements) e.position += shift;
    moved.domain = Domain::box(ex.domain.bounds().lo + shift, ex.domain.bounds().hi + shift, 2);
    const double a = mean_psi6(ex);
    EXPECT_TRUE(std::isfinite(a));
    EXPECT_NEAR(a, mean_psi6(moved), 1e-9);
}

TEST(MetricsPsi6, ThreeDimensionalDataIsAnOptionError) {
    Exemplar ex;
    ex.dimension = 3;
    ex.domain = Domain::box({0, 0, 0}, {1, 1, 1}, 3);
    ex.add_element(ex.type_index("a"), {Vec3{0.5, 0.5, 0.5}});
    try {
        mean_psi6(ex);
        FAIL() << "expected Error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::option);
    }
    Exemplar flat;
    flat.add_element(flat.type_index("a"), {Vec3{0.5, 0.5, 0}});
    EXPECT_THROW(mean_psi6(flat, -1.0), Error);
}
