// disk_configurations: shares of the salient disk configurations of section 4.1
// (Figure 5) among close pairs of disks — disjoint, tangent, overlapping, nested — so an
// output's overlaps can be held against its exemplar's.
#include <algorithm>
#include <cmath>

#include "pcf/neighbour_grid.hpp"
#include "tessera/error.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera {

DiskConfigurationShares disk_configurations(const Exemplar& data, double margin, double tolerance) {
    if (!(margin >= 0.0) || !std::isfinite(margin) || !(tolerance >= 0.0) || !std::isfinite(tolerance))
        throw Error(ErrorKind::option, "disk configurations: margin and tolerance must be finite numbers >= 0");
    // Disks only: points (radius 0) have no extent to overlap with.
    std::vector<Vec3> p;
    std::vector<double> r;
    for (const Element& e : data.elements)
        if (e.radius > 0.0 && e.sample_count >= 1) {
            p.push_back({e.position.x, e.position.y, 0.0});
            r.push_back(e.radius);
        }
    const int n = static_cast<int>(p.size());
    DiskConfigurationShares s;
    if (n < 2) return s;
    const double largest = *std::max_element(r.begin(), r.end());
    pcf::NeighbourGrid grid(data.domain.bounds(), 2.0 * largest + margin, n);
    for (int i = 0; i < n; ++i) grid.insert(i, p[i]);
    long long disjoint = 0, tangent = 0, overlapping = 0, nested = 0;
    for (int i = 0; i < n; ++i)
        grid.for_each_within(p[i], r[i] + largest + margin, [&](int j, double d2) {
            if (j <= i) return;  // each unordered pair once
            const double d = std::sqrt(d2);
            const double r1 = std::max(r[i], r[j]), r2 = std::min(r[i], r[j]);
            const double gap = d - r1 - r2;
            if (!(gap < margin)) return;
            if (gap > tolerance * r2)
                ++disjoint;
            else if (gap >= -tolerance * r2)
                ++tangent;
            else if (d <= r1 - r2)
                ++nested;
            else
                ++overlapping;
        });
    const long long pairs = disjoint + tangent + overlapping + nested;
    s.pairs = static_cast<int>(pairs);
    if (pairs > 0) {
        s.disjoint = static_cast<double>(disjoint) / pairs;
        s.tangent = static_cast<double>(tangent) / pairs;
        s.overlapping = static_cast<double>(overlapping) / pairs;
        s.nested = static_cast<double>(nested) / pairs;
    }
    return s;
}

}  // namespace tessera
