// Exemplars whose coordinates were rounded (core/dequantize.hpp).
#include "core/dequantize.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/crowding_repair.hpp"
#include "core/rng.hpp"

namespace tessera::core {

namespace {

// Rounding finer than this share of the spacing is left alone; from kLattice of the
// spacing up, a common divisor of the coordinates is the pattern's own lattice (a square
// lattice at whole coordinates has q = its spacing).
constexpr double kNegligible = 0.02;
constexpr double kLattice = 0.3;
// A coordinate counts as a multiple of q within this share of q (text formats print a
// rounded value back with a few ulps of error).
constexpr double kTolerance = 1e-6;
// Draws tried per element before it keeps its recorded place (every draw would bring it
// closer to a neighbour than the closest pair of the data).
constexpr int kAttempts = 8;

bool divides_all(const Exemplar& ex, double q) {
    for (const Sample& s : ex.samples)
        for (int k = 0; k < ex.dimension; ++k) {
            const double m = s.p[k] / q;
            if (std::abs(m - std::round(m)) > kTolerance) return false;
        }
    return true;
}

}  // namespace

double coordinate_resolution(const Exemplar& ex) {
    if (ex.samples.empty()) return 0.0;
    double extent = 0.0;
    for (const Sample& s : ex.samples)
        for (int k = 0; k < ex.dimension; ++k) extent = std::max(extent, std::abs(s.p[k]));
    if (!(extent > 0.0)) return 0.0;
    // From a step above the extent down to 1e-9 of it: the first (largest) that divides all.
    const int top = static_cast<int>(std::ceil(std::log10(extent))) + 1;
    const int bottom = static_cast<int>(std::floor(std::log10(extent * 1e-9)));
    for (int e = top; e >= bottom; --e)
        for (const double m : {5.0, 2.0, 1.0}) {
            const double q = m * std::pow(10.0, e);
            if (q <= extent && divides_all(ex, q)) return q;
        }
    return 0.0;
}

bool is_rounded(double resolution, double spacing) {
    return resolution > 0.0 && spacing > 0.0 && resolution >= kNegligible * spacing &&
           resolution <= kLattice * spacing;
}

Exemplar dequantized(const Exemplar& exemplar, double spacing, std::uint64_t seed) {
    Exemplar out = exemplar;
    const double q = coordinate_resolution(exemplar);
    if (!is_rounded(q, spacing)) return out;
    const int n = static_cast<int>(out.elements.size());
    // The closest distance of each type pair: no draw brings a pair closer (a viewer, and
    // every crowding bound, judges closeness by the recorded data).
    const NearestDistanceTails closest(exemplar, CrowdingLevel::centroids);
    std::vector<Vec3> p(n);
    for (int i = 0; i < n; ++i) p[i] = out.elements[i].position;
    auto apart = [&](int j, const Vec3& at) {
        Vec3 d = p[j] - at;
        if (out.dimension == 2) d.z = 0.0;
        return norm(d);
    };
    const KeyedRng rng(seed, Purpose::dequantize);
    for (int i = 0; i < n; ++i) {
        const int a = out.elements[i].type;
        for (int attempt = 0; attempt < kAttempts; ++attempt) {
            Vec3 shift;
            for (int k = 0; k < out.dimension; ++k)
                shift[k] = q * (rng.uniform((static_cast<std::uint64_t>(i) * kAttempts + attempt) * 3 + k) - 0.5);
            const Vec3 at = p[i] + shift;
            bool fits = true;
            for (int j = 0; j < n && fits; ++j)
                fits = j == i || apart(j, at) >= closest.hard_core(a, out.elements[j].type);
            if (!fits) continue;
            Element& e = out.elements[i];
            e.position = e.position + shift;
            for (int s = 0; s < e.sample_count; ++s)
                out.samples[e.first_sample + s].p = out.samples[e.first_sample + s].p + shift;
            p[i] = at;
            break;
        }
    }
    return out;
}

}  // namespace tessera::core
