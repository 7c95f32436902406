// The arithmetic PCF synthesis is built on (src/pcf/pair_distance.hpp, synth_state.hpp):
// the normalised pair distance, the kernel table and the box boundary correction.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.hpp"
#include "pcf/pair_distance.hpp"
#include "pcf/pcf_math.hpp"
#include "pcf/synth_state.hpp"
#include "pcf/synth_test_model.hpp"

using namespace tessera;

TEST(PcfSynthParts, PairDistanceMapsTheSalientConfigurations) {
    const double r1 = 2.0, r2 = 0.5, r_max = 3.0;
    EXPECT_DOUBLE_EQ(pcf::normalised_pair_distance(r1 - r2, r1, r2, r_max), 1.0);  // inner border
    EXPECT_DOUBLE_EQ(pcf::normalised_pair_distance(r1, r1, r2, r_max), 2.0);       // centre on the border
    EXPECT_DOUBLE_EQ(pcf::normalised_pair_distance(r1 + r2, r1, r2, r_max), 3.0);  // tangent
    EXPECT_DOUBLE_EQ(pcf::normalised_pair_distance(0.0, r1, r2, r_max), 0.75);     // concentric
    EXPECT_DOUBLE_EQ(pcf::normalised_pair_distance(r1 + r2 + 1.5, r1, r2, r_max), 3.5);
    EXPECT_DOUBLE_EQ(pcf::normalised_pair_distance(r1, r2, r1, r_max), 2.0);  // radii in either order
    EXPECT_DOUBLE_EQ(pcf::normalised_pair_distance(1.5, 0.0, 0.0, r_max), 0.5);  // points
    EXPECT_DOUBLE_EQ(pcf::normalised_pair_distance(0.0, 1.0, 1.0, r_max), 0.0);  // equal radii, d = 0
    // Continuous and increasing in d, with the slope of its branch between the kinks.
    const double h = 0.01;
    for (double d = h; d < 6.0; d += h) {
        const pcf::PairDistance a = pcf::normalised_pair_distance_slope(d - h, r1, r2, r_max);
        const pcf::PairDistance b = pcf::normalised_pair_distance_slope(d, r1, r2, r_max);
        EXPECT_GT(b.x, a.x);
        EXPECT_LE(b.x - a.x, h * std::max(a.slope, b.slope) + 1e-9) << "d = " << d;
        if (a.slope == b.slope) {
            EXPECT_NEAR(b.x - a.x, h * b.slope, 1e-9) << "d = " << d;
        }
    }
}

TEST(PcfSynthParts, BoxBoundaryCorrectionCountsTheSameSamples) {
    const Exemplar ex = test::poisson_disk(40, 10.0, 1.0, 3);
    const PcfModel model = test::reference_model(ex);
    const Domain box = Domain::box({1, 2, 0}, {7, 5, 0}, 2);
    const pcf::State state(model, box, {std::vector<double>(5, 0.0)});
    const core::KeyedRng rng(5, core::Purpose::test);
    for (int i = 0; i < 20000; ++i) {
        const Vec3 p{1.0 + 6.0 * rng.uniform(3 * i), 2.0 + 3.0 * rng.uniform(3 * i + 1), 0.0};
        const double rho = 8.0 * rng.uniform(3 * i + 2);
        ASSERT_EQ(state.inside_fraction(p, rho), pcf::circle_inside_fraction(box, p, rho))
            << "at (" << p.x << ", " << p.y << "), radius " << rho;
    }
}

TEST(PcfSynthParts, PolygonBoundaryCorrectionCountsTheSameSamples) {
    const Exemplar ex = test::poisson_disk(40, 10.0, 1.0, 3);
    const PcfModel model = test::reference_model(ex);
    const Domain shape =
        Domain::polygon({{0, 0, 0}, {14, 0, 0}, {14, 6, 0}, {6, 6, 0}, {6, 14, 0}, {0, 14, 0}}, {{{2, 2, 0}, {4, 2, 0}, {3, 4, 0}}})
            .scaled(1.3);
    const pcf::State state(model, shape, {std::vector<double>(5, 0.0)});
    const core::KeyedRng rng(6, core::Purpose::test);
    int tested = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 p{19.0 * rng.uniform(3 * i), 19.0 * rng.uniform(3 * i + 1), 0.0};
        if (!shape.inside(p)) continue;
        const double rho = 12.0 * rng.uniform(3 * i + 2);
        ++tested;
        ASSERT_EQ(state.inside_fraction(p, rho), pcf::circle_inside_fraction(shape, p, rho))
            << "at (" << p.x << ", " << p.y << "), radius " << rho;
    }
    EXPECT_GT(tested, 5000);
}

TEST(PcfSynthParts, KernelTableFollowsTheKernel) {
    const Exemplar ex = test::poisson_disk(40, 10.0, 1.0, 3);
    const PcfModel model = test::reference_model(ex);
    const pcf::State state(model, ex.domain, {std::vector<double>(5, 0.0)});
    std::vector<double> values(state.kernel_max);
    for (double x = 0.0; x < state.x_limit; x += 0.0137) {
        int lo = 0, hi = 0;
        state.axis.bin_range(x, lo, hi);
        int first = 0;
        const int n = state.kernel(x, first, values.data());
        ASSERT_EQ(first, lo);
        ASSERT_EQ(n, hi - lo + 1);
        for (int m = 0; m < n; ++m)
            EXPECT_NEAR(values[m], pcf::kernel(state.axis.x(lo + m) - x, state.axis.sigma), 1e-6);
    }
}
