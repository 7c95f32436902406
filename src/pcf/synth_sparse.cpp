// PCF synthesis, the fallback for classes with too few elements for PCFs
// (PcfSparseClass): keyed random darts inside the domain, the first that keeps the
// class's spacing, its closest approaches (State::separations) and its tethers to its
// parents is taken; after kSparseDarts darts the one that broke them least.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/rng.hpp"
#include "pcf/synth_steps.hpp"

namespace tessera::pcf {

namespace {

constexpr std::uint64_t kSparseDarts = 20000;

// How far (normalised axis) a dart at p breaks the fallback's rules: spacing (in units of
// r_max), separations, and per parent how far its nearest element lies beyond the tether.
double sparse_violation(const State& s, const PcfSparseClass& sc, const Vec3& p, double r) {
    double v = s.separation_violation(sc.cls, p, r);
    s.for_each_near(sc.cls, p, sc.spacing, [&](int j) {
        v = std::max(v, (sc.spacing - s.distance(p, s.elems[j].p)) / s.r_max);
        return true;
    });
    for (size_t o = 0; o < sc.tether.size(); ++o) {
        const double x = sc.tether[o];
        if (!(x > 0.0) || s.placed(static_cast<int>(o)) == 0) continue;
        double nearest = std::numeric_limits<double>::infinity();
        double largest = 0.0;
        for (const auto* list : {&s.members[o], &s.fixed[o]})
            for (int j : *list) largest = std::max(largest, s.elems[j].r);
        const double reach = (s.model.disks ? std::max(0.0, x - 3.0) + 0.0 : x) * s.r_max + r + largest;
        s.for_each_near(static_cast<int>(o), p, std::max(reach, x * s.r_max), [&](int j) {
            nearest = std::min(nearest, s.pair(s.distance(p, s.elems[j].p), r, s.elems[j].r).x);
            return true;
        });
        v = std::max(v, nearest < std::numeric_limits<double>::infinity() ? nearest - x : x);
    }
    return v;
}

}  // namespace

SparseReport place_sparse(State& s, const PcfSparseClass& sc, const std::vector<int>& elements, std::uint64_t seed,
                          const std::function<void()>& tick) {
    SparseReport report;
    const Box b = s.fill->bounds();
    const double w = b.hi.x - b.lo.x, h = b.hi.y - b.lo.y;
    const core::KeyedRng dart(seed, core::Purpose::pcf_dart, static_cast<std::uint64_t>(sc.cls), 1ull << 40);
    std::uint64_t attempt = 0;
    CircleProfile profile;
    for (int i : elements) {
        const double r = s.elems[i].r;
        double best = std::numeric_limits<double>::infinity();
        Vec3 best_p = s.fill->closest_inside(b.lo + (b.hi - b.lo) * 0.5);
        for (std::uint64_t k = 0; k < kSparseDarts && best > 0.0; ++k, ++attempt) {
            const Vec3 p{b.lo.x + w * dart.uniform(2 * attempt), b.lo.y + h * dart.uniform(2 * attempt + 1), 0.0};
            if (!s.fill->inside(p)) continue;
            const double v = sparse_violation(s, sc, p, r);
            if (v < best) {
                best = v;
                best_p = p;
            }
            if ((k & 1023) == 1023) tick();
        }
        if (best > 0.0) ++report.by_bound;
        report.worst = std::max(report.worst, std::isfinite(best) ? best : 0.0);
        s.begin_profile(best_p, profile);
        s.insert(i, profile);
        tick();
    }
    return report;
}

}  // namespace tessera::pcf
