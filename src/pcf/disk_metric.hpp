// The normalised disk metric's slope, for the PCF method's gradient (Eq. 4 to 6 use
// d x_ij / d d_ij): private to the library, beside the public disk_metric functions of
// tessera/pcf_synthesis.hpp (defined in disk_metric.cpp).
#pragma once

namespace tessera::pcf {

// d/dd of disk_metric_normalised(d, ra, rb, r_max) (radii in either order): piecewise
// constant, 1 / r_max for points and beyond contact, 1 / r2 between the inner and outer
// borders, 1 / (4 (r1 - r2)) while nested. At a branch boundary the slope of the branch
// that holds d (the same branch choice as the metric) is returned; 0 for identical disks
// at d = 0 (the nested branch has no width).
double disk_metric_slope(double d, double ra, double rb, double r_max);

}  // namespace tessera::pcf
