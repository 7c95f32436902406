// The acceptance measures on the smaller PCF examples and a real dataset: synthesis
// into 4x the area keeps every mean PCF inside the input's validity envelope for >= 95% of
// its r-bins, each class's count within 2% of the input density, and the shares of the
// salient disk configurations within 5 percentage points. (The dense ecosystem and the
// anemones are left to the benchmark, B4: they take longer.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "tessera/tessera.hpp"

using namespace tessera;

namespace {

void expect_quality(const Exemplar& ex, const std::string& name) {
    SCOPED_TRACE(name);
    PcfSynthOptions o;
    const PcfModel model = analyze_distribution(ex, o.analysis);
    const Arrangement out = synthesize_pcf(model, ex.domain.scaled(2.0), o);
    const PcfQuality q = compare_distribution(model, ex, out);
    for (size_t k = 0; k < q.inside_fraction.size(); ++k)
        EXPECT_GE(q.inside_fraction[k], 0.95) << "PCF " << model.classes[model.pcfs[k].child] << " | "
                                              << model.classes[model.pcfs[k].parent];
    for (size_t c = 0; c < q.count_ratio.size(); ++c)
        EXPECT_NEAR(q.count_ratio[c], 1.0, 0.02) << model.classes[c];
    EXPECT_NEAR(q.output_shares.disjoint, q.input_shares.disjoint, 0.05);
    EXPECT_NEAR(q.output_shares.tangent, q.input_shares.tangent, 0.05);
    EXPECT_NEAR(q.output_shares.overlapping, q.input_shares.overlapping, 0.05);
    EXPECT_NEAR(q.output_shares.nested, q.input_shares.nested, 0.05);
}

const std::string examples = std::string(TESSERA_SOURCE_DIR) + "/examples/pcf/";
const std::string shared = std::string(TESSERA_SHARED_DATA_DIR) + "/points/";

}  // namespace

TEST(PcfExamples, ToyForest) { expect_quality(load(examples + "toy_forest.json"), "toy_forest"); }
TEST(PcfExamples, FourClassClusters) { expect_quality(load(examples + "clustered_four.json"), "clustered_four"); }
// Touching and nested disks in five classes of 7 to 80 elements (0.7 s).
TEST(PcfExamples, TableSet) { expect_quality(load(examples + "table_set.json"), "table_set"); }
// Four sizes in a chain of dependencies that never overlap, also across classes without a
// PCF between them (2 s).
TEST(PcfExamples, Droplets) { expect_quality(load(examples + "droplets.json"), "droplets"); }
TEST(PcfExamples, Amacrine) {
    LoadOptions lo;
    lo.input_domain = parse_box_domain("0,0,1.60121,1", "window");
    expect_quality(load(shared + "amacrine.csv", lo), "amacrine");
}
