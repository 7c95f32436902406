// Greedy pairing (the paper's heuristic) against the exact Hungarian assignment.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.hpp"
#include "det/matching.hpp"

using namespace tessera;
using namespace tessera::det;

namespace {

Params test_params() {
    Params p;
    p.spacing = 1.0;
    p.cap2 = 1.0;
    p.alpha = 1.0;
    return p;
}

NeighborEntry entry(double x, double y, int key = 0, int type = 0) {
    NeighborEntry e;
    e.offset = {x, y, 0};
    e.key = key;
    e.match_key = key * 2;
    e.type = type;
    return e;
}

// A jittered hexagonal neighbourhood of radius ~2 spacings.
std::vector<NeighborEntry> hex_neighborhood(const core::KeyedRng& rng, std::uint64_t base, double jitter) {
    std::vector<NeighborEntry> out;
    std::uint64_t c = base;
    for (int j = -3; j <= 3; ++j)
        for (int i = -3; i <= 3; ++i) {
            const double x = i + 0.5 * (j & 1), y = j * std::sqrt(3.0) / 2;
            if (x * x + y * y > 4.0 || (i == 0 && j == 0)) continue;
            const double jx = jitter * (rng.uniform(c) - 0.5), jy = jitter * (rng.uniform(c + 1) - 0.5);
            c += 2;
            out.push_back(entry(x + jx, y + jy));
        }
    return out;
}

}  // namespace

TEST(DetMatching, IdenticalNeighbourhoodsCostNothing) {
    const Params p = test_params();
    MatchScratch s;
    std::vector<NeighborEntry> a = {entry(1, 0), entry(0, 1), entry(-1, -1)};
    std::vector<int> partner(3);
    EXPECT_DOUBLE_EQ(match_greedy(a.data(), 3, a.data(), 3, p, s, partner.data(), INFINITY), 0.0);
    EXPECT_EQ(partner, (std::vector<int>{0, 1, 2}));
    EXPECT_DOUBLE_EQ(match_hungarian(a.data(), 3, a.data(), 3, p, s, partner.data()), 0.0);
}

TEST(DetMatching, UnpairedOutputSamplesCostTheCap) {
    const Params p = test_params();
    MatchScratch s;
    std::vector<NeighborEntry> out = {entry(1, 0), entry(0, 1)};
    std::vector<NeighborEntry> in = {entry(1, 0.1)};
    std::vector<int> partner(2);
    const double c = match_greedy(out.data(), 2, in.data(), 1, p, s, partner.data(), INFINITY);
    EXPECT_NEAR(c, 0.01 + p.cap2, 1e-12);
    EXPECT_EQ(partner[0], 0);
    EXPECT_EQ(partner[1], -1);
}

TEST(DetMatching, KeysSeparateSamplesOfDifferentIds) {
    const Params p = test_params();
    MatchScratch s;
    std::vector<NeighborEntry> out = {entry(1, 0, 1)};
    std::vector<NeighborEntry> in = {entry(1.5, 0, 1), entry(1, 0, 2)};  // sorted by key, as required
    std::vector<int> partner(1);
    EXPECT_NEAR(match_greedy(out.data(), 1, in.data(), 2, p, s, partner.data(), INFINITY), 0.25, 1e-12);
    EXPECT_EQ(partner[0], 0);
}

TEST(DetMatching, TypeMismatchPaysAlpha) {
    Params p = test_params();
    p.alpha = 0.3;
    MatchScratch s;
    std::vector<NeighborEntry> out = {entry(1, 0, 0, 0)};
    std::vector<NeighborEntry> in = {entry(1, 0, 0, 1)};
    EXPECT_NEAR(match_greedy(out.data(), 1, in.data(), 1, p, s, nullptr, INFINITY), 0.3, 1e-12);
}

TEST(DetMatching, GreedyCanLoseToExactOnAConstructedCase) {
    // Greedy takes the cheapest pair (a0-b0, cost 0) and leaves a1 with b1 far away;
    // the exact assignment crosses the pairs for a lower total.
    Params p = test_params();
    p.cap2 = 100.0;
    MatchScratch s;
    std::vector<NeighborEntry> out = {entry(0, 0), entry(1, 0)};
    std::vector<NeighborEntry> in = {entry(0, 0), entry(-1.2, 0)};
    const double g = match_greedy(out.data(), 2, in.data(), 2, p, s, nullptr, INFINITY);
    const double h = match_hungarian(out.data(), 2, in.data(), 2, p, s, nullptr);
    EXPECT_NEAR(g, 2.2 * 2.2, 1e-12);
    EXPECT_NEAR(h, 1.2 * 1.2 + 1.0, 1e-12);
}

TEST(DetMatching, GreedyIsCloseToExactOnJitteredLattices) {
    // The paper reports the greedy heuristic close to exhaustive pairing; measure it.
    const Params p = test_params();
    MatchScratch s;
    const core::KeyedRng rng(7, core::Purpose::test);
    double sum_greedy = 0.0, sum_exact = 0.0;
    int equal = 0;
    const int trials = 200;
    for (int t = 0; t < trials; ++t) {
        auto a = hex_neighborhood(rng, 1000u * t, 0.3);
        auto b = hex_neighborhood(rng, 1000u * t + 500, 0.3);
        const double g = match_greedy(a.data(), int(a.size()), b.data(), int(b.size()), p, s, nullptr, INFINITY);
        const double h = match_hungarian(a.data(), int(a.size()), b.data(), int(b.size()), p, s, nullptr);
        ASSERT_LE(h, g + 1e-9) << "the exact assignment can never cost more";
        sum_greedy += g;
        sum_exact += h;
        equal += std::abs(g - h) < 1e-9;
    }
    EXPECT_LT(sum_greedy / sum_exact, 1.05);
    EXPECT_GT(equal, trials / 2);
}

TEST(DetMatching, EarlyExitNeverUnderestimates) {
    const Params p = test_params();
    MatchScratch s;
    const core::KeyedRng rng(8, core::Purpose::test);
    auto a = hex_neighborhood(rng, 1, 0.4);
    auto b = hex_neighborhood(rng, 2, 0.4);
    const double full = match_greedy(a.data(), int(a.size()), b.data(), int(b.size()), p, s, nullptr, INFINITY);
    const double bounded = match_greedy(a.data(), int(a.size()), b.data(), int(b.size()), p, s, nullptr, full / 2);
    EXPECT_GE(bounded, full / 2);
}
