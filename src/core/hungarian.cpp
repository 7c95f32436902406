// core/hungarian.cpp — the assignment problem by shortest augmenting paths with
// potentials (Kuhn 1955; the form with one Dijkstra-like sweep per row). Index 0 of the
// column arrays is a virtual column that holds the row being inserted.
#include "core/hungarian.hpp"

#include <algorithm>
#include <limits>

namespace tessera::core {

namespace {

void prepare(HungarianScratch& s, int rows, int cols) {
    s.u.assign(rows + 1, 0.0);
    s.v.assign(cols + 1, 0.0);
    s.row_of_col.assign(cols + 1, 0);
    s.way.assign(cols + 1, 0);
    s.min_slack.resize(cols + 1);
    s.used.resize(cols + 1);
}

// Inserts row `row` (1-based): grows an alternating tree from the virtual column until it
// reaches a free column, updating the potentials so that reduced costs stay >= 0, then
// flips the path.
void insert_row(const double* cost, int cols, int row, HungarianScratch& s) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    s.row_of_col[0] = row;
    std::fill(s.min_slack.begin(), s.min_slack.end(), inf);
    std::fill(s.used.begin(), s.used.end(), 0);
    int col = 0;
    do {
        s.used[col] = 1;
        const int r = s.row_of_col[col];
        const double* cost_row = cost + static_cast<size_t>(r - 1) * cols;
        double delta = inf;
        int next = 0;
        for (int j = 1; j <= cols; ++j) {
            if (s.used[j]) continue;
            const double slack = cost_row[j - 1] - s.u[r] - s.v[j];
            if (slack < s.min_slack[j]) s.min_slack[j] = slack, s.way[j] = col;
            if (s.min_slack[j] < delta) delta = s.min_slack[j], next = j;
        }
        for (int j = 0; j <= cols; ++j) {
            if (s.used[j]) {
                s.u[s.row_of_col[j]] += delta;
                s.v[j] -= delta;
            } else {
                s.min_slack[j] -= delta;
            }
        }
        col = next;
    } while (s.row_of_col[col] != 0);
    do {
        const int prev = s.way[col];
        s.row_of_col[col] = s.row_of_col[prev];
        col = prev;
    } while (col != 0);
}

}  // namespace

double hungarian(const double* cost, int rows, int cols, HungarianScratch& scratch, int* col_of_row) {
    if (rows == 0) return 0.0;
    prepare(scratch, rows, cols);
    for (int row = 1; row <= rows; ++row) insert_row(cost, cols, row, scratch);
    double total = 0.0;
    for (int j = 1; j <= cols; ++j) {
        const int r = scratch.row_of_col[j];
        if (r == 0) continue;
        col_of_row[r - 1] = j - 1;
        total += cost[static_cast<size_t>(r - 1) * cols + (j - 1)];
    }
    return total;
}

}  // namespace tessera::core
