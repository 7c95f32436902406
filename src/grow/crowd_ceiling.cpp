// The local count ceiling (grow/crowd_ceiling.hpp).
#include "grow/crowd_ceiling.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/dynamic_grid.hpp"
#include "grow/ball_lattice.hpp"

namespace tessera::grow {

namespace {

// R in mean spacings (density^(-1/d)): about 50 neighbours in 2D, 270 in 3D, enough for the
// count to measure density rather than the nearest neighbour's distance.
constexpr double kRadius = 4.0;
// The share of the exemplar's elements whose count the ceiling allows.
constexpr double kQuantile = 0.85;
// An exemplar element counts only when this share of its disk lies in the window (the edge
// correction of a smaller share is too noisy).
constexpr double kMinInside = 0.5;
// Fewer counted elements than this: no ceiling (a quantile of a handful is not one).
constexpr int kMinCounted = 8;
// Points per axis of the lattice that measures the share of a disk inside the window.
constexpr int kLattice = 16;

}  // namespace

CrowdCeiling exemplar_crowd_ceiling(const Exemplar& ex, double total_density) {
    CrowdCeiling ceiling;
    const int n = static_cast<int>(ex.elements.size());
    if (n == 0 || total_density <= 0.0) return ceiling;
    for (const Element& e : ex.elements)
        if (e.sample_count != 1) return ceiling;
    const int d = ex.dimension;
    const double radius = kRadius * std::pow(total_density, -1.0 / d);
    std::vector<Vec3> p(n);
    for (int i = 0; i < n; ++i) {
        p[i] = ex.elements[i].position;
        if (d == 2) p[i].z = 0.0;
    }
    core::DynamicGrid grid(radius, d);
    for (int i = 0; i < n; ++i) grid.insert(i, p[i]);
    const std::vector<Vec3> lattice = unit_ball_lattice(d, kLattice);
    std::vector<double> counts;
    for (int i = 0; i < n; ++i) {
        int inside = 0;
        for (const Vec3& u : lattice) inside += ex.domain.inside(p[i] + u * radius) ? 1 : 0;
        const double share = static_cast<double>(inside) / lattice.size();
        if (share < kMinInside) continue;
        int neighbours = 0;
        grid.for_each_within(
            p[i], radius, [&](int j) { return p[j]; }, [&](int j) { neighbours += j != i ? 1 : 0; });
        counts.push_back(neighbours / share);
    }
    if (static_cast<int>(counts.size()) < kMinCounted) return ceiling;
    // Counts that vary at least as a Poisson pattern's (variance >= mean) are those of a
    // random or clustered pattern: no ceiling then (its own crowded places are the rule, and
    // a ceiling left Japanese pines 10% under their density).
    double mean = 0.0, var = 0.0;
    for (const double c : counts) mean += c;
    mean /= counts.size();
    for (const double c : counts) var += (c - mean) * (c - mean);
    var /= counts.size();
    if (var >= mean) return ceiling;
    const size_t k = std::min(counts.size() - 1, static_cast<size_t>(kQuantile * counts.size()));
    std::nth_element(counts.begin(), counts.begin() + k, counts.end());
    ceiling.radius = radius;
    ceiling.limit = counts[k];
    return ceiling;
}

}  // namespace tessera::grow
