// Tests of measure_distribution, compare_distribution and disk_configurations: an
// arrangement measured against its own model reproduces the model; a different pattern
// falls outside the envelopes; classes match by name; salient configurations are counted.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis_test_data.hpp"
#include "tessera/error.hpp"
#include "tessera/pcf_synthesis.hpp"

using namespace tessera;

TEST(PcfMeasure, OwnExemplarReproducesTheModel) {
    Exemplar ex = test::three_classes({}, {20, 30, 25});
    for (Element& e : ex.elements) e.radius = 0.2 + 0.1 * e.type;
    const PcfModel m = analyze_distribution(ex);
    const std::vector<PcfEnvelope> measured = measure_distribution(m, ex);
    ASSERT_EQ(measured.size(), m.pcfs.size());
    for (size_t q = 0; q < measured.size(); ++q) {
        EXPECT_EQ(measured[q].parent, m.pcfs[q].parent);
        EXPECT_EQ(measured[q].child, m.pcfs[q].child);
        EXPECT_EQ(measured[q].mean, m.pcfs[q].mean);
        EXPECT_EQ(measured[q].lower, m.pcfs[q].lower);
        EXPECT_EQ(measured[q].upper, m.pcfs[q].upper);
    }
    const PcfQuality quality = compare_distribution(m, ex, ex);
    ASSERT_EQ(quality.inside_fraction.size(), m.pcfs.size());
    for (double f : quality.inside_fraction) EXPECT_DOUBLE_EQ(f, 1.0);
    ASSERT_EQ(quality.count_ratio.size(), 3u);
    for (double r : quality.count_ratio) EXPECT_NEAR(r, 1.0, 1e-12);
    EXPECT_EQ(quality.input_shares.pairs, quality.output_shares.pairs);
}

TEST(PcfMeasure, MatchesClassesByNameAndCountsPerArea) {
    const Exemplar ex = test::three_classes();
    const PcfModel m = analyze_distribution(ex);
    // The same elements with the types listed in reverse order, in a domain twice as wide
    // holding the same elements: counts per area halve.
    Exemplar other;
    other.domain = Domain::box({0, 0, 0}, {20, 10, 0}, 2);
    for (const char* name : {"c", "b", "a", "extra"}) other.type_index(name);
    for (const Element& e : ex.elements) other.add_element(other.find_type(ex.types[e.type].name), {e.position});
    other.add_element(3, {Vec3{15, 5, 0}});
    const std::vector<PcfEnvelope> measured = measure_distribution(m, other);
    ASSERT_EQ(measured.size(), m.pcfs.size());
    const PcfQuality q = compare_distribution(m, ex, other);
    for (double r : q.count_ratio) EXPECT_NEAR(r, 0.5, 1e-12);
}

TEST(PcfMeasure, DifferentPatternLeavesTheEnvelope) {
    // Model: hard-core points; output: uniform random points, with pairs far closer
    // than any pair of the exemplar.
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    test::add_poisson_disk(ex, ex.type_index("p"), 400, 10.0, 0.35, 9);
    const PcfModel m = analyze_distribution(ex);
    const PcfQuality q = compare_distribution(m, ex, test::poisson_points(400, 10.0, 4));
    ASSERT_EQ(q.inside_fraction.size(), 1u);
    EXPECT_LT(q.inside_fraction[0], 0.95);
    // Another hard-core pattern of the same kind stays (mostly) inside.
    Exemplar same;
    same.domain = ex.domain;
    test::add_poisson_disk(same, same.type_index("p"), 400, 10.0, 0.35, 10);
    EXPECT_GT(compare_distribution(m, ex, same).inside_fraction[0], 0.9);
}

TEST(PcfMeasure, EmptyAndSingleClassesGiveZeros) {
    const PcfModel m = analyze_distribution(test::three_classes());
    Exemplar sparse;
    sparse.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    sparse.add_element(sparse.type_index("a"), {Vec3{1, 1, 0}});
    const std::vector<PcfEnvelope> measured = measure_distribution(m, sparse);
    for (const PcfEnvelope& e : measured)
        for (double v : e.mean) EXPECT_EQ(v, 0.0);
}

TEST(PcfDiskConfigurations, CountsTheSalientCases) {
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {100, 100, 0}, 2);
    const int t = ex.type_index("d");
    // Four pairs far apart from each other: nested, overlapping, tangent, disjoint but close.
    ex.add_element(t, {Vec3{10, 10, 0}}, 2.0);
    ex.add_element(t, {Vec3{10.5, 10, 0}}, 1.0);
    ex.add_element(t, {Vec3{40, 10, 0}}, 1.0);
    ex.add_element(t, {Vec3{41.5, 10, 0}}, 1.0);
    ex.add_element(t, {Vec3{70, 10, 0}}, 1.0);
    ex.add_element(t, {Vec3{71.51, 10, 0}}, 0.5);
    ex.add_element(t, {Vec3{10, 60, 0}}, 1.0);
    ex.add_element(t, {Vec3{12.5, 60, 0}}, 1.0);
    ex.add_element(t, {Vec3{90, 90, 0}}, 1.0);  // alone: no close pair
    const DiskConfigurationShares s = disk_configurations(ex, 1.0);
    EXPECT_EQ(s.pairs, 4);
    EXPECT_DOUBLE_EQ(s.nested, 0.25);
    EXPECT_DOUBLE_EQ(s.overlapping, 0.25);
    EXPECT_DOUBLE_EQ(s.tangent, 0.25);
    EXPECT_DOUBLE_EQ(s.disjoint, 0.25);
    // A smaller margin leaves the disjoint pair (gap 0.5) out.
    EXPECT_EQ(disk_configurations(ex, 0.4).pairs, 3);
    // Points have no extent: no pairs.
    EXPECT_EQ(disk_configurations(test::poisson_points(50, 1.0, 1), 1.0).pairs, 0);
    EXPECT_THROW(disk_configurations(ex, -1.0), Error);
}
