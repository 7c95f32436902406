// The per-element arithmetic of Eq. 2 and 3: kernel sums over one reference element's
// neighbours, its boundary-correction weights c_i(x_k), and the normalisation that turns
// the sums into its individual PCF. Analysis averages these into mean PCFs and
// envelopes (pcf_estimate.hpp); synthesis can evaluate a candidate element's individual
// PCF with the same three steps.
#pragma once

#include <vector>

#include "pcf/pcf_math.hpp"
#include "tessera/domain.hpp"

namespace tessera::pcf {

// acc[k] += weight * k_sigma(x_k - x) for the bins within the kernel's reach of x.
inline void add_kernel(const Axis& axis, double x, double weight, double* acc) {
    int lo = 0, hi = -1;
    axis.bin_range(x, lo, hi);
    for (int k = lo; k <= hi; ++k) acc[k] += weight * kernel(axis.x(k) - x, axis.sigma);
}

// c[k] = c_i(x_k): the share of the circle of Euclidean radius x_k r_max around p that
// lies in the domain (section 3.1). Circles within the distance to the boundary are
// whole (1) without sampling; distance_to_boundary never overestimates.
inline void boundary_fractions(const Axis& axis, const Domain& domain, const Vec3& p, double r_max, double* c) {
    const double free = domain.distance_to_boundary(p);
    for (int k = 0; k < axis.bins; ++k) {
        const double rho = axis.x(k) * r_max;
        c[k] = rho <= free ? 1.0 : circle_inside_fraction(domain, p, rho);
    }
}

// The factors |W| step / A_k of Eq. 2 for an axis, r_max and domain area: step k_sigma is
// the kernel's mass in one bin, so step times a kernel sum counts the neighbours in the
// ring of area A_k, and a uniform random pattern gets PCF = 1 (pcf_synthesis.hpp).
class PcfNormaliser {
public:
    PcfNormaliser() = default;
    PcfNormaliser(const Axis& axis, double r_max, double area) : scale_(axis.bins) {
        for (int k = 0; k < axis.bins; ++k) scale_[k] = area * axis.step / axis.ring_area(k, r_max);
    }
    // out[k] = |W| step acc[k] / (A_k neighbours c[k]): an individual PCF (Eq. 3) from the kernel
    // sums of one reference element over `neighbours` possible neighbours (n_b, or n_b - 1
    // within a class); all 0 when there are none.
    void individual(const double* acc, const double* c, double neighbours, double* out) const {
        const int bins = static_cast<int>(scale_.size());
        for (int k = 0; k < bins; ++k) out[k] = neighbours > 0.0 ? scale_[k] * acc[k] / (neighbours * c[k]) : 0.0;
    }
    int bins() const { return static_cast<int>(scale_.size()); }

private:
    std::vector<double> scale_;
};

}  // namespace tessera::pcf
