// tessera::Grower (include/tessera/grow.hpp): what a user of on-demand growth sees. A
// lattice keeps its order and spacing over many rings; class shares hold, a rare class
// included; growing A then B looks like growing A and B at once, without crowding or holes
// along the seam; locked elements never change; multi-sample shapes are copied whole; the
// round bound is reported; bad input is a clear error; the thread count changes nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "quality_data.hpp"
#include "tessera/error.hpp"
#include "tessera/tessera.hpp"

using namespace tessera;
using test::example;
using test::expect_no_crowding;

namespace {

// A box of the given half-size around the exemplar's centre.
Domain centred_box(const Exemplar& ex, double half) {
    const Vec3 c = ex.domain.bounds().center();
    if (ex.dimension == 2) return Domain::box(c - Vec3{half, half, 0}, c + Vec3{half, half, 0}, 2);
    return Domain::box(c - Vec3{half, half, half}, c + Vec3{half, half, half}, 3);
}

std::vector<double> type_shares(const std::vector<Element>& elements, size_t types) {
    std::vector<double> share(types, 0.0);
    for (const Element& e : elements) share[e.type] += 1.0 / static_cast<double>(elements.size());
    return share;
}

Arrangement grown(const Exemplar& ex, const Domain& region, GrowOptions o = {}) {
    Grower g(ex, o);
    const GrowReport r = g.grow(region);
    EXPECT_TRUE(r.covered) << "the region was not covered in " << r.rounds << " rounds";
    EXPECT_FALSE(r.bound_hit);
    return g.arrangement();
}

void expect_no_hole(const Exemplar& ex, const Arrangement& out, const std::string& what) {
    const double hole = largest_empty_circle(out).radius, exemplar_hole = largest_empty_circle(ex).radius;
    EXPECT_LE(hole, 1.3 * exemplar_hole) << what << ": hole " << hole << " vs the exemplar's " << exemplar_hole;
}

// A two-class exemplar with a rare class: dots on a jittered grid, one in twelve a berry.
Exemplar rare_class_exemplar() {
    Exemplar ex;
    ex.dimension = 2;
    ex.types.resize(2);
    ex.types[0].name = "dot";
    ex.types[1].name = "berry";
    ex.domain = Domain::box({0, 0, 0}, {12, 12, 0}, 2);
    std::uint64_t s = 12345;
    auto jitter = [&] {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        return (static_cast<double>(s >> 11) / 9007199254740992.0 - 0.5) * 0.3;
    };
    for (int i = 0; i < 12; ++i)
        for (int j = 0; j < 12; ++j) {
            const bool berry = (i * 5 + j * 7) % 12 == 0;
            ex.add_element(berry ? 1 : 0, {Vec3{i + 0.5 + jitter(), j + 0.5 + jitter(), 0}}, 0.3);
        }
    return ex;
}

}  // namespace

TEST(Grow, AJitteredLatticeKeepsItsOrderAndSpacingOverTwentyRings) {
    const Exemplar ex = example("hex_jittered_2d");
    const double spacing = mean_nearest_neighbor_distance(ex);
    const Arrangement out = grown(ex, centred_box(ex, 20.0 * spacing));
    EXPECT_GT(out.elements.size(), 1000u);
    EXPECT_GE(mean_psi6(out), 0.8);
    EXPECT_NEAR(mean_nearest_neighbor_distance(out), spacing, 0.05 * spacing);
    expect_no_crowding(ex, out, "hex");
    expect_no_hole(ex, out, "hex");
    EXPECT_GE(inside_fraction(out), 0.995);
}

TEST(Grow, TwoClassStripesKeepTheirSharesAndTheRegion) {
    const Exemplar ex = example("striped_dots_2d");
    const Arrangement out = grown(ex, ex.domain.scaled(std::sqrt(20.0)));
    const std::vector<double> want = type_shares(ex.elements, ex.types.size());
    const std::vector<double> got = type_shares(out.elements, ex.types.size());
    for (size_t t = 0; t < want.size(); ++t) EXPECT_NEAR(got[t], want[t], 0.05) << ex.types[t].name;
    expect_no_crowding(ex, out, "striped dots");
    EXPECT_GE(inside_fraction(out), 0.995);
}

// Disks of three sizes, the large ones 80 times the small ones' radius: the small disks'
// closest pair lies at 0.80 of their typical distance, and their hard core, which packs a
// fifth of the plane, does not hold their density. Taken as hard, patches copied at
// misaligned offsets packed them between each other: 1.5x their density, the output 1.39x.
TEST(Grow, DisksOfWidelyDifferentSizesKeepTheirDensityAndShares) {
    const Exemplar ex = example("pcf/wide_radii");
    const Domain region = ex.domain.scaled(3.0);
    const Arrangement out = grown(ex, region);
    const double want = ex.elements.size() / ex.domain.measure(), got = out.elements.size() / region.measure();
    EXPECT_NEAR(got, want, 0.1 * want);
    const std::vector<double> want_share = type_shares(ex.elements, 3), got_share = type_shares(out.elements, 3);
    for (int t = 0; t < 3; ++t)
        EXPECT_NEAR(got_share[t], want_share[t], 0.15 * want_share[t]) << ex.types[t].name;
    expect_no_crowding(ex, out, "wide radii");
}

TEST(Grow, ARareClassKeepsItsShareWithinTwentyPercent) {
    const Exemplar ex = rare_class_exemplar();
    const double want = type_shares(ex.elements, 2)[1];
    ASSERT_LT(want, 0.1);
    for (std::uint64_t seed : {1, 2}) {
        GrowOptions o;
        o.seed = seed;
        const Arrangement out = grown(ex, ex.domain.scaled(3.0), o);
        EXPECT_NEAR(type_shares(out.elements, 2)[1], want, 0.2 * want) << "seed " << seed;
        expect_no_crowding(ex, out, "rare class");
    }
}

TEST(Grow, PoissonDisksHaveNoHolesOrCrowdingAlsoAlongTheSeamOfTwoCalls) {
    const Exemplar ex = example("poisson_disk_2d");
    const Box b = ex.domain.bounds();
    const Vec3 size = b.size();
    const Domain a = Domain::box(b.lo, b.lo + Vec3{2 * size.x, 2 * size.y, 0}, 2);
    const Domain right = Domain::box(b.lo + Vec3{2 * size.x, 0, 0}, b.lo + Vec3{4 * size.x, 2 * size.y, 0}, 2);
    const Domain both = Domain::box(b.lo, b.lo + Vec3{4 * size.x, 2 * size.y, 0}, 2);
    Grower g(ex);
    g.grow(a);
    const GrowReport second = g.grow(right);
    EXPECT_TRUE(second.covered);
    EXPECT_GT(second.added, 0);
    const Arrangement seamed = g.arrangement();
    const Arrangement at_once = grown(ex, both);
    expect_no_crowding(ex, seamed, "A then B");
    expect_no_hole(ex, seamed, "A then B");
    // Within noise of growing both at once: the count and the pair correlation.
    const double n1 = static_cast<double>(seamed.elements.size()), n2 = static_cast<double>(at_once.elements.size());
    EXPECT_NEAR(n1, n2, 0.05 * n2);
    const double e1 = pcf_relative_error(ex, seamed), e2 = pcf_relative_error(ex, at_once);
    EXPECT_LT(e1, 1.3 * e2 + 0.02) << "A then B " << e1 << ", at once " << e2;
    // Around the seam (x = the boundary between A and B) specifically: no hole either.
    const double seam = b.lo.x + 2 * size.x, spacing = mean_nearest_neighbor_distance(ex);
    Arrangement strip;
    strip.dimension = 2;
    strip.types = seamed.types;
    strip.domain = Domain::box({seam - 3 * spacing, b.lo.y, 0}, {seam + 3 * spacing, b.lo.y + 2 * size.y, 0}, 2);
    for (const Element& e : seamed.elements)
        if (strip.domain.inside(e.position)) strip.add_element(e.type, {e.position}, e.radius);
    expect_no_hole(ex, strip, "seam strip");
}

TEST(Grow, TwoClassGrownTo20TimesItsAreaKeepsSharesPcfAndHolesNearSynthesizeDets) {
    const Exemplar ex = example("two_class_2d");
    const Box b = ex.domain.bounds();
    const double s = std::sqrt(20.0);
    const Domain region = Domain::box(b.lo, b.lo + Vec3{s * b.size().x, s * b.size().y, 0}, 2);
    Arrangement out = grown(ex, region);
    Arrangement det = synthesize_det(ex, region);
    out.domain = region;  // holes are measured inside the region grown
    const std::vector<double> want = type_shares(ex.elements, 2), got = type_shares(out.elements, 2);
    // Within 5% of each share (stones 0.191-0.198 of the exemplar's 0.196 over seeds 1-6;
    // 0.146-0.158 before the minority completion of grow/rare_types.hpp).
    for (int t = 0; t < 2; ++t) EXPECT_NEAR(got[t], want[t], 0.05 * want[t]) << ex.types[t].name << " share";
    const double e_grow = pcf_relative_error(ex, out), e_det = pcf_relative_error(ex, det);
    EXPECT_LT(e_grow, 1.6 * e_det + 0.02) << "grow " << e_grow << ", synthesize_det " << e_det;
    expect_no_hole(ex, out, "two class at 20x");
    expect_no_crowding(ex, out, "two class at 20x");
}

// Growth's least-squares solve draws distances towards the typical one (a first peak of g
// 1.84 against the exemplar's 1.57, error 0.116); the default sweep of the relaxation for a
// hard-core pattern brings it to 0.076-0.082 over seeds 1-4, synthesize_det's 0.033-0.039.
TEST(Grow, PoissonDisksGrownTo20TimesTheirAreaKeepTheirPairCorrelationNearSynthesizeDets) {
    const Exemplar ex = example("poisson_disk_2d");
    const Box b = ex.domain.bounds();
    const double s = std::sqrt(20.0);
    const Domain region = Domain::box(b.lo, b.lo + Vec3{s * b.size().x, s * b.size().y, 0}, 2);
    const Arrangement out = grown(ex, region), det = synthesize_det(ex, region);
    const double e_grow = pcf_relative_error(ex, out), e_det = pcf_relative_error(ex, det);
    EXPECT_LT(e_grow, 2.5 * e_det + 0.01) << "grow " << e_grow << ", synthesize_det " << e_det;
    expect_no_crowding(ex, out, "Poisson disks at 20x");
}

// A field pattern grown over 20x its window from the window's lower corner (its domain is
// the region grown), and the output's density over the exemplar's.
struct GrownField {
    Exemplar ex;
    Arrangement out;
    double density_ratio = 0.0;
};
GrownField grown_field_pattern(const std::string& name) {
    GrownField f{test::field_pattern(name), {}, 0.0};
    const Box b = f.ex.domain.bounds();
    const double s = std::sqrt(20.0);
    const Domain region = Domain::box(b.lo, b.lo + Vec3{s * b.size().x, s * b.size().y, 0}, 2);
    f.out = grown(f.ex, region);
    f.out.domain = region;
    f.density_ratio = (f.out.elements.size() / region.measure()) / (f.ex.elements.size() / f.ex.domain.measure());
    return f;
}

// The pair correlation of a grown field pattern against synthesize_det's into the same
// region: rounded coordinates put grown elements on a lattice, and growth's own steps do not
// hold a soft pattern's pair correlation (grown Japanese pines had 0.31 against 0.03, ganglia
// 0.16 against 0.04) until the rounding was undone and the final relaxation added
// (docs/grow.md).
void expect_pcf_near_det(const Exemplar& ex, const Arrangement& out, const std::string& name) {
    DetOptions o;
    o.threads = 2;
    const Arrangement det = synthesize_det(ex, out.domain, o);
    const double e_grow = pcf_relative_error(ex, out), e_det = pcf_relative_error(ex, det);
    EXPECT_LT(e_grow, 1.5 * e_det + 0.07) << name << ": PCF error " << e_grow << ", synthesize_det's " << e_det;
}

// Real patterns whose closest pair is far under their typical spacing (retinal mosaics of
// two independent-looking classes, near-random pines): the hard core does not hold their
// density, so a horizon element's patch fills only its own Voronoi cell. Without it, these
// grew at 2x (ganglia) to 12x (japanesepines) their density.
TEST(Grow, SoftRealPatternsKeepTheirDensityAndClassSharesAt20TimesTheirWindow) {
    for (const std::string name : {"amacrine", "ganglia", "japanesepines"}) {
        const auto [ex, out, ratio] = grown_field_pattern(name);
        EXPECT_NEAR(ratio, 1.0, 0.1) << name << ": " << out.elements.size() << " elements";
        const size_t types = ex.types.size();
        const std::vector<double> want_share = type_shares(ex.elements, types),
                                  got_share = type_shares(out.elements, types);
        for (size_t t = 0; t < types; ++t)
            EXPECT_NEAR(got_share[t], want_share[t], 0.05 * want_share[t]) << name << " " << ex.types[t].name;
        expect_no_crowding(ex, out, name);
        expect_pcf_near_det(ex, out, name);
    }
}

// A random pattern's holes run into each other and into the region's edge, where no hole is
// enclosed: grown Japanese pines (23x their window, seeds 1 to 3) kept holes of 1.28x to 1.41x
// the exemplar's largest along the region's edge. In a covered region every hole over 1.25x
// the exemplar's is filled.
TEST(Grow, ARandomPatternLeavesNoHoleAlongTheRegionsEdge) {
    const Exemplar ex = test::field_pattern("japanesepines");
    const Box b = ex.domain.bounds();
    const Domain region = Domain::box(b.lo, b.lo + Vec3{4.8 * b.size().x, 4.8 * b.size().y, 0}, 2);
    for (const std::uint64_t seed : {1, 2, 3}) {
        GrowOptions o;
        o.seed = seed;
        const Arrangement out = grown(ex, region, o);
        const double hole = largest_empty_circle(out).radius, exemplar_hole = largest_empty_circle(ex).radius;
        EXPECT_LE(hole, 1.3 * exemplar_hole) << "seed " << seed << ": hole " << hole;
        EXPECT_NEAR(out.elements.size() / (23.04 * ex.elements.size()), 1.0, 0.1) << "seed " << seed;
    }
}

// Field patterns whose closest pairs are far under their spacing but that are regular at a
// few spacings (Swedish pines, cells, anemones): neither the hard core nor the Voronoi
// ownership holds their density, the count ceiling does most of it (without it, Swedish
// pines and anemones grew at 1.4x; with it they and cells grew at 1.08x to 1.15x), and the
// covered region's surplus is thinned out where it is most crowded (grow/thinning.hpp,
// docs/grow.md) without opening a hole.
TEST(Grow, InhibitedRealPatternsKeepTheirDensityUnderTheCountCeiling) {
    for (const std::string name : {"swedishpines", "cells", "anemones"}) {
        const auto [ex, out, ratio] = grown_field_pattern(name);
        EXPECT_NEAR(ratio, 1.0, 0.04) << name << ": " << out.elements.size() << " elements";
        expect_no_crowding(ex, out, name);
        expect_no_hole(ex, out, name);  // inside the region grown
        expect_pcf_near_det(ex, out, name);
    }
}

// A clustered pattern (redwood seedlings: tight clusters, wide gaps): the horizon's patches
// do not reach across the gaps, so the paper's rounds stop after a few clusters; the rest
// of the region is filled next to them (grow/uncovered.hpp) and the whole region holds
// clusters at the exemplar's density, with no hole or crowding beyond the exemplar's.
TEST(Grow, AClusteredPatternFillsItsWholeRegionWhereTheHorizonStops) {
    const Exemplar ex = test::field_pattern("redwood");
    const Box b = ex.domain.bounds();
    const double s = std::sqrt(20.0);
    const Domain region = Domain::box(b.lo, b.lo + Vec3{s * b.size().x, s * b.size().y, 0}, 2);
    const double expected = 20.0 * ex.elements.size();

    GrowOptions paper;
    paper.stop_at_horizon = true;
    Grower stopped(ex, paper);
    stopped.grow(region);
    EXPECT_LT(stopped.arrangement().elements.size(), 0.5 * expected) << "the horizon alone covered the region";

    Grower g(ex);
    const GrowReport r = g.grow(region);
    Arrangement out = g.arrangement();
    out.domain = region;
    EXPECT_GT(r.uncovered, 0);
    EXPECT_NEAR(out.elements.size() / expected, 1.0, 0.1);
    for (const Element& e : out.elements) {
        EXPECT_FALSE(e.locked) << "a filled element is locked in the output";
        EXPECT_TRUE(region.inside(e.position));
    }
    expect_no_crowding(ex, out, "redwood");
    expect_no_hole(ex, out, "redwood");
    DetOptions det_options;
    det_options.threads = 2;
    const Arrangement det = synthesize_det(ex, region, det_options);
    EXPECT_LT(pcf_relative_error(ex, out), 2.0 * pcf_relative_error(ex, det)) << "clusters lost";
}

TEST(Grow, TwoClassGrownInTwoCallsMatchesOneCallInSharesAndPcf) {
    const Exemplar ex = example("two_class_2d");
    const Box b = ex.domain.bounds();
    const Vec3 size = b.size();
    const Domain left = Domain::box(b.lo, b.lo + Vec3{2 * size.x, 3 * size.y, 0}, 2);
    const Domain right = Domain::box(b.lo + Vec3{2 * size.x, 0, 0}, b.lo + Vec3{4 * size.x, 3 * size.y, 0}, 2);
    Grower g(ex);
    g.grow(left);
    g.grow(right);
    const Arrangement seamed = g.arrangement();
    const Arrangement at_once = grown(ex, Domain::box(b.lo, b.lo + Vec3{4 * size.x, 3 * size.y, 0}, 2));
    const std::vector<double> s1 = type_shares(seamed.elements, 2), s2 = type_shares(at_once.elements, 2);
    EXPECT_NEAR(s1[0], s2[0], 0.03);
    EXPECT_LT(pcf_relative_error(ex, seamed), 1.3 * pcf_relative_error(ex, at_once) + 0.02);
    expect_no_crowding(ex, seamed, "two class A then B");
}

TEST(Grow, LockedElementsAreBitIdenticalAfterGrowthAndSynthesis) {
    const Exemplar ex = example("two_class_2d");
    Arrangement start = synthesize_det(ex, ex.domain);
    for (Element& e : start.elements) e.locked = true;
    Grower g(ex);
    g.set_arrangement(start);
    g.grow(ex.domain.scaled(2.5));
    g.grow(ex.domain.scaled(3.0));
    Arrangement out = g.arrangement();
    EXPECT_GT(out.elements.size(), 3 * start.elements.size());
    std::map<std::uint64_t, const Element*> by_id;
    for (const Element& e : out.elements) by_id[e.id] = &e;
    auto expect_same = [&](const Arrangement& after, const std::string& what) {
        std::map<std::uint64_t, const Element*> now;
        for (const Element& e : after.elements) now[e.id] = &e;
        for (const Element& a : start.elements) {
            ASSERT_TRUE(now.count(a.id)) << what << ": element " << a.id << " is gone";
            const Element& b = *now[a.id];
            EXPECT_EQ(a.type, b.type) << what;
            EXPECT_TRUE(b.locked) << what;
            EXPECT_TRUE(a.position.x == b.position.x && a.position.y == b.position.y) << what << " element " << a.id;
            for (int s = 0; s < a.sample_count; ++s) {
                const Vec3& p = start.samples[a.first_sample + s].p;
                const Vec3& q = after.samples[b.first_sample + s].p;
                EXPECT_TRUE(p.x == q.x && p.y == q.y) << what << " element " << a.id << " sample " << s;
            }
        }
    };
    expect_same(out, "after growth");
    // A synthesis session over the grown arrangement leaves them too.
    DetSession session(ex);
    session.set_arrangement(out);
    session.iterate(out.domain, 3);
    session.finish();
    expect_same(session.arrangement(), "after synthesis");
}

TEST(Grow, MultiSampleElementsKeepTheirShapeAndDoNotCross) {
    const Exemplar ex = example("sticks_2d");
    const Arrangement out = grown(ex, ex.domain.scaled(2.0));
    EXPECT_GT(out.elements.size(), 2 * ex.elements.size());
    // Every element is a rigid copy of an exemplar element of its type: the same lengths
    // between consecutive samples.
    std::vector<double> length(ex.types.size(), 0.0);
    for (const Element& e : ex.elements)
        length[e.type] = norm(ex.samples[e.first_sample + 1].p - ex.samples[e.first_sample].p);
    for (const Element& e : out.elements) {
        const double l = norm(out.samples[e.first_sample + 1].p - out.samples[e.first_sample].p);
        EXPECT_NEAR(l, length[e.type], 0.35 * length[e.type]);
    }
    expect_no_crowding(ex, out, "sticks");
    EXPECT_GE(inside_fraction(out), 0.995);
}

// Deformable noodles of 8 samples, which touch easily where patches meet: a touching
// candidate takes another noodle's shape that fits, so the density holds (it was 75% when
// every touching candidate was dropped); no two noodles cross. Where no candidate's shape
// fitted, a place emptier than the exemplar's largest empty circle (against samples) gets a
// noodle of a shape that fits it (grow/sample_holes.hpp): such places were 1.7x the
// exemplar's, now under 1.5x.
TEST(Grow, NoodlesKeepMostOfTheirDensityWithoutCrossingOrHoles) {
    const Exemplar ex = example("noodles_2d");
    const Box b = ex.domain.bounds();
    const double s = 5.0;
    const Domain region = Domain::box(b.lo, b.lo + Vec3{s * b.size().x, s * b.size().y, 0}, 2);
    Arrangement out = grown(ex, region);
    const double density = out.elements.size() / region.measure(), want = ex.elements.size() / ex.domain.measure();
    EXPECT_GT(density, 0.84 * want) << out.elements.size() << " noodles";
    expect_no_crowding(ex, out, "noodles");
    EXPECT_GE(inside_fraction(out), 0.995);
    out.domain = region;
    const double hole = largest_empty_circle(out).radius, exemplar_hole = largest_empty_circle(ex).radius;
    EXPECT_LT(hole, 1.5 * exemplar_hole) << "hole " << hole << " vs the exemplar's " << exemplar_hole;
}

// Rods in a slab fit many orientations: a candidate that touches others takes another rod's
// orientation only where the place and its neighbours hold fewer rods within r than the
// exemplar's crowded ones (without that check they grew at 1.64x the exemplar's density),
// and the rounds still left them at 1.18x (1.25x inside) until the thinning of a covered
// region took multi-sample elements too; removing a rod must not open a hole.
TEST(Grow, ThreeDimensionalRodsKeepTheirDensityWithoutHoles) {
    const Exemplar ex = example("rods_3d");
    const Box b = ex.domain.bounds();
    const Domain region = Domain::box(b.lo, b.lo + Vec3{5 * b.size().x, 5 * b.size().y, b.size().z}, 3);
    Arrangement out = grown(ex, region);
    const double ratio = (out.elements.size() / region.measure()) / (ex.elements.size() / ex.domain.measure());
    EXPECT_GT(ratio, 0.95);
    EXPECT_LT(ratio, 1.06) << out.elements.size() << " rods";
    out.domain = region;
    const double hole = largest_empty_circle(out).radius, exemplar_hole = largest_empty_circle(ex).radius;
    EXPECT_LT(hole, 1.35 * exemplar_hole) << "hole " << hole << " vs the exemplar's " << exemplar_hole;
    expect_no_crowding(ex, out, "rods");
}

// A dense random packing of spheres (packing fraction 0.53) is denser than growth packs one
// element after another (random sequential adsorption jams at 0.38): the rounds left 0.79
// of the exemplar's density inside the region and holes the size of a sphere; the packing's
// completion pushes the missing spheres in (grow/rare_types.hpp).
TEST(Grow, AJammedSpherePackingIsGrownToTheExemplarsDensity) {
    const Exemplar ex = example("spheres_3d");
    const Box b = ex.domain.bounds();
    const Domain region = Domain::box(b.lo, b.lo + b.size() * 2.0, 3);
    Arrangement out = grown(ex, region);
    const double density = ex.elements.size() / ex.domain.measure();
    EXPECT_GT(out.elements.size(), 0.95 * density * region.measure());
    EXPECT_LT(out.elements.size(), 1.05 * density * region.measure());
    const Vec3 margin{1.0, 1.0, 1.0};  // a sphere's diameter in from the walls
    const Vec3 lo = region.bounds().lo + margin, hi = region.bounds().hi - margin;
    int inside = 0;
    for (const Element& e : out.elements)
        inside += e.position.x >= lo.x && e.position.y >= lo.y && e.position.z >= lo.z && e.position.x < hi.x &&
                  e.position.y < hi.y && e.position.z < hi.z;
    const Vec3 size = hi - lo;
    EXPECT_GT(inside / (size.x * size.y * size.z), 0.88 * density) << inside << " spheres inside";
    out.domain = region;
    const double hole = largest_empty_circle(out).radius, exemplar_hole = largest_empty_circle(ex).radius;
    EXPECT_LT(hole, 1.12 * exemplar_hole) << "hole " << hole << " vs the exemplar's " << exemplar_hole;
    expect_no_crowding(ex, out, "spheres");
}

TEST(Grow, ThreeDimensionalRodsStayInsideTheirRegion) {
    const Exemplar ex = example("rods_3d");
    const Domain region = ex.domain.scaled(1.6);
    const Arrangement out = grown(ex, region);
    EXPECT_GT(out.elements.size(), 2 * ex.elements.size());
    for (const Sample& s : out.samples) EXPECT_TRUE(region.inside(s.p)) << s.p.x << " " << s.p.y << " " << s.p.z;
    expect_no_crowding(ex, out, "rods");
}

// The bilayer of examples/membrane_3d.json: as many lipids per leaflet as the exemplar has
// per area, every head on its leaflet's outer side (centroids alone cannot tell a lipid
// from a flipped one), the small molecules (the rare class) in proportion.
TEST(Grow, AMembraneKeepsItsLeafletsAndItsSmallMolecules) {
    const Exemplar ex = example("membrane_3d");
    const Box b = ex.domain.bounds();
    const Domain region = Domain::box(b.lo, b.lo + Vec3{2 * b.size().x, 2 * b.size().y, b.size().z}, 3);
    const Arrangement out = grown(ex, region);
    const double mid = b.center().z;
    const int lipid = ex.find_type("lipid"), molecule = ex.find_type("molecule");
    auto count = [](const std::vector<Element>& elements, int type) {
        return static_cast<double>(std::count_if(elements.begin(), elements.end(), [&](const Element& e) { return e.type == type; }));
    };
    EXPECT_NEAR(count(out.elements, lipid), 4.0 * count(ex.elements, lipid), 0.1 * 4.0 * count(ex.elements, lipid));
    int flipped = 0;
    for (const Element& e : out.elements) {
        if (e.type != lipid) continue;
        const double head = out.samples[e.first_sample].p.z, centre = e.position.z;
        flipped += (head - centre) * (centre - mid) < 0.0;
    }
    EXPECT_LE(flipped, static_cast<int>(0.01 * count(out.elements, lipid)));
    const double want = count(ex.elements, molecule) / ex.elements.size();
    EXPECT_NEAR(count(out.elements, molecule) / out.elements.size(), want, 0.2 * want);
    for (const Sample& s : out.samples) EXPECT_TRUE(region.inside(s.p));
    expect_no_crowding(ex, out, "membrane");
}

// Lipids of a grown membrane whose head lies off both planes the exemplar's heads lie on.
int lipid_heads_off_their_planes(const Exemplar& ex, const Arrangement& out) {
    const int lipid = ex.find_type("lipid");
    double head_lo = 1e300, head_hi = -1e300;
    for (const Element& e : ex.elements)
        if (e.type == lipid) {
            const double z = ex.samples[e.first_sample].p.z;
            head_lo = std::min(head_lo, z), head_hi = std::max(head_hi, z);
        }
    int off = 0;
    for (const Element& e : out.elements) {
        if (e.type != lipid) continue;
        const double z = out.samples[e.first_sample].p.z;
        off += std::min(std::abs(z - head_lo), std::abs(z - head_hi)) > 0.2;
    }
    return off;
}

// Every seed grows a whole membrane: the seed copies the layer's whole thickness (a lipid's
// patch never reaches the other leaflet) and every element stays on the layer (offsets
// copied lipid to lipid drifted, and membranes grew stacked and crowded). Before, only the
// exemplar's central channel had a whole patch, and every seed grew the same membrane.
// The channel proteins (3 of its 177 elements, each spanning both leaflets) are proposed
// only where a match's patch holds one, and mostly land on lipids other patches put there:
// the rounds alone grew 55% to 76% of their share. A rare type short of its share is
// completed once the region is covered (grow/rare_types.hpp), each channel taking the place
// of the lipids it overlaps and the ring around it grown again: within 20% for every seed.
TEST(Grow, EverySeedGrowsAWholeMembraneWithItsChannelProteinsShare) {
    const Exemplar ex = example("membrane_3d");
    const Box b = ex.domain.bounds();
    const Domain region = Domain::box(b.lo, b.lo + Vec3{3 * b.size().x, 3 * b.size().y, b.size().z}, 3);
    const int lipid = ex.find_type("lipid"), channel = ex.find_type("channel");
    auto count = [](const std::vector<Element>& elements, int type) {
        return static_cast<double>(std::count_if(elements.begin(), elements.end(), [&](const Element& e) { return e.type == type; }));
    };
    std::set<size_t> sizes;
    for (const std::uint64_t seed : {1, 2, 3}) {
        GrowOptions o;
        o.seed = seed;
        const Arrangement out = grown(ex, region, o);
        sizes.insert(out.elements.size());
        EXPECT_NEAR(count(out.elements, lipid), 9.0 * count(ex.elements, lipid), 0.05 * 9.0 * count(ex.elements, lipid))
            << "seed " << seed;
        EXPECT_EQ(lipid_heads_off_their_planes(ex, out), 0) << "seed " << seed;
        for (const Sample& s : out.samples) EXPECT_TRUE(region.inside(s.p));
        expect_no_crowding(ex, out, "membrane");
        const double want = count(ex.elements, channel) / ex.elements.size();
        EXPECT_NEAR(count(out.elements, channel) / out.elements.size(), want, 0.2 * want) << "seed " << seed;
    }
    EXPECT_EQ(sizes.size(), 3u) << "the seeds grew the same membrane";
}

// Growth next to an existing membrane (a later call, a world's later tile) finds the
// layer's depth from the existing elements: without it, offsets copied lipid to lipid
// drifted, and 40 of about 600 new lipids had their heads off the leaflets' planes.
TEST(Grow, GrowthNextToAnExistingMembraneKeepsItsLeaflets) {
    const Exemplar ex = example("membrane_3d");
    const Box b = ex.domain.bounds();
    const Vec3 size = b.size();
    Grower first(ex);
    first.grow(Domain::box(b.lo, b.lo + Vec3{2 * size.x, 2 * size.y, size.z}, 3));
    Grower next(ex);
    next.set_arrangement(first.arrangement());
    const Domain beside = Domain::box(b.lo + Vec3{2 * size.x, 0, 0}, b.lo + Vec3{4 * size.x, 2 * size.y, size.z}, 3);
    next.grow(beside);
    const Arrangement out = next.arrangement();
    EXPECT_EQ(lipid_heads_off_their_planes(ex, out), 0);
    const int lipid = ex.find_type("lipid");
    double grown = 0.0, wanted = 0.0;
    for (const Element& e : out.elements) grown += e.type == lipid && beside.inside(e.position);
    for (const Element& e : ex.elements) wanted += 4.0 * (e.type == lipid);
    EXPECT_NEAR(grown, wanted, 0.1 * wanted);
    expect_no_crowding(ex, out, "membrane beside a membrane");
}

TEST(Grow, GrowByACountAndStepOutward) {
    const Exemplar ex = example("poisson_disk_2d");
    Grower g(ex);
    const GrowReport r = g.grow(500);
    EXPECT_NEAR(static_cast<double>(g.arrangement().elements.size()), 500.0, 60.0);
    EXPECT_GE(r.added, 400);
    const size_t before = g.arrangement().elements.size();
    const GrowReport s = g.step();
    EXPECT_EQ(s.rounds, 1);
    EXPECT_GT(g.arrangement().elements.size(), before);
    EXPECT_FALSE(g.horizon().empty());
    expect_no_crowding(ex, g.arrangement(), "count and step");
}

TEST(Grow, TheRoundBoundIsReported) {
    const Exemplar ex = example("poisson_disk_2d");
    GrowOptions o;
    o.max_rounds = 2;
    Grower g(ex, o);
    const GrowReport r = g.grow(ex.domain.scaled(6.0));
    EXPECT_TRUE(r.bound_hit);
    EXPECT_FALSE(r.covered);
    EXPECT_EQ(r.rounds, 2);
}

TEST(Grow, TheTreeSearchChoiceGrowsACleanPattern) {
    const Exemplar ex = example("two_class_2d");
    GrowOptions o;
    o.choice = GrowChoice::mcts;
    const Arrangement out = grown(ex, ex.domain.scaled(2.0), o);
    EXPECT_GT(out.elements.size(), 3 * ex.elements.size());
    expect_no_crowding(ex, out, "mcts");
    EXPECT_GE(inside_fraction(out), 0.995);
}

TEST(Grow, TheSameSeedGivesTheSameArrangementForAnyThreadCount) {
    const Exemplar ex = example("two_class_2d");
    std::vector<Arrangement> outs;
    for (int threads : {1, 2, 3}) {
        GrowOptions o;
        o.threads = threads;
        o.seed = 7;
        outs.push_back(grown(ex, ex.domain.scaled(2.0), o));
    }
    for (size_t k = 1; k < outs.size(); ++k) {
        ASSERT_EQ(outs[k].samples.size(), outs[0].samples.size());
        for (size_t s = 0; s < outs[0].samples.size(); ++s) {
            EXPECT_EQ(outs[k].samples[s].p.x, outs[0].samples[s].p.x);
            EXPECT_EQ(outs[k].samples[s].p.y, outs[0].samples[s].p.y);
        }
    }
}

TEST(Grow, TheSeedPatchCountsAsAddedAndAStepIsTimed) {
    const Exemplar ex = example("poisson_disk_2d");
    Grower g(ex);
    const GrowReport first = g.grow(centred_box(ex, 6.0));
    EXPECT_EQ(first.added, static_cast<int>(g.arrangement().elements.size()));
    Grower s(ex);
    const GrowReport step = s.step();
    EXPECT_EQ(step.added, static_cast<int>(s.arrangement().elements.size()));
    EXPECT_GT(step.seconds, 0.0);
    EXPECT_EQ(s.last_report().added, step.added);
}

// A cancel is polled inside rounds: a 3D growth on one thread (by round 22, rounds of about
// 0.2 s) stops within about 0.1 s of the request (0.15 s allowed here), its report up to the
// last finished round is kept, and the arrangement stays valid.
// A cancel at any point of a call, the minority completion's regrowth included (it holds the
// stones it squeezed in locked while the room around them is regrown), leaves no element
// locked that the caller did not lock.
TEST(Grow, ACancelAnywhereLeavesNoElementLocked) {
    const Exemplar ex = example("two_class_2d");
    const Box b = ex.domain.bounds();
    const Domain region = Domain::box(b.lo, b.lo + Vec3{3 * b.size().x, 3 * b.size().y, 0}, 2);
    GrowOptions o;
    o.threads = 1;
    int events = 0;
    {
        Grower whole(ex, o);
        whole.set_progress([&](const ProgressEvent&) { return ++events > 0; });
        ASSERT_GT(whole.grow(region).rare, 0) << "the case must squeeze stones in";
    }
    int cancelled = 0;
    for (int stop_at = 1; stop_at < events; stop_at += std::max(1, events / 40)) {
        Grower g(ex, o);
        int seen = 0;
        g.set_progress([&](const ProgressEvent&) { return ++seen < stop_at; });
        try {
            g.grow(region);
        } catch (const Cancelled&) {
            ++cancelled;
        }
        for (const Element& e : g.arrangement().elements) ASSERT_FALSE(e.locked) << "cancelled at event " << stop_at;
    }
    EXPECT_GT(cancelled, 10);
}

TEST(Grow, ACancelTakesEffectWithinARoundAndKeepsTheReport) {
    const Exemplar ex = example("rods_3d");
    GrowOptions o;
    o.threads = 1;
    Grower g(ex, o);
    std::atomic<bool> stop{false};
    std::atomic<int> rounds_seen{0};
    int repeats = 0;  // events re-sent inside a round (the polls)
    g.set_progress([&](const ProgressEvent& e) {
        if (e.stage == "round" && e.iteration + 1 == rounds_seen) ++repeats;
        if (e.stage == "round") rounds_seen = std::max(rounds_seen.load(), e.iteration + 1);
        return !stop.load();
    });
    Box b = ex.domain.bounds();
    for (int k = 0; k < 2; ++k) b.hi[k] = b.lo[k] + 12.0 * (b.hi[k] - b.lo[k]);  // ~20,000 rods
    std::chrono::steady_clock::time_point asked;
    std::thread timer([&] {
        while (rounds_seen < 22) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        std::this_thread::sleep_for(std::chrono::milliseconds(40));  // inside the next round
        asked = std::chrono::steady_clock::now();
        stop = true;
    });
    EXPECT_THROW(g.grow(Domain::box(b.lo, b.hi, 3)), Cancelled);
    const auto stopped = std::chrono::steady_clock::now();
    timer.join();
    const double latency = std::chrono::duration<double>(stopped - asked).count();
    EXPECT_LT(latency, 0.15);
    EXPECT_GT(repeats, 5) << "the cancel is polled inside rounds";
    const GrowReport& r = g.last_report();
    EXPECT_GE(r.rounds, 22);
    EXPECT_FALSE(r.covered);
    const Arrangement& a = g.arrangement();
    std::set<std::uint64_t> ids;
    for (const Element& e : a.elements) ids.insert(e.id);
    EXPECT_EQ(ids.size(), a.elements.size()) << "element ids are unique after a cancel";
    EXPECT_FALSE(g.horizon().empty());
    for (const int h : g.horizon()) EXPECT_LT(h, static_cast<int>(a.elements.size()));
    stop = false;
    const size_t before = a.elements.size();
    EXPECT_GT(g.grow(200).added, 0) << "growth goes on after a cancel";
    EXPECT_GT(g.arrangement().elements.size(), before);
}

TEST(Grow, BadInputIsAClearError) {
    const Exemplar ex = example("two_class_2d");
    auto kind_of = [](auto&& call) {
        try {
            call();
        } catch (const Error& e) {
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
            return e.kind();
        }
        ADD_FAILURE() << "no error";
        return ErrorKind::io;
    };
    EXPECT_EQ(kind_of([&] { Grower(ex).grow(Domain::box({0, 0, 0}, {0, 5, 0}, 2)); }), ErrorKind::domain);
    EXPECT_EQ(kind_of([&] { Grower(ex).grow(0); }), ErrorKind::option);
    EXPECT_EQ(kind_of([&] {
                  Grower g(ex);
                  g.grow(ex.domain);
                  g.grow(Domain::box({100, 100, 0}, {110, 110, 0}, 2));
              }),
              ErrorKind::input);
    EXPECT_EQ(kind_of([&] {
                  Arrangement other = synthesize_det(example("poisson_disk_2d"), example("poisson_disk_2d").domain);
                  Grower(ex).set_arrangement(other);
              }),
              ErrorKind::input);
    EXPECT_EQ(kind_of([&] {
                  GrowOptions o;
                  o.energy_factor = 0.0;
                  Grower(ex, o);
              }),
              ErrorKind::option);
    EXPECT_EQ(kind_of([&] { Grower(ex).grow(example("rods_3d").domain); }), ErrorKind::domain);
}
