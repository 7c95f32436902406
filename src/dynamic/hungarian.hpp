// Exact minimum-cost assignment (Kuhn's Hungarian method with row and column potentials,
// O(rows^2 x cols)) for the small cost matrices of one neighbourhood pairing (Eq. 4 pairs
// only samples of equal time offset; one group holds a handful of samples). Runs in the
// innermost loop of the search, so it works in caller-owned scratch and never allocates
// once the scratch has grown to the largest matrix.
#pragma once

#include <vector>

namespace tessera::dynamic {

struct HungarianScratch {
    std::vector<double> u, v, min_slack;
    std::vector<int> row_of_col, way;
    std::vector<char> used;
};

// `cost` is row-major rows x cols with rows <= cols. Returns the minimum total cost of
// giving every row its own column and writes the column of each row to col_of_row.
double hungarian(const double* cost, int rows, int cols, HungarianScratch& scratch, int* col_of_row);

}  // namespace tessera::dynamic
