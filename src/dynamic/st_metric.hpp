// The neighbourhood distance of Dynamic Element Textures, Eq. 4 with the smooth falloff of
// Eq. 8-9: entries are paired only within a group of equal time offset, exactly, by the
// Hungarian algorithm; a pair costs (kappa_o + kappa_i) / 2 x (|u_o - u_i|^2 + alpha [types
// differ]) truncated at cap2, and an output entry left unpaired costs kappa_o x cap2 (the
// input neighbourhood is gathered further than the output's, as the static method does, so
// that an output entry near the radius still finds its partner).
#pragma once

#include <vector>

#include "core/hungarian.hpp"
#include "dynamic/st_neighbourhood.hpp"

namespace tessera::dynamic {

struct MetricScratch {
    core::HungarianScratch hungarian;
    std::vector<double> cost, full;
    std::vector<int> column, kept;
};

// Distance between the output neighbourhood `out` (its groups only) and the input one given
// by its entries and group starts. Groups with time offset >= 1 are summed first (the trail
// of the compact shape is one fixed pair per group, cheap), and the sum stops as soon as it
// reaches `bound` (the caller's N-th best), returning a value >= bound. With `partner`, the
// input entry (index into `in`) paired with each output entry, -1 when unpaired; partners
// are only complete when the returned value is below the bound.
double st_distance(const StNeighbourhood& out, const StEntry* in, const int* in_start, const StParams& params,
                   MetricScratch& scratch, int* partner, double bound);

// The cost of pairing two entries (without the falloff weight), truncated at cap2.
inline double pair_cost(const StEntry& o, const StEntry& i, const StParams& params) {
    double c = squared_norm(o.offset - i.offset);
    if (o.type != i.type) c += params.alpha;
    return c < params.cap2 ? c : params.cap2;
}

}  // namespace tessera::dynamic
