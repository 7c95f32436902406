// Defects a viewer sees, on PCF outputs at 4x the area (metrics.hpp): the share of
// crowded elements per ordered class pair (nearest neighbour of the other class closer
// than the exemplar's 1% quantile) within 1.5x of the exemplar's, and no pair closer than
// 1/100 of that unless the exemplar has such pairs (the final crowding repair,
// src/pcf/synth_repair.hpp); the largest empty circle within 1.3x of the exemplar's
// (src/pcf/synth_holes.hpp).
#include <gtest/gtest.h>

#include <string>

#include "tessera/tessera.hpp"

using namespace tessera;

namespace {

const std::string examples = std::string(TESSERA_SOURCE_DIR) + "/examples/pcf/";
const std::string points = std::string(TESSERA_SHARED_DATA_DIR) + "/points/";

Arrangement synthesize_4x(const Exemplar& ex) {
    PcfSynthOptions o;
    o.threads = 2;
    return synthesize_pcf(ex, ex.domain.scaled(2.0), o);
}

void expect_no_hole(const Exemplar& ex, const Arrangement& out) {
    EXPECT_LE(largest_empty_circle(out).radius, 1.3 * largest_empty_circle(ex).radius);
}

void expect_no_crowding(const Exemplar& ex, const Arrangement& out) {
    for (const CrowdingPair& c : crowding(ex, out)) {
        SCOPED_TRACE(c.name_a + " -> " + c.name_b);
        EXPECT_LE(c.output_share, 1.5 * c.exemplar_share);
        if (c.exemplar_coincident == 0) {
            EXPECT_EQ(c.output_coincident, 0);
        }
    }
}

Exemplar csv(const std::string& name, const std::string& window) {
    LoadOptions lo;
    lo.input_domain = parse_box_domain(window, "window");
    return load(points + name + ".csv", lo);
}

}  // namespace

TEST(PcfDefects, ToyForestIsNotCrowdedAndHasNoHole) {
    const Exemplar ex = load(examples + "toy_forest.json");
    const Arrangement out = synthesize_4x(ex);
    expect_no_crowding(ex, out);
    expect_no_hole(ex, out);
}

TEST(PcfDefects, TableSetIsNotCrowdedAndHasNoHole) {
    const Exemplar ex = load(examples + "table_set.json");
    const Arrangement out = synthesize_4x(ex);
    expect_no_crowding(ex, out);
    expect_no_hole(ex, out);
}

TEST(PcfDefects, RedwoodIsNotCrowdedAndHasNoHole) {  // a clustered pattern
    const Exemplar ex = csv("redwood", "0,-1,1,0");
    const Arrangement out = synthesize_4x(ex);
    expect_no_crowding(ex, out);
    expect_no_hole(ex, out);
}

TEST(PcfDefects, AmacrineIsNotCrowdedAndHasNoHole) {  // two classes
    const Exemplar ex = csv("amacrine", "0,0,1.60121,1");
    const Arrangement out = synthesize_4x(ex);
    expect_no_crowding(ex, out);
    expect_no_hole(ex, out);
}

TEST(PcfDefects, ClusteredFourAndDropletsHaveNoHole) {
    for (const char* name : {"clustered_four.json", "droplets.json"}) {
        SCOPED_TRACE(name);
        const Exemplar ex = load(examples + name);
        expect_no_hole(ex, synthesize_4x(ex));
    }
}

// Radii spanning two orders of magnitude: without the hole closing (src/pcf/synth_holes.cpp)
// a hole several large disks wide was left (1.45x the exemplar's largest empty circle).
TEST(PcfDefects, WideRadiiHasNoHole) {
    const Exemplar ex = load(examples + "wide_radii.json");
    const Arrangement out = synthesize_4x(ex);
    expect_no_hole(ex, out);
    expect_no_crowding(ex, out);
}
