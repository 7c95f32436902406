// Tests of analyze_distribution: the estimator (a Poisson pattern's PCF is ~1, a
// Poisson-disk pattern's is ~0 below its hard-core distance, in boxes and polygons),
// envelopes, the dependency graph (default, explicit, cycles, unknown names), the
// model's bookkeeping (counts, radii, r_max, axis) and input / option errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis_test_data.hpp"
#include "tessera/error.hpp"
#include "tessera/metrics.hpp"
#include "tessera/pcf_synthesis.hpp"

using namespace tessera;

namespace {

double mean_over(const PcfModel& m, const std::vector<double>& values, double x0, double x1) {
    double sum = 0.0;
    int n = 0;
    for (size_t k = 0; k < m.x.size(); ++k)
        if (m.x[k] >= x0 - 1e-9 && m.x[k] <= x1 + 1e-9) sum += values[k], ++n;
    return sum / n;
}

std::string error_of(const Exemplar& ex, const PcfAnalysisSettings& s = {}) {
    try {
        analyze_distribution(ex, s);
    } catch (const Error& e) {
        return std::string(to_string(e.kind())) + ": " + e.what();
    }
    return "no error";
}

}  // namespace

TEST(PcfAnalysis, PoissonPatternIsFlatAtOne) {
    const PcfModel m = analyze_distribution(test::poisson_points(3000, 10.0, 3));
    ASSERT_EQ(m.pcfs.size(), 1u);
    EXPECT_FALSE(m.disks);
    EXPECT_NEAR(mean_over(m, m.pcfs[0].mean, 2.0, 5.0), 1.0, 0.1);
    // Pointwise too, away from the kernel's cut at x = 0.
    for (size_t k = 0; k < m.x.size(); ++k)
        if (m.x[k] >= 1.5) {
            EXPECT_NEAR(m.pcfs[0].mean[k], 1.0, 0.15) << "x = " << m.x[k];
        }
}

TEST(PcfAnalysis, SmallWindowsAreCorrectedAtTheBoundary) {
    // 100 points: the neighbourhood (5 r_max ~ 5.4) is half the window, so most rings are
    // cut by the boundary; averaged over 20 patterns the corrected PCF stays at 1.
    std::vector<double> sum;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const PcfModel m = analyze_distribution(test::poisson_points(100, 10.0, seed));
        sum.resize(m.x.size());
        for (size_t k = 0; k < m.x.size(); ++k) sum[k] += m.pcfs[0].mean[k] / 20.0;
        if (seed == 20) {
            EXPECT_NEAR(mean_over(m, sum, 2.0, 5.0), 1.0, 0.05);
            EXPECT_NEAR(mean_over(m, sum, 4.0, 5.0), 1.0, 0.08);
        }
    }
}

TEST(PcfAnalysis, RandomDisksFollowTheRingConvention) {
    // Uniform random centres, equal radii r: beyond contact x = 3 + (d - 2 r) / r_max, so
    // the ring of A_k = 2 pi x_k step r_max^2 holds (x - 3 + 2 r / r_max) / x times the
    // neighbours of a centre-distance ring: the PCF tends to that, not to 1.
    Exemplar ex = test::poisson_points(3000, 10.0, 21);
    const double r_max = pcf_r_max(100.0, 3000), r = 0.3 * r_max;
    for (Element& e : ex.elements) e.radius = r;
    const PcfModel m = analyze_distribution(ex);
    ASSERT_TRUE(m.disks);
    std::vector<double> ratio(m.x.size());
    for (size_t k = 0; k < m.x.size(); ++k) ratio[k] = m.pcfs[0].mean[k] / ((m.x[k] - 3.0 + 2.0 * r / r_max) / m.x[k]);
    EXPECT_NEAR(mean_over(m, ratio, 4.5, 8.0), 1.0, 0.1);
}

TEST(PcfAnalysis, PoissonPatternInPolygonIsFlatAtOne) {
    // A 24-gon: the boundary correction (circle fractions) must hold beyond boxes.
    std::vector<Vec3> ring;
    for (int k = 0; k < 24; ++k)
        ring.push_back({5 + 5 * std::cos(2 * std::numbers::pi * k / 24), 5 + 5 * std::sin(2 * std::numbers::pi * k / 24), 0});
    const Domain disk = Domain::polygon(ring);
    Exemplar all = test::poisson_points(4000, 10.0, 11), ex;
    ex.domain = disk;
    const int t = ex.type_index("p");
    for (const Element& e : all.elements)
        if (disk.inside(e.position)) ex.add_element(t, {e.position});
    const PcfModel m = analyze_distribution(ex);
    EXPECT_NEAR(m.area, disk.measure(), 1e-9);
    EXPECT_NEAR(mean_over(m, m.pcfs[0].mean, 2.0, 5.0), 1.0, 0.1);
}

TEST(PcfAnalysis, PoissonDiskPatternIsEmptyBelowHardCore) {
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    const int n = 800;
    const double r_max = pcf_r_max(100.0, n);
    test::add_poisson_disk(ex, ex.type_index("p"), n, 10.0, 0.65 * r_max, 5);
    ASSERT_EQ(static_cast<int>(ex.elements.size()), n);
    PcfAnalysisSettings s;
    s.sigma = 0.1;
    const PcfModel m = analyze_distribution(ex, s);
    EXPECT_NEAR(m.r_max, r_max, 1e-12);
    for (size_t k = 0; k < m.x.size(); ++k) {
        if (m.x[k] <= 0.65 - 0.4 - 1e-9) {
            EXPECT_EQ(m.pcfs[0].upper[k], 0.0) << "x = " << m.x[k];
        }
        if (m.x[k] <= 0.65 - 0.3) {
            EXPECT_LT(m.pcfs[0].mean[k], 0.02) << "x = " << m.x[k];
        }
    }
    EXPECT_NEAR(mean_over(m, m.pcfs[0].mean, 2.0, 5.0), 1.0, 0.1);
}

TEST(PcfAnalysis, AgreesWithStandardEstimatorOnPoints) {
    // Both estimate the same g(r) of a clustered pattern: at x = d / r_max the paper's
    // kernel exp(-t^2 / sigma^2) is a Gaussian of standard deviation sigma r_max / sqrt(2).
    // Edge corrections differ (circle fraction vs translation), so the match is loose.
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    const int t = ex.type_index("p");
    const core::KeyedRng rng(17, core::Purpose::test);
    for (int c = 0; c < 60; ++c) {
        const Vec3 centre{10 * rng.uniform(1000 + 2 * c), 10 * rng.uniform(1001 + 2 * c), 0};
        for (int i = 0; i < 12; ++i) {
            const double a = 2 * std::numbers::pi * rng.uniform(5000 + 24 * c + 2 * i);
            const double r = 0.6 * std::sqrt(rng.uniform(5001 + 24 * c + 2 * i));
            const Vec3 p{centre.x + r * std::cos(a), centre.y + r * std::sin(a), 0};
            if (ex.domain.inside(p)) ex.add_element(t, {p});
        }
    }
    const PcfModel m = analyze_distribution(ex);
    PcfOptions o;
    o.r_max = 5.0 * m.r_max;
    o.bandwidth = m.settings.sigma * m.r_max / std::sqrt(2.0);
    o.bins = static_cast<int>(m.x.size());
    const PcfResult g = pair_correlation(ex, o);
    for (size_t k = 0; k < m.x.size(); ++k) {
        if (m.x[k] < 1.0) continue;
        EXPECT_NEAR(m.pcfs[0].mean[k], g.curves[0].g[k], 0.1 * g.curves[0].g[k] + 0.05) << "x = " << m.x[k];
    }
}

TEST(PcfAnalysis, EnvelopesContainTheMean) {
    Exemplar ex = test::three_classes({}, {30, 40, 50});
    for (Element& e : ex.elements) e.radius = 0.1 + 0.05 * (e.type + 1);
    const PcfModel m = analyze_distribution(ex);
    EXPECT_TRUE(m.disks);
    ASSERT_EQ(m.pcfs.size(), 6u);
    for (const PcfEnvelope& e : m.pcfs) {
        ASSERT_EQ(e.mean.size(), m.x.size());
        double spread = 0.0;
        for (size_t k = 0; k < m.x.size(); ++k) {
            EXPECT_LE(e.lower[k], e.mean[k]);
            EXPECT_LE(e.mean[k], e.upper[k]);
            spread += e.upper[k] - e.lower[k];
        }
        EXPECT_GT(spread, 0.0);
    }
}

TEST(PcfAnalysis, ModelBookkeeping) {
    Exemplar ex = test::three_classes({}, {5, 3, 4});
    for (size_t i = 0; i < ex.elements.size(); ++i) ex.elements[i].radius = 0.1 * (i % 4) + 0.05;
    PcfAnalysisSettings s;
    s.step = 0.2;
    s.extent = 4.0;
    const PcfModel m = analyze_distribution(ex, s);
    EXPECT_EQ(m.classes, (std::vector<std::string>{"a", "b", "c"}));
    EXPECT_EQ(m.counts, (std::vector<int>{5, 3, 4}));
    EXPECT_NEAR(m.area, 100.0, 1e-12);
    EXPECT_NEAR(m.r_max, pcf_r_max(100.0, 12), 1e-15);
    // Disks: the axis runs to 3 + extent.
    ASSERT_EQ(m.x.size(), 36u);
    EXPECT_NEAR(m.x.back(), 7.0, 1e-12);
    for (const auto& r : m.radii) EXPECT_TRUE(std::is_sorted(r.begin(), r.end(), std::greater<>()));
    EXPECT_EQ(m.radii[0].size(), 5u);
    EXPECT_DOUBLE_EQ(m.settings.step, 0.2);
    // Points: 0 to extent.
    const PcfModel points = analyze_distribution(test::three_classes({}, {5, 3, 4}), s);
    EXPECT_EQ(points.x.size(), 21u);
}

TEST(PcfAnalysis, DefaultGraphDependsOnEveryEarlierClass) {
    const PcfModel m = analyze_distribution(test::three_classes());
    EXPECT_EQ(m.parents, (std::vector<std::vector<int>>{{}, {0}, {0, 1}}));
    EXPECT_EQ(m.order, (std::vector<int>{0, 1, 2}));
    // Grouped by class in order: its own PCF, then one per parent.
    const std::vector<std::pair<int, int>> expected = {{0, 0}, {1, 1}, {0, 1}, {2, 2}, {0, 2}, {1, 2}};
    ASSERT_EQ(m.pcfs.size(), expected.size());
    for (size_t q = 0; q < expected.size(); ++q) {
        EXPECT_EQ(m.pcfs[q].parent, expected[q].first) << q;
        EXPECT_EQ(m.pcfs[q].child, expected[q].second) << q;
    }
}

TEST(PcfAnalysis, ExplicitDependencies) {
    // a depends on c; b and c are independent: c must come before a.
    const PcfModel m = analyze_distribution(test::three_classes({std::vector<std::string>{"c"}, std::vector<std::string>{},
                                                                 std::vector<std::string>{}}));
    EXPECT_EQ(m.parents, (std::vector<std::vector<int>>{{2}, {}, {}}));
    EXPECT_EQ(m.order, (std::vector<int>{1, 2, 0}));
    ASSERT_EQ(m.pcfs.size(), 4u);
    EXPECT_EQ(m.pcfs[3].parent, 2);
    EXPECT_EQ(m.pcfs[3].child, 0);
    // A sparse graph keeps the default for types without depends_on: c depends on a and b.
    const PcfModel mixed = analyze_distribution(test::three_classes({std::nullopt, std::vector<std::string>{}}));
    EXPECT_EQ(mixed.parents, (std::vector<std::vector<int>>{{}, {}, {0, 1}}));
}

TEST(PcfAnalysis, SeparationsOfClassesWithoutAPcf) {
    // a and b independent (no PCF between them), c depends on both: one separation, a-b,
    // the closest approach of an a and a b on the normalised axis.
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    const int a = ex.type_index("a"), b = ex.type_index("b"), c = ex.type_index("c");
    ex.types[a].depends_on = std::vector<std::string>{};
    ex.types[b].depends_on = std::vector<std::string>{};
    ex.add_element(a, {Vec3{2, 2, 0}}, 1.0);
    ex.add_element(a, {Vec3{8, 8, 0}}, 1.0);
    ex.add_element(b, {Vec3{2, 4, 0}}, 0.5);  // 0.5 apart from the first a
    ex.add_element(b, {Vec3{8, 5, 0}}, 0.5);
    ex.add_element(c, {Vec3{5, 5, 0}}, 0.2);
    ex.add_element(c, {Vec3{2.1, 2, 0}}, 0.2);  // inside an a: c has PCFs with a and b, no separation
    const PcfModel m = analyze_distribution(ex);
    ASSERT_EQ(m.separations.size(), 1u);
    EXPECT_EQ(m.separations[0].a, a);
    EXPECT_EQ(m.separations[0].b, b);
    EXPECT_NEAR(m.separations[0].x, 3.0 + 0.5 / m.r_max, 1e-12);
    // Never closer than 3 + sigma: the cap (beyond the salient configurations).
    ex.elements[2].position = Vec3{2, 6, 0};
    ex.samples[ex.elements[2].first_sample].p = Vec3{2, 6, 0};
    EXPECT_DOUBLE_EQ(analyze_distribution(ex).separations[0].x, 3.0 + PcfAnalysisSettings{}.sigma);
    // The default graph connects every pair: no separations.
    EXPECT_TRUE(analyze_distribution(test::three_classes()).separations.empty());
}

TEST(PcfAnalysis, EdgePcfUsesChildAsReference) {
    // 2 parents, 40 children: the envelope is over the child's 40 elements. Children
    // are all far (> 3 r_max) from the parents except one, close to parent 0.
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {40, 40, 0}, 2);
    const int parent = ex.type_index("parent"), child = ex.type_index("child");
    ex.add_element(parent, {Vec3{5, 5, 0}});
    ex.add_element(parent, {Vec3{35, 35, 0}});
    for (int i = 0; i < 40; ++i) ex.add_element(child, {Vec3{20.0 + (i % 8) * 0.9, 12.0 + (i / 8) * 0.9, 0}});
    ex.elements.back().position = ex.samples.back().p = {5.5, 5, 0};
    const PcfModel m = analyze_distribution(ex);
    const PcfEnvelope& edge = m.pcfs[2];
    ASSERT_EQ(edge.parent, parent);
    ASSERT_EQ(edge.child, child);
    const double x = 0.5 / m.r_max;
    const size_t k = static_cast<size_t>(std::lround(x / m.settings.step));
    // One child sees one parent at x: its individual PCF peaks there; the others are 0,
    // and the mean is their average.
    EXPECT_GT(edge.upper[k], 0.0);
    EXPECT_EQ(edge.lower[k], 0.0);
    EXPECT_NEAR(edge.mean[k], edge.upper[k] / 40.0, 1e-9 * edge.upper[k]);
}

TEST(PcfAnalysis, CycleErrorNamesTheClasses) {
    const std::string e = error_of(test::three_classes(
        {std::vector<std::string>{"c"}, std::vector<std::string>{}, std::vector<std::string>{"a"}}));
    EXPECT_NE(e.find("input"), std::string::npos) << e;
    EXPECT_NE(e.find("cycle"), std::string::npos) << e;
    EXPECT_NE(e.find("'a'"), std::string::npos) << e;
    EXPECT_NE(e.find("'c'"), std::string::npos) << e;
    EXPECT_EQ(e.find("'b'"), std::string::npos) << e;
    const std::string self = error_of(test::three_classes({std::nullopt, std::vector<std::string>{"b"}}));
    EXPECT_NE(self.find("cycle"), std::string::npos) << self;
    EXPECT_NE(self.find("'b'"), std::string::npos) << self;
}

TEST(PcfAnalysis, UnknownDependencyIsAnError) {
    const std::string e = error_of(test::three_classes({std::nullopt, std::vector<std::string>{"rock"}}));
    EXPECT_NE(e.find("input"), std::string::npos) << e;
    EXPECT_NE(e.find("'b'"), std::string::npos) << e;
    EXPECT_NE(e.find("'rock'"), std::string::npos) << e;
}

TEST(PcfAnalysis, ClassWithOneElementIsSparse) {
    const PcfModel m = analyze_distribution(test::three_classes({}, {5, 1, 4}));
    ASSERT_EQ(m.sparse.size(), 1u);
    EXPECT_EQ(m.sparse[0].cls, 1);
    EXPECT_EQ(m.counts[1], 1);
    EXPECT_GT(m.sparse[0].spacing, 0.0);
    EXPECT_GT(m.sparse[0].tether[0], 0.0);  // b depends on a
    EXPECT_EQ(m.sparse[0].tether[2], 0.0);  // c depends on b, not b on c
}

TEST(PcfAnalysis, ClassWithoutElementsIsAnError) {
    const std::string e = error_of(test::three_classes({}, {5, 0, 4}));
    EXPECT_NE(e.find("input"), std::string::npos) << e;
    EXPECT_NE(e.find("'b' has no elements"), std::string::npos) << e;
}

TEST(PcfAnalysis, InputErrors) {
    Exemplar negative = test::three_classes();
    negative.elements[12].radius = -1.0;
    EXPECT_NE(error_of(negative).find("'b'"), std::string::npos) << error_of(negative);
    Exemplar sticks = test::three_classes();
    sticks.add_element(0, {Vec3{1, 1, 0}, Vec3{2, 2, 0}});
    EXPECT_NE(error_of(sticks).find("multi-sample"), std::string::npos) << error_of(sticks);
    Exemplar three_d;
    three_d.dimension = 3;
    three_d.domain = Domain::box({0, 0, 0}, {1, 1, 1}, 3);
    for (int i = 0; i < 3; ++i) three_d.add_element(three_d.type_index("s"), {Vec3{0.1 * i, 0.5, 0.5}});
    EXPECT_NE(error_of(three_d).find("2D"), std::string::npos) << error_of(three_d);
    EXPECT_EQ(error_of(Exemplar{}).rfind("input", 0), 0u) << error_of(Exemplar{});
}

TEST(PcfAnalysis, OptionErrors) {
    for (const auto& [field, value] : {std::pair<int, double>{0, 0.0}, {0, -1.0}, {1, 0.0}, {2, -2.0}, {1, NAN}}) {
        PcfAnalysisSettings s;
        (field == 0 ? s.sigma : field == 1 ? s.step : s.extent) = value;
        const std::string e = error_of(test::three_classes(), s);
        EXPECT_EQ(e.rfind("option", 0), 0u) << e;
        EXPECT_NE(e.find(field == 0 ? "sigma" : field == 1 ? "step" : "extent"), std::string::npos) << e;
    }
}
