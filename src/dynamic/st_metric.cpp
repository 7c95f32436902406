// dynamic/st_metric.cpp — Eq. 4 / Eq. 9, group by group.
#include "dynamic/st_metric.hpp"

#include <algorithm>
#include <cstdint>

namespace tessera::dynamic {

namespace {

// One group of equal time offset: rows are the output entries, columns the input entries
// followed by one "unpaired" column per row.
double group_distance(const StEntry* out, int rows, const StEntry* in, int inputs, int in_base,
                      const StParams& params, MetricScratch& s, int* partner, double bound) {
    if (rows == 0) return 0.0;
    if (rows == 1 && inputs == 1) {  // the compact shape's trail: one fixed pair
        const double w = 0.5 * (out[0].kappa + in[0].kappa);
        const double c = pair_cost(out[0], in[0], params);
        if (partner) partner[0] = c < params.cap2 ? in_base : -1;
        return c < params.cap2 ? w * c : out[0].kappa * params.cap2;
    }
    // Row by row, the weighted pair costs (Eq. 9) and each row's cheapest: their sum bounds
    // the optimum from below, so a hopeless candidate is refused after a row or two, before
    // the O(rows^2 x cols) pairing. Columns no row pairs below the cap are as good as
    // "unpaired" and are left out of the pairing.
    s.full.resize(static_cast<size_t>(rows) * inputs);
    std::uint64_t useful = 0;  // inputs <= max_group < 64
    double lower = 0.0;
    for (int r = 0; r < rows; ++r) {
        double* row = s.full.data() + static_cast<size_t>(r) * inputs;
        const double unpaired = out[r].kappa * params.cap2;
        double cheapest = unpaired;
        for (int c = 0; c < inputs; ++c) {
            const double cost = pair_cost(out[r], in[c], params);
            const bool pairs = cost < params.cap2;
            row[c] = pairs ? 0.5 * (out[r].kappa + in[c].kappa) * cost : unpaired;
            useful |= std::uint64_t(pairs) << c;
            cheapest = std::min(cheapest, row[c]);
        }
        lower += cheapest;
        if (lower >= bound) return lower;
    }
    s.kept.clear();
    for (int c = 0; c < inputs; ++c)
        if (useful >> c & 1u) s.kept.push_back(c);
    const int kept = static_cast<int>(s.kept.size());
    const int cols = kept + rows;
    s.cost.resize(static_cast<size_t>(rows) * cols);
    for (int r = 0; r < rows; ++r) {
        double* row = s.cost.data() + static_cast<size_t>(r) * cols;
        const double* full = s.full.data() + static_cast<size_t>(r) * inputs;
        for (int k = 0; k < kept; ++k) row[k] = full[s.kept[k]];
        std::fill(row + kept, row + cols, out[r].kappa * params.cap2);
    }
    s.column.resize(rows);
    const double total = core::hungarian(s.cost.data(), rows, cols, s.hungarian, s.column.data());
    if (partner)
        for (int r = 0; r < rows; ++r) {
            const int k = s.column[r];
            partner[r] = k < kept && pair_cost(out[r], in[s.kept[k]], params) < params.cap2 ? in_base + s.kept[k] : -1;
        }
    return total;
}

}  // namespace

double st_distance(const StNeighbourhood& out, const StEntry* in, const int* in_start, const StParams& params,
                   MetricScratch& scratch, int* partner, double bound) {
    double total = 0.0;
    // Past groups first, then the spatial group 0 (the Hungarian on the largest group last,
    // when the bound has had every chance to stop the sum).
    for (int step = 1; step <= out.groups; ++step) {
        const int k = step % out.groups;
        const int o0 = out.start[k], o1 = out.start[k + 1];
        const int i0 = in_start[k], i1 = in_start[k + 1];
        total += group_distance(out.entries.data() + o0, o1 - o0, in + i0, i1 - i0, i0, params, scratch,
                                partner ? partner + o0 : nullptr, bound - total);
        if (total >= bound) return total;
    }
    return total;
}

}  // namespace tessera::dynamic
