// Tests of metrics_report_json: the sections and fields `tessera metrics` prints,
// one r grid for both PCFs, nulls for infinities, and zero differences when the
// output is the exemplar itself.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "metrics/field_data.hpp"
#include "tessera/metrics.hpp"

using namespace tessera;

TEST(MetricsReport, SectionsAndFields) {
    const Exemplar ex = test::load_field_pattern("amacrine");
    Exemplar out = ex;
    out.domain = Domain::box({0, 0, 0}, ex.domain.bounds().hi * 2.0, 2);
    for (auto& e : out.elements) e.position = e.position * 2.0;
    const auto j = nlohmann::json::parse(metrics_report_json(ex, out));
    for (const char* section : {"exemplar", "output"}) {
        SCOPED_TRACE(section);
        const auto& s = j.at(section);
        EXPECT_EQ(s.at("elements").get<int>(), 294);
        EXPECT_EQ(s.at("count_per_class").at("on").get<int>() + s.at("count_per_class").at("off").get<int>(), 294);
        EXPECT_GT(s.at("density").get<double>(), 0.0);
        for (const char* f : {"mean", "stddev", "min", "max"}) EXPECT_TRUE(s.at("nearest_neighbor").at(f).is_number());
        EXPECT_TRUE(s.at("mean_psi6").is_number());
        const auto& pcf = s.at("pcf");
        EXPECT_GT(pcf.at("bandwidth").get<double>(), 0.0);
        EXPECT_EQ(pcf.at("r").size(), 101u);
        ASSERT_EQ(pcf.at("pairs").size(), 3u);
        EXPECT_TRUE(pcf.at("pairs")[0].at("g")[0].is_null());  // +inf at r = 0
        EXPECT_TRUE(pcf.at("pairs")[0].at("g")[50].is_number());
    }
    // One r grid for both, from the exemplar.
    EXPECT_EQ(j["exemplar"]["pcf"]["r"], j["output"]["pcf"]["r"]);
    EXPECT_NEAR(j["exemplar"]["density"].get<double>(), 4.0 * j["output"]["density"].get<double>(), 1e-9);
    EXPECT_NEAR(j.at("nn_mean_relative_difference").get<double>(), 1.0, 1e-9);
    EXPECT_GT(j.at("pcf_relative_error").get<double>(), 0.1);
    EXPECT_TRUE(j.at("psi6_difference").is_number());
}

TEST(MetricsReport, IdenticalOutputHasZeroDifferences) {
    const Exemplar ex = test::load_field_pattern("redwood");
    const auto j = nlohmann::json::parse(metrics_report_json(ex, ex, {.r_max = 0.25, .bandwidth = 0.01}));
    EXPECT_DOUBLE_EQ(j.at("pcf_relative_error").get<double>(), 0.0);
    EXPECT_DOUBLE_EQ(j.at("nn_mean_relative_difference").get<double>(), 0.0);
    EXPECT_DOUBLE_EQ(j.at("psi6_difference").get<double>(), 0.0);
    EXPECT_DOUBLE_EQ(j["exemplar"]["pcf"]["r"].back().get<double>(), 0.25);
    EXPECT_DOUBLE_EQ(j["exemplar"]["pcf"]["bandwidth"].get<double>(), 0.01);
}

TEST(MetricsReport, ExemplarLevelErrorIsTheReportedOne) {
    // pcf_relative_error(exemplar, output): the report's number, on the exemplar's grid.
    const Exemplar ex = test::load_field_pattern("ganglia");
    Exemplar out = ex;
    for (auto& e : out.elements) e.position = e.position * 0.97;
    const PcfOptions options{.r_max = 0.2, .bandwidth = 0.008};
    const auto j = nlohmann::json::parse(metrics_report_json(ex, out, options));
    const double error = pcf_relative_error(ex, out, options);
    EXPECT_GT(error, 0.01);
    EXPECT_DOUBLE_EQ(error, j.at("pcf_relative_error").get<double>());
    const PcfResult grid = pair_correlation(ex, options);
    EXPECT_EQ(pair_correlation_on_grid_of(out, grid).r, grid.r);
    EXPECT_DOUBLE_EQ(pair_correlation_on_grid_of(out, grid).bandwidth, 0.008);
}

TEST(MetricsReport, ThreeDimensionalHasNoPsi6) {
    Exemplar ex;
    ex.dimension = 3;
    ex.domain = Domain::box({0, 0, 0}, {4, 4, 4}, 3);
    const int t = ex.type_index("a");
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 4; ++k) ex.add_element(t, {Vec3{i + 0.5, k + 0.5, 0.5 + (i + k) % 4}});
    const auto j = nlohmann::json::parse(metrics_report_json(ex, ex));
    EXPECT_FALSE(j["exemplar"].contains("mean_psi6"));
    EXPECT_FALSE(j.contains("psi6_difference"));
    EXPECT_EQ(j["dimension"].get<int>(), 3);
}
