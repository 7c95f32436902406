// The arithmetic PCF synthesis is built on (src/pcf/pair_distance.hpp, synth_state.hpp):
// the normalised pair distance, the kernel table and the boundary correction profiles.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.hpp"
#include "pcf/pair_distance.hpp"
#include "pcf/pcf_math.hpp"
#include "pcf/synth_state.hpp"
#include "pcf/disk_metric.hpp"
#include "pcf/synth_test_data.hpp"
#include "tessera/pcf_synthesis.hpp"

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
    // The library's disk metric and slope, in closed forms of their own.
    for (double ra : {0.0, 0.5, 1.0, 2.0})
        for (double rb : {0.0, 0.3, 1.0})
            for (double d = 0.0; d < 8.0; d += 0.0173) {
                const pcf::PairDistance pd = pcf::normalised_pair_distance_slope(d, ra, rb, r_max);
                EXPECT_NEAR(pd.x, disk_metric_normalised(d, ra, rb, r_max), 1e-12) << d << " " << ra << " " << rb;
                EXPECT_DOUBLE_EQ(pd.slope, pcf::disk_metric_slope(d, ra, rb, r_max)) << d << " " << ra << " " << rb;
            }
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

namespace {

// State::weight against 1 / circle_inside_fraction at random points and radii of a domain.
void expect_same_correction(const Domain& domain, std::uint64_t seed) {
    const Exemplar ex = test::poisson_disk(40, 10.0, 1.0, 3);
    const PcfModel model = analyze_distribution(ex);
    const pcf::State state(model, domain, {std::vector<double>(5, 0.0)});
    const core::KeyedRng rng(seed, core::Purpose::test);
    const Box b = domain.bounds();
    int tested = 0;
    for (int i = 0; i < 4000; ++i) {
        const Vec3 p{b.lo.x + (b.hi.x - b.lo.x) * rng.uniform(2 * i), b.lo.y + (b.hi.y - b.lo.y) * rng.uniform(2 * i + 1), 0.0};
        if (!domain.inside(p)) continue;
        pcf::CircleProfile profile;
        state.begin_profile(p, profile);
        state.build_profile(profile);
        for (int k = 0; k < 10; ++k) {
            const double d = 12.0 * rng.uniform(100000 + 10 * i + k);
            ++tested;
            ASSERT_EQ(state.weight(static_cast<const pcf::CircleProfile&>(profile), d),
                      1.0 / pcf::circle_inside_fraction(domain, p, d))
                << "at (" << p.x << ", " << p.y << "), radius " << d;
        }
    }
    EXPECT_GT(tested, 10000);
}

}  // namespace

TEST(PcfSynthParts, BoxBoundaryCorrectionCountsTheSameSamples) {
    expect_same_correction(Domain::box({1, 2, 0}, {7, 5, 0}, 2), 5);
}

TEST(PcfSynthParts, PolygonBoundaryCorrectionCountsTheSameSamples) {
    const Domain shape =
        Domain::polygon({{0, 0, 0}, {14, 0, 0}, {14, 6, 0}, {6, 6, 0}, {6, 14, 0}, {0, 14, 0}}, {{{2, 2, 0}, {4, 2, 0}, {3, 4, 0}}})
            .scaled(1.3);
    expect_same_correction(shape, 6);
}

TEST(PcfSynthParts, KernelTableFollowsTheKernel) {
    const Exemplar ex = test::poisson_disk(40, 10.0, 1.0, 3);
    const PcfModel model = analyze_distribution(ex);
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
