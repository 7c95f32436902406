// The crowding repair (core/crowding_repair.hpp): the output's closest pairs are held to
// the exemplar's lower tail of nearest-neighbour distances, per ordered type pair.
#include <gtest/gtest.h>

#include <cmath>

#include "core/crowding_repair.hpp"
#include "core/rng.hpp"
#include "tessera/metrics.hpp"

using namespace tessera;

namespace {

// A jittered square lattice of spacing 1 (hard core about 0.6) in a w x w box.
Exemplar jittered_lattice(int w, std::uint64_t seed) {
    Exemplar ex;
    ex.dimension = 2;
    ex.domain = Domain::box({0, 0, 0}, {double(w), double(w), 0}, 2);
    const int t = ex.type_index("dot");
    const core::KeyedRng rng(seed, core::Purpose::test);
    std::uint64_t c = 0;
    for (int y = 0; y < w; ++y)
        for (int x = 0; x < w; ++x, c += 2)
            ex.add_element(t, {{x + 0.5 + 0.4 * (rng.uniform(c) - 0.5), y + 0.5 + 0.4 * (rng.uniform(c + 1) - 0.5), 0}});
    return ex;
}

double closest_pair(const Exemplar& data) {
    double best = INFINITY;
    for (size_t i = 0; i < data.elements.size(); ++i)
        for (size_t j = i + 1; j < data.elements.size(); ++j)
            best = std::min(best, norm(data.elements[i].position - data.elements[j].position));
    return best;
}

}  // namespace

TEST(CrowdingRepair, DuplicatesAreSeparatedToTheExemplarsClosestDistances) {
    const Exemplar ex = jittered_lattice(10, 1);
    // 24 duplicates (one exactly coincident, the others up to 0.3 away) of lattice elements
    // whose right-hand neighbour is missing: there is room for them, as at a patch seam.
    const Exemplar lattice = jittered_lattice(20, 2);
    Exemplar out;
    out.dimension = 2;
    out.domain = lattice.domain;
    out.types = lattice.types;
    std::vector<char> duplicated(lattice.elements.size(), 0), removed(lattice.elements.size(), 0);
    for (int k = 0; k < 24; ++k) duplicated[k * 16 + 21] = 1, removed[k * 16 + 22] = 1;
    for (size_t i = 0; i < lattice.elements.size(); ++i) {
        if (removed[i]) continue;
        out.add_element(0, {lattice.elements[i].position});
        if (duplicated[i]) out.add_element(0, {lattice.elements[i].position + Vec3{0.0125 * (i % 25), 0.0, 0.0}});
    }
    ASSERT_LT(closest_pair(out), 1e-9);
    const core::CrowdingBounds tails(ex);
    const core::CrowdingRepairReport report = core::repair_crowding(out, out.domain, tails);
    EXPECT_FALSE(report.bound_hit);
    EXPECT_EQ(report.remaining, 0);
    EXPECT_GE(closest_pair(out), 0.95 * tails.hard_core(0, 0));
    for (const CrowdingPair& c : crowding(ex, out)) EXPECT_LE(c.output_share, 1.5 * c.exemplar_share) << c.name_a;
    for (const Sample& s : out.samples) EXPECT_TRUE(out.domain.inside(s.p));
}

TEST(CrowdingRepair, AFaithfulCopyAndLockedElementsAreLeftAlone) {
    // A clustered exemplar: its close pairs are legitimate, so a copy of it is not touched.
    Exemplar ex;
    ex.dimension = 2;
    ex.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    const core::KeyedRng rng(5, core::Purpose::test);
    std::uint64_t c = 0;
    for (int k = 0; k < 12; ++k) {
        const Vec3 centre{1 + 8 * rng.uniform(c), 1 + 8 * rng.uniform(c + 1), 0};
        c += 2;
        for (int m = 0; m < 6; ++m, c += 2)
            ex.add_element(ex.type_index("seedling"),
                           {centre + Vec3{0.6 * (rng.uniform(c) - 0.5), 0.6 * (rng.uniform(c + 1) - 0.5), 0}});
    }
    Exemplar copy = ex;
    const core::CrowdingBounds tails(ex);
    EXPECT_EQ(core::repair_crowding(copy, copy.domain, tails).moved, 0);
    // A locked element is never moved, even when it is the crowded one.
    Exemplar out = jittered_lattice(10, 3);
    const Exemplar lattice = jittered_lattice(10, 4);
    out.add_element(0, {out.elements[40].position + Vec3{0.05, 0, 0}});
    out.elements.back().locked = true;
    const Vec3 locked_at = out.elements.back().position;
    const core::CrowdingBounds lattice_tails(lattice);
    core::repair_crowding(out, out.domain, lattice_tails);
    EXPECT_EQ(out.elements.back().position, locked_at);
    EXPECT_GE(norm(out.elements[40].position - locked_at), 0.95 * lattice_tails.hard_core(0, 0));
}

TEST(CrowdingRepair, CoincidentPairsTheExemplarHasAreKeptInProportion) {
    // 5% of the exemplar's elements sit on top of another one: an output with the same share
    // keeps them, one with five times the share loses the excess.
    Exemplar ex = jittered_lattice(20, 6);
    for (int k = 0; k < 10; ++k) ex.add_element(0, {ex.elements[k * 37].position});
    const core::CrowdingBounds tails(ex);
    EXPECT_EQ(tails.centroids.quantile(0, 0, 0.01), 0.0);
    Exemplar out = jittered_lattice(20, 7);
    for (int k = 0; k < 50; ++k) out.add_element(0, {out.elements[k * 7].position});
    core::repair_crowding(out, out.domain, tails);
    int coincident = 0;  // elements with a neighbour at distance 0
    for (size_t i = 0; i < out.elements.size(); ++i)
        for (size_t j = 0; j < out.elements.size(); ++j)
            if (i != j && norm(out.elements[i].position - out.elements[j].position) < 1e-12) {
                ++coincident;
                break;
            }
    // The exemplar has 20 of 410 elements with a coincident neighbour; the output may keep
    // up to slack (1.25) times that share of its 450, and keeps some.
    EXPECT_LE(coincident, static_cast<int>(1.25 * 20.0 / 410.0 * 450.0) + 1);
    EXPECT_GT(coincident, 0);
}
