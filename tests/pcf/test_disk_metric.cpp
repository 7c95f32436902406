// Tests of the disk metric (Eq. 7 to 10 with tessera's continuity fix), its slope and
// r_max (Eq. 1): the salient configurations map to 1, 2, 3; the normalised metric is
// continuous and increasing in d for fixed radii, whatever their order; points use d / r_max.
#include <gtest/gtest.h>

#include <cmath>

#include "pcf/disk_metric.hpp"
#include "tessera/error.hpp"
#include "tessera/pcf_synthesis.hpp"

using namespace tessera;

TEST(PcfDiskMetric, SalientConfigurationsMapToOneTwoThree) {
    const double r_max = 0.7;
    for (const auto& [r1, r2] : {std::pair{1.0, 0.5}, {2.0, 0.1}, {3.0, 2.9}, {0.4, 0.4}, {5.0, 1.0}}) {
        SCOPED_TRACE(std::to_string(r1) + ", " + std::to_string(r2));
        if (r1 > r2) {
            EXPECT_NEAR(disk_metric_normalised(r1 - r2, r1, r2, r_max), 1.0, 1e-12);
        }  // inner border
        EXPECT_NEAR(disk_metric_normalised(r1, r1, r2, r_max), 2.0, 1e-12);                     // centre on border
        EXPECT_NEAR(disk_metric_normalised(r1 + r2, r1, r2, r_max), 3.0, 1e-12);                // tangent
        // Symmetric in the radii.
        EXPECT_DOUBLE_EQ(disk_metric_normalised(0.8 * r1, r1, r2, r_max), disk_metric_normalised(0.8 * r1, r2, r1, r_max));
        EXPECT_DOUBLE_EQ(disk_metric(0.8 * r1, r1, r2), disk_metric(0.8 * r1, r2, r1));
    }
}

TEST(PcfDiskMetric, UnnormalisedMetricMatchesEquationNine) {
    // Figure 5's values of f: inner border 4 r1 - 4 r2, border 4 r1 - r2, outer border 4 r1 + 2 r2.
    const double r1 = 2.0, r2 = 0.5;
    EXPECT_DOUBLE_EQ(disk_metric(r1 - r2, r1, r2), 4 * r1 - 4 * r2);
    EXPECT_DOUBLE_EQ(disk_metric(r1, r1, r2), 4 * r1 - r2);
    EXPECT_DOUBLE_EQ(disk_metric(r1 + r2, r1, r2), 4 * r1 + 2 * r2);
    EXPECT_DOUBLE_EQ(disk_metric(0.0, 1.0, 1.0), 0.0);  // identical disks
}

TEST(PcfDiskMetric, ContinuousAndIncreasingInDistance) {
    const double r_max = 0.3;
    for (const auto& [r1, r2] : {std::pair{1.0, 0.5}, {0.5, 1.0}, {2.0, 0.01}, {1.0, 1.0}, {0.2, 0.19}}) {
        SCOPED_TRACE(std::to_string(r1) + ", " + std::to_string(r2));
        const double dd = 1e-4;
        double previous = disk_metric_normalised(dd, r1, r2, r_max);
        for (double d = 2 * dd; d < 3.0 * (r1 + r2); d += dd) {
            const double x = disk_metric_normalised(d, r1, r2, r_max);
            EXPECT_GT(x, previous) << "d = " << d;
            // The largest slope is 1 / min(r2, r_max, 4 (r1 - r2)): steps stay small.
            const double slope = std::max({1.0 / std::min(r1, r2), 1.0 / r_max,
                                           r1 != r2 ? 0.25 / std::abs(r1 - r2) : 0.0});
            EXPECT_LE(x - previous, 1.01 * slope * dd) << "jump at d = " << d;
            previous = x;
        }
    }
}

TEST(PcfDiskMetric, BeyondContactIsTheGapInUnitsOfRmax) {
    EXPECT_NEAR(disk_metric_normalised(1.5 + 0.7, 1.0, 0.5, 0.35), 3.0 + 0.7 / 0.35, 1e-12);
    // Concentric disks of different radii sit at 3/4 (f = 3 (r1 - r2)), identical ones at 0.
    EXPECT_NEAR(disk_metric_normalised(0.0, 1.0, 0.5, 0.35), 0.75, 1e-12);
    EXPECT_EQ(disk_metric_normalised(0.0, 1.0, 1.0, 0.35), 0.0);
}

TEST(PcfDiskMetric, PointsUseDistanceOverRmax) {
    EXPECT_DOUBLE_EQ(disk_metric_normalised(0.6, 0.0, 0.0, 0.2), 3.0);
    EXPECT_DOUBLE_EQ(disk_metric_normalised(0.0, 0.0, 0.0, 0.2), 0.0);
    EXPECT_DOUBLE_EQ(pcf::disk_metric_slope(0.6, 0.0, 0.0, 0.2), 5.0);
}

TEST(PcfDiskMetric, PointAgainstDiskIsNestedOrOutside) {
    // r2 = 0: the three salient distances coincide at d = r1.
    const double r_max = 0.5;
    EXPECT_NEAR(disk_metric_normalised(0.0, 1.0, 0.0, r_max), 0.75, 1e-12);
    EXPECT_NEAR(disk_metric_normalised(1.0, 1.0, 0.0, r_max), 1.0, 1e-12);
    EXPECT_NEAR(disk_metric_normalised(1.25, 0.0, 1.0, r_max), 3.5, 1e-12);
    EXPECT_TRUE(std::isfinite(disk_metric_normalised(1.0 + 1e-15, 1.0, 0.0, r_max)));
}

TEST(PcfDiskMetric, NearlyEqualRadiiStayInRange) {
    // Eq. 10 evaluated literally would divide rounding noise by 4 (r1 - r2).
    const double r1 = 1.0, r2 = 1.0 - 1e-13;
    for (double d : {0.0, 5e-14, 1e-13}) {
        const double x = disk_metric_normalised(d, r1, r2, 0.5);
        EXPECT_GE(x, 0.75);
        EXPECT_LE(x, 1.0);
    }
}

TEST(PcfDiskMetric, SlopeMatchesFiniteDifferences) {
    const double r_max = 0.4;
    for (const auto& [r1, r2] : {std::pair{1.0, 0.5}, {0.3, 0.3}, {0.0, 0.0}, {1.0, 0.0}})
        for (double d : {0.1, 0.45, 0.9, 1.2, 1.7, 2.5}) {
            const double h = 1e-7;
            const double fd = (disk_metric_normalised(d + h, r1, r2, r_max) - disk_metric_normalised(d - h, r1, r2, r_max)) / (2 * h);
            if (std::abs(d - (r1 - r2)) < 1e-3 || std::abs(d - (r1 + r2)) < 1e-3) continue;  // branch boundaries
            EXPECT_NEAR(pcf::disk_metric_slope(d, r1, r2, r_max), fd, 1e-5 * std::abs(fd) + 1e-6)
                << r1 << " " << r2 << " d = " << d;
        }
}

TEST(PcfDiskMetric, RmaxFormula) {
    // Eq. 1: unit square, n points: 2 sqrt(1 / (2 sqrt(3) n)); scales with sqrt(area / n).
    EXPECT_NEAR(pcf_r_max(1.0, 100), 2.0 * std::sqrt(1.0 / (2.0 * std::sqrt(3.0) * 100)), 1e-15);
    EXPECT_NEAR(pcf_r_max(400.0, 100), 20.0 * pcf_r_max(1.0, 100), 1e-12);
    // Hexagonal packing of n disks of diameter r_max fills the area: n * sqrt(3) / 2 r_max^2 = area.
    const double r = pcf_r_max(50.0, 300);
    EXPECT_NEAR(300 * std::sqrt(3.0) / 2.0 * r * r, 50.0, 1e-9);
    EXPECT_THROW(pcf_r_max(0.0, 10), Error);
    EXPECT_THROW(pcf_r_max(1.0, 0), Error);
}
