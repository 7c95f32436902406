// The disk metric of section 4.2 (Eq. 7 to 10) and r_max of Eq. 1, with the conventions
// fixed in tessera/pcf_synthesis.hpp.
//
// With r1 >= r2 the three branches of Eq. 10 simplify (Eq. 7 to 9 substituted):
//   nested,      d <= r1 - r2:       extent = 2 r1, overlap = 2 r2,       f = 3 (r1 - r2) + d,
//                                    f_norm = 3/4 + d / (4 (r1 - r2))      in [3/4, 1];
//   overlapping, r1 - r2 < d <= r1 + r2: extent = d + r1 + r2, overlap = r1 + r2 - d,
//                                    f = 3 d + r1 - r2,  f_norm = 2 + (d - r1) / r2  in (1, 3];
//   disjoint,    d > r1 + r2:        tessera's continuous fix of Eq. 10's third branch,
//                                    x = 3 + (d - r1 - r2) / r_max.
// The closed forms are what is evaluated (pcf/pair_distance.hpp, shared with synthesis):
// Eq. 10's f / (4 r1 - 4 r2) divides a difference of nearly equal terms by a tiny number
// when the radii are close, the closed form does not.
#include "pcf/disk_metric.hpp"
#include "pcf/pair_distance.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "tessera/error.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera {

double disk_metric(double d, double ra, double rb) {
    const double r1 = std::max(ra, rb), r2 = std::min(ra, rb);
    const double extent = std::max(d + r1 + r2, 2.0 * r1);          // Eq. 7
    const double overlap = std::clamp(r1 + r2 - d, 0.0, 2.0 * r2);  // Eq. 8
    return extent - overlap + d + r1 - r2;                          // Eq. 9
}

double disk_metric_normalised(double d, double ra, double rb, double r_max) {
    // One expression for analysis and synthesis (pcf/pair_distance.hpp), so both place a
    // pair at exactly the same x.
    return pcf::normalised_pair_distance(d, ra, rb, r_max);
}

double pcf_r_max(double area, int n) {
    if (!(area > 0.0) || !std::isfinite(area) || n <= 0)
        throw Error(ErrorKind::option, "pcf r_max needs an area > 0 and at least one element, got area " +
                                           std::to_string(area) + " and " + std::to_string(n) + " elements");
    return 2.0 * std::sqrt(area / (2.0 * std::sqrt(3.0) * n));  // Eq. 1 scaled to an area
}

namespace pcf {

double disk_metric_slope(double d, double ra, double rb, double r_max) {
    return normalised_pair_distance_slope(d, ra, rb, r_max).slope;
}

}  // namespace pcf
}  // namespace tessera
