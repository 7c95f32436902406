// Tests of pair_correlation and pcf_relative_error: agreement with spatstat on
// every field dataset, translation invariance, g ~ 1 for a Poisson pattern, the
// first peak of a 3D lattice, option errors and class matching by name.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/rng.hpp"
#include "metrics/field_data.hpp"
#include "tessera/error.hpp"
#include "tessera/metrics.hpp"

using namespace tessera;

namespace {

const PcfCurve* find_curve(const PcfResult& pcf, const std::string& a, const std::string& b) {
    for (const auto& c : pcf.curves)
        if ((c.name_a == a && c.name_b == b) || (c.name_a == b && c.name_b == a)) return &c;
    return nullptr;
}

Exemplar uniform_points(int n, double side, std::uint64_t seed, int dimension = 2) {
    Exemplar ex;
    ex.dimension = dimension;
    ex.domain = Domain::box({0, 0, 0}, {side, side, dimension == 3 ? side : 0.0}, dimension);
    const int t = ex.type_index("p");
    const core::KeyedRng rng(seed, core::Purpose::test);
    for (int i = 0; i < n; ++i) {
        Vec3 p{side * rng.uniform(3 * i), side * rng.uniform(3 * i + 1), 0.0};
        if (dimension == 3) p.z = side * rng.uniform(3 * i + 2);
        ex.add_element(t, {p});
    }
    return ex;
}

}  // namespace

// spatstat 3.0 pcf / pcfcross (gaussian, translate, divisor r) on every dataset in
// points/, every class pair: within 3% wherever r >= 3 h and g_ref >= 0.2.
TEST(MetricsPcf, AgreesWithSpatstatOnFieldData) {
    const auto names = test::field_dataset_names();
    ASSERT_GE(names.size(), 7u);
    for (const auto& name : names) {
        SCOPED_TRACE(name);
        const Exemplar ex = test::load_field_pattern(name);
        const auto params = test::reference_params(name);
        const auto ref = test::read_csv(test::shared_data_dir() + "/reference/" + name + "_pcf.csv");
        ASSERT_EQ(ref.rows.size(), 101u);
        PcfOptions opt;
        opt.r_max = params.r_max;
        opt.bandwidth = params.bandwidth;
        opt.bins = 101;
        const PcfResult pcf = pair_correlation(ex, opt);
        ASSERT_EQ(pcf.r.size(), 101u);
        EXPECT_DOUBLE_EQ(pcf.bandwidth, params.bandwidth);
        for (size_t k = 0; k < pcf.r.size(); ++k) ASSERT_NEAR(pcf.r[k], ref.number(k, ref.column("r")), 1e-9);

        int columns_checked = 0;
        for (size_t col = 1; col < ref.columns.size(); ++col) {
            const std::string& column = ref.columns[col];
            const PcfCurve* curve = nullptr;
            if (column == "g") {
                ASSERT_EQ(pcf.curves.size(), 1u);
                curve = &pcf.curves[0];
            } else {
                // g_A_B: class names contain no underscore in these datasets.
                const auto second = column.find('_', 2);
                ASSERT_NE(second, std::string::npos) << column;
                curve = find_curve(pcf, column.substr(2, second - 2), column.substr(second + 1));
            }
            ASSERT_NE(curve, nullptr) << column;
            SCOPED_TRACE(column);
            EXPECT_TRUE(std::isinf(curve->g[0]));
            int points_checked = 0;
            for (size_t k = 0; k < pcf.r.size(); ++k) {
                const double g_ref = ref.number(k, static_cast<int>(col));
                if (pcf.r[k] < 3.0 * params.bandwidth || !(g_ref >= 0.2)) continue;
                EXPECT_NEAR(curve->g[k] / g_ref, 1.0, 0.03) << "r = " << pcf.r[k];
                ++points_checked;
            }
            EXPECT_GT(points_checked, 50);
            ++columns_checked;
        }
        EXPECT_EQ(columns_checked, static_cast<int>(pcf.curves.size()));
    }
}

TEST(MetricsPcf, TranslationInvariant) {
    const Exemplar ex = test::load_field_pattern("amacrine");
    Exemplar moved = ex;
    const Vec3 shift{123.25, -56.75, 0.0};
    for (auto& e : moved.elements) e.position += shift;
    for (auto& s : moved.samples) s.p += shift;
    moved.domain = Domain::box(ex.domain.bounds().lo + shift, ex.domain.bounds().hi + shift, 2);
    const PcfResult a = pair_correlation(ex), b = pair_correlation(moved);
    ASSERT_EQ(a.r.size(), b.r.size());
    ASSERT_EQ(a.curves.size(), 3u);
    for (size_t k = 0; k < a.r.size(); ++k) EXPECT_NEAR(a.r[k], b.r[k], 1e-9 * a.r.back());
    for (size_t c = 0; c < a.curves.size(); ++c)
        for (size_t k = 1; k < a.r.size(); ++k)
            EXPECT_NEAR(a.curves[c].g[k], b.curves[c].g[k], 1e-6 * std::max(1.0, a.curves[c].g[k]));
    EXPECT_LT(pcf_relative_error(a, b), 1e-6);
}

TEST(MetricsPcf, PoissonPatternIsNearOne) {
    const Exemplar ex = uniform_points(5000, 1.0, 7);
    PcfOptions opt;
    opt.r_max = 0.05;
    opt.bandwidth = 0.002;
    const PcfResult pcf = pair_correlation(ex, opt);
    for (size_t k = 0; k < pcf.r.size(); ++k) {
        if (pcf.r[k] < 5.0 * opt.bandwidth) continue;
        EXPECT_NEAR(pcf.curves[0].g[k], 1.0, 0.15) << "r = " << pcf.r[k];
    }
}

TEST(MetricsPcf, CubicLatticeFirstPeakAtSpacing) {
    Exemplar ex;
    ex.dimension = 3;
    const double spacing = 2.0;
    const int m = 8;
    ex.domain = Domain::box({-1, -1, -1}, {m * spacing - 1, m * spacing - 1, m * spacing - 1}, 3);
    const int t = ex.type_index("atom");
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j)
            for (int k = 0; k < m; ++k) ex.add_element(t, {Vec3{i * spacing, j * spacing, k * spacing}});
    const PcfResult pcf = pair_correlation(ex);  // defaults: r_max = 5 x spacing, h = r_max / 40
    EXPECT_NEAR(pcf.r.back(), 5.0 * spacing, 1e-9);
    // First local maximum above r = 3 h (later shells merge under the kernel and
    // can be higher: 24 neighbours at 2 sqrt 5 and 24 at 2 sqrt 6).
    const auto& g = pcf.curves[0].g;
    size_t peak = 0;
    for (size_t k = 1; k + 1 < pcf.r.size() && peak == 0; ++k)
        if (pcf.r[k] >= 3.0 * pcf.bandwidth && g[k] > 1.0 && g[k] > g[k - 1] && g[k] >= g[k + 1]) peak = k;
    ASSERT_GT(peak, 0u);
    EXPECT_NEAR(pcf.r[peak], spacing, 0.05 * spacing);
    // Well inside the first shell there are no pairs at all.
    const size_t hole = static_cast<size_t>(std::lround(0.5 * spacing / (pcf.r[1] - pcf.r[0])));
    EXPECT_LT(g[hole], 0.01);
}

TEST(MetricsPcf, DefaultsFollowTheSpacing) {
    const Exemplar ex = test::load_field_pattern("cells");
    const PcfResult pcf = pair_correlation(ex);
    EXPECT_EQ(pcf.r.size(), 101u);
    EXPECT_NEAR(pcf.r.back(), 5.0 * nearest_neighbor_distances(ex).mean, 1e-12);
    EXPECT_NEAR(pcf.bandwidth, pcf.r.back() / 40.0, 1e-12);
    EXPECT_DOUBLE_EQ(pcf.r[0], 0.0);
}

TEST(MetricsPcf, RejectsBadOptions) {
    const Exemplar ex = test::load_field_pattern("cells");
    auto kind_of = [&](PcfOptions o) {
        try {
            pair_correlation(ex, o);
        } catch (const Error& e) {
            return e.kind();
        }
        return ErrorKind::internal;
    };
    EXPECT_EQ(kind_of({.r_max = -1.0}), ErrorKind::option);
    EXPECT_EQ(kind_of({.r_max = NAN}), ErrorKind::option);
    EXPECT_EQ(kind_of({.bandwidth = -0.1}), ErrorKind::option);
    EXPECT_EQ(kind_of({.bins = 1}), ErrorKind::option);
    EXPECT_EQ(kind_of({.bins = -5}), ErrorKind::option);
    EXPECT_NO_THROW(pair_correlation(ex, {.r_max = 0.2, .bandwidth = 0.01, .bins = 2}));
}

TEST(MetricsPcf, DeterministicAndSymmetricInClassOrder) {
    const Exemplar ex = test::load_field_pattern("ganglia");
    const PcfResult a = pair_correlation(ex), b = pair_correlation(ex);
    for (size_t c = 0; c < a.curves.size(); ++c)
        for (size_t k = 1; k < a.r.size(); ++k) ASSERT_EQ(a.curves[c].g[k], b.curves[c].g[k]);

    // The same pattern with the two types listed in the other order: curves are
    // matched by class name, so the relative error is 0.
    Exemplar swapped = ex;
    std::swap(swapped.types[0], swapped.types[1]);
    for (auto& e : swapped.elements) e.type = 1 - e.type;
    const PcfResult s = pair_correlation(swapped);
    EXPECT_EQ(s.curves[0].name_a, ex.types[1].name);
    EXPECT_LT(pcf_relative_error(a, s), 1e-12);
}

TEST(MetricsPcf, RelativeErrorCountsMissingClassesAsZero) {
    const Exemplar ex = test::load_field_pattern("amacrine");
    const PcfResult full = pair_correlation(ex);
    PcfResult only_first = full;
    only_first.curves.resize(1);  // keep (on, on)
    const double e = pcf_relative_error(full, only_first);
    EXPECT_GT(e, 0.5);
    EXPECT_LT(e, 1.0 + 1e-12);
    EXPECT_DOUBLE_EQ(pcf_relative_error(full, full), 0.0);
    PcfResult coarse = pair_correlation(ex, {.bins = 51});
    EXPECT_THROW(pcf_relative_error(full, coarse), Error);
}
