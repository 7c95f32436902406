// The pair correlation relaxation (det/pair_relaxation.hpp) on its own: a cancel reaches into
// a sweep, and a relaxed output is the same for any thread count.
#include <gtest/gtest.h>

#include "core/interrupt.hpp"
#include "det/pair_relaxation.hpp"
#include "quality_data.hpp"
#include "tessera/tessera.hpp"

using namespace tessera;

namespace {

// An unrelaxed synthesis of Poisson disks over `scale` times the exemplar's sides, and the
// relaxation's parameters for it.
struct Case {
    Exemplar ex;
    Domain domain;
    Arrangement out;
    det::Params params;
};
Case poisson_case(double scale) {
    Case c{test::example("poisson_disk_2d"), {}, {}, {}};
    c.domain = c.ex.domain.scaled(scale);
    DetOptions o;
    o.iterations = 1;
    o.relax_sweeps = 0;
    c.out = synthesize_det(c.ex, c.domain, o);
    c.params.spacing = nearest_neighbor_distances(c.ex).mean;
    c.params.radius = 2.5 * c.params.spacing;
    return c;
}

}  // namespace

TEST(PairRelaxation, ACancelStopsASweepBeforeItEnds) {
    // A sweep over a large output takes seconds: its loops check the interrupt, whose poll
    // (about every 50 ms on the caller's thread) throws here at the first chance.
    Case c = poisson_case(10.0);  // ~11,000 disks: 20 sweeps take about a second
    const det::PairRelaxation relaxation(c.ex, c.params);
    ASSERT_TRUE(relaxation.applies());
    int polls = 0, sweeps_done = 0;
    const core::Interrupt stop([&] {
        ++polls;
        throw Cancelled();
    });
    EXPECT_THROW(relaxation.relax(c.out, c.domain, {}, 20, 1, 2, [&](int) { ++sweeps_done; }, &stop), Cancelled);
    EXPECT_EQ(polls, 1);
    EXPECT_LT(sweeps_done, 20) << "the cancel waited for the end of the relaxation";
}

TEST(PairRelaxation, MovesLowerTheErrorAndAreTheSameForAnyThreadCount) {
    Case c = poisson_case(3.0);
    const det::PairRelaxation relaxation(c.ex, c.params);
    Arrangement one = c.out, two = c.out;
    const det::PairRelaxation::Report a = relaxation.relax(one, c.domain, {}, 2, 7, 1);
    const det::PairRelaxation::Report b = relaxation.relax(two, c.domain, {}, 2, 7, 2);
    EXPECT_GT(a.moves, 0);
    EXPECT_LT(a.after, a.before);
    EXPECT_EQ(a.moves, b.moves);
    ASSERT_EQ(one.elements.size(), two.elements.size());
    for (size_t e = 0; e < one.elements.size(); ++e) ASSERT_EQ(one.elements[e].position, two.elements[e].position) << e;
}
