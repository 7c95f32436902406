// Exact minimum-cost assignment (Kuhn's Hungarian method with row and column potentials,
// O(rows^2 x cols)) for the small cost matrices of one neighbourhood pairing: the static
// method's exact matching (det/matching.cpp) and the dynamic method's Eq. 4, which pairs only
// samples of equal time offset (dynamic/st_metric.cpp). Runs in the innermost loop of a
// search, so it works in caller-owned scratch and never allocates once the scratch has grown
// to the largest matrix. Infinite costs forbid a pair (a row must have a finite column).
#pragma once

#include <vector>

namespace tessera::core {

struct HungarianScratch {
    std::vector<double> u, v, min_slack;
    std::vector<int> row_of_col, way;
    std::vector<char> used;
};

// `cost` is row-major rows x cols with rows <= cols. Returns the minimum total cost of
// giving every row its own column and writes the column of each row to col_of_row.
double hungarian(const double* cost, int rows, int cols, HungarianScratch& scratch, int* col_of_row);

}  // namespace tessera::core
