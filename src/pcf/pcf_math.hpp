// The arithmetic every part of the PCF method shares (pcf_synthesis.hpp): the paper's
// Gaussian kernel, the normalised axis with its ring areas, and the perimeter-fraction
// boundary correction. Private to the library.
#pragma once

#include <algorithm>
#include <cmath>

#include "tessera/domain.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera::pcf {

inline constexpr double kPi = 3.14159265358979323846;

// k_sigma(t) = exp(-t^2 / sigma^2) / (sqrt(pi) sigma)  (section 3.1).
inline double kernel(double t, double sigma) {
    return std::exp(-(t * t) / (sigma * sigma)) / (std::sqrt(kPi) * sigma);
}

// The discretised normalised axis x_k = k * step, k = 0 .. bins - 1.
struct Axis {
    double step = 0.1;
    double sigma = 0.25;
    int bins = 0;
    // Kernel support: contributions beyond 4 sigma (e^-16 of the peak) are dropped.
    double reach() const { return 4.0 * sigma; }
    // The bins [lo, hi] a pair at normalised distance x contributes to (empty if lo > hi).
    void bin_range(double x, int& lo, int& hi) const {
        lo = std::max(0, static_cast<int>(std::ceil((x - reach()) / step)));
        hi = std::min(bins - 1, static_cast<int>(std::floor((x + reach()) / step)));
    }
    double x(int k) const { return k * step; }
    // A_k of Eq. 2 in data units: the ring 2 pi x_k step r_max^2 (x_k at least step / 2).
    double ring_area(int k, double r_max) const {
        const double xk = std::max(k * step, 0.5 * step);
        return 2.0 * kPi * xk * step * r_max * r_max;
    }
    // The largest normalised distance worth computing: the last bin plus the kernel reach.
    double x_limit() const { return (bins - 1) * step + reach(); }
};

// The axis for a model: points run to `extent`, disks to 3 + extent (the overlap part
// of the disk metric, [0, 3], comes first).
inline Axis make_axis(const PcfAnalysisSettings& s, bool disks) {
    Axis a;
    a.step = s.step;
    a.sigma = s.sigma;
    a.bins = static_cast<int>(std::floor(((disks ? 3.0 : 0.0) + s.extent) / s.step + 1e-9)) + 1;
    return a;
}

// How far apart synthesis keeps classes without a PCF between them at most (PcfSeparation):
// the salient configurations of disks end at contact, x = 3; one kernel width beyond.
inline double separation_cap(const PcfAnalysisSettings& s, bool disks) { return (disks ? 3.0 : 0.0) + s.sigma; }

// Fraction of the circle of radius rho around p that lies in the domain (section 3.1's
// boundary correction weight), estimated from 64 points on the circle for every kind of
// domain (within 1/64 of the exact fraction); 1 when rho <= 0.
inline double circle_inside_fraction(const Domain& domain, const Vec3& p, double rho) {
    if (!(rho > 0.0)) return 1.0;
    constexpr int samples = 64;
    int inside = 0;
    for (int k = 0; k < samples; ++k) {
        const double a = 2.0 * kPi * (k + 0.5) / samples;
        inside += domain.inside({p.x + rho * std::cos(a), p.y + rho * std::sin(a), 0.0});
    }
    return std::max(inside, 1) / static_cast<double>(samples);  // never 0: p itself is inside
}

}  // namespace tessera::pcf
