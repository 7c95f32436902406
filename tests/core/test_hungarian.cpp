// The exact assignment against brute force over every injection of rows into columns.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <vector>

#include "core/rng.hpp"
#include "core/hungarian.hpp"

namespace {

using tessera::core::hungarian;
using tessera::core::HungarianScratch;

// Minimum over all ways to give each row its own column (columns permuted, first `rows` used).
double brute_force(const std::vector<double>& cost, int rows, int cols) {
    std::vector<int> perm(cols);
    std::iota(perm.begin(), perm.end(), 0);
    double best = std::numeric_limits<double>::infinity();
    do {
        double sum = 0.0;
        for (int r = 0; r < rows; ++r) sum += cost[r * cols + perm[r]];
        best = std::min(best, sum);
    } while (std::next_permutation(perm.begin(), perm.end()));
    return best;
}

TEST(Hungarian, MatchesBruteForceOnRandomMatrices) {
    const tessera::core::KeyedRng rng(7, tessera::core::Purpose::test);
    HungarianScratch scratch;
    std::uint64_t counter = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const int rows = 1 + static_cast<int>(rng.below(counter++, 5));
        const int cols = rows + static_cast<int>(rng.below(counter++, 3));
        std::vector<double> cost(rows * cols);
        // Small integers make ties common: the optimum value must still be exact.
        for (double& c : cost) c = static_cast<double>(rng.below(counter++, trial % 2 ? 4 : 1000));
        std::vector<int> col(rows, -1);
        const double total = hungarian(cost.data(), rows, cols, scratch, col.data());
        EXPECT_DOUBLE_EQ(total, brute_force(cost, rows, cols)) << "trial " << trial;
        // The columns are distinct and their costs add up to the total.
        std::vector<int> sorted = col;
        std::sort(sorted.begin(), sorted.end());
        EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());
        double sum = 0.0;
        for (int r = 0; r < rows; ++r) sum += cost[r * cols + col[r]];
        EXPECT_DOUBLE_EQ(sum, total);
    }
}

TEST(Hungarian, PrefersTheGlobalOptimumOverTheGreedyChoice) {
    // Greedy takes (0,0) = 1 and is left with (1,1) = 100; the optimum is 2 + 3.
    const std::vector<double> cost = {1, 2, 3, 100};
    HungarianScratch scratch;
    int col[2];
    EXPECT_DOUBLE_EQ(hungarian(cost.data(), 2, 2, scratch, col), 5.0);
    EXPECT_EQ(col[0], 1);
    EXPECT_EQ(col[1], 0);
}

}  // namespace
