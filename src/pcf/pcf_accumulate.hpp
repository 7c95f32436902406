// The per-element arithmetic of Eq. 2 and 3: kernel sums over one reference element's
// neighbours, each weighted by the boundary correction, and the normalisation that turns
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

// The boundary correction of section 3.1 for a pair at Euclidean centre distance d from
// the reference element at p: 1 / c_i(d), c_i(d) the share of the circle of radius d
// around p inside the domain. The centre distance, not the normalised one, because the
// correction is about where neighbours can be (pcf_synthesis.hpp); for points it is the
// per-ring weight c_i(x_k) of the paper up to the kernel's width. `free` is
// domain.distance_to_boundary(p): circles within it are whole (it never overestimates).
inline double boundary_weight(const Domain& domain, const Vec3& p, double free, double d) {
    return d <= free ? 1.0 : 1.0 / circle_inside_fraction(domain, p, d);
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
    // out[k] = |W| step acc[k] / (A_k neighbours): an individual PCF (Eq. 3) from the kernel
    // sums of one reference element (each kernel weighted by boundary_weight) over
    // `neighbours` possible neighbours (n_b, or n_b - 1 within a class); 0 when there are none.
    void individual(const double* acc, double neighbours, double* out) const {
        const int bins = static_cast<int>(scale_.size());
        for (int k = 0; k < bins; ++k) out[k] = neighbours > 0.0 ? scale_[k] * acc[k] / neighbours : 0.0;
    }
    int bins() const { return static_cast<int>(scale_.size()); }

private:
    std::vector<double> scale_;
};

}  // namespace tessera::pcf
