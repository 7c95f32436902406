// The normalised pair distance of the PCF method (include/tessera/pcf_synthesis.hpp),
// header-only so that every part of the method evaluates the exact same expression:
// synthesis uses it for every pair, and disk_metric_normalised may call it.
//
// For two disks with radii r1 >= r2 and centre distance d (Eq. 7 to 10):
//   nested,  d <= r1 - r2:       f = 3 (r1 - r2) + d,  x = f / (4 (r1 - r2))        in [3/4, 1]
//   overlap, r1 - r2 < d <= r1 + r2: f = 3 d + r1 - r2, x = (f - 4 r1 + 7 r2) / (3 r2)
//                                                        = (d - r1 + 2 r2) / r2     in (1, 3]
//   apart,   d > r1 + r2:        x = 3 + (d - r1 - r2) / r_max (the header's continuous
//                                form of Eq. 10's last branch: the gap in units of r_max)
// Equal radii: the nested branch is the single point d = 0, which maps to x = 0.
// Points (both radii 0): x = d / r_max.
// The metric is piecewise linear in d; `slope` is dx/dd on the branch d falls in (0 on
// the single point d = 0 of equal radii), which is what the refinement's chain rule needs.
#pragma once

#include <algorithm>

namespace tessera::pcf {

struct PairDistance {
    double x = 0.0;      // position on the normalised axis
    double slope = 0.0;  // dx/dd
};

inline PairDistance normalised_pair_distance_slope(double d, double ra, double rb, double r_max) {
    const double r1 = std::max(ra, rb), r2 = std::min(ra, rb);
    if (r1 <= 0.0) return {d / r_max, 1.0 / r_max};  // points
    if (d > r1 + r2) return {3.0 + (d - r1 - r2) / r_max, 1.0 / r_max};
    if (d > r1 - r2) return {(d - r1 + 2.0 * r2) / r2, 1.0 / r2};  // r2 > 0 here
    const double gap = r1 - r2;
    if (gap <= 0.0) return {0.0, 0.0};  // equal radii, d = 0
    return {(3.0 * gap + d) / (4.0 * gap), 1.0 / (4.0 * gap)};
}

// The same with 1 / r_max given (synthesis evaluates millions of pairs; the result may
// differ from the division in the last bit).
inline PairDistance normalised_pair_distance_slope(double d, double ra, double rb, double r_max,
                                                   double inv_r_max) {
    const double r1 = std::max(ra, rb), r2 = std::min(ra, rb);
    if (r1 <= 0.0) return {d * inv_r_max, inv_r_max};
    if (d > r1 + r2) return {3.0 + (d - r1 - r2) * inv_r_max, inv_r_max};
    return normalised_pair_distance_slope(d, ra, rb, r_max);
}

// x alone: disk_metric_normalised's convention for any radii >= 0 and r_max > 0.
inline double normalised_pair_distance(double d, double ra, double rb, double r_max) {
    return normalised_pair_distance_slope(d, ra, rb, r_max).x;
}

}  // namespace tessera::pcf
