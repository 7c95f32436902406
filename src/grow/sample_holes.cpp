// Holes between multi-sample elements (grow/sample_holes.hpp).
#include "grow/sample_holes.hpp"

#include <algorithm>
#include <cmath>

#include "grow/generate.hpp"
#include "grow/sample_index.hpp"
#include "tessera/metrics.hpp"

namespace tessera::grow {

namespace {

// Input shapes tried per place: the nearest to the neighbours' match, then spread over the pool.
constexpr int kShapeTries = 16;
// Probes per lattice step of half the exemplar's largest empty circle; more probes than this
// in a region and the pass is skipped (a region of millions of elements' worth of holes).
constexpr double kProbeStep = 0.5;
constexpr std::size_t kMaxProbes = 8u << 20;
// How deep a place is measured, in exemplar holes: deeper places first.
constexpr double kDepthCap = 3.0;

class SampleHoles {
public:
    SampleHoles(Grower::Impl& g, const Domain& region, double hole)
        : g_(g), region_(region), hole_(hole), samples_(g, hole), balance_(g) {}

    // Places emptier than the hole, deepest first (ties in lattice order).
    std::vector<std::pair<double, Vec3>> places() const {
        const Box& b = region_.bounds();
        const double step = kProbeStep * hole_;
        const int d = g_.metric.dimension;
        std::array<long, 3> n{1, 1, 1};
        double total = 1.0;
        for (int k = 0; k < d; ++k) n[k] = std::max(1L, static_cast<long>(std::ceil((b.hi[k] - b.lo[k]) / step))), total *= n[k];
        std::vector<std::pair<double, Vec3>> found;
        if (total > static_cast<double>(kMaxProbes)) return found;
        for (long i = 0; i < n[0]; ++i)
            for (long j = 0; j < n[1]; ++j)
                for (long k = 0; k < n[2]; ++k) {
                    Vec3 p{b.lo.x + (i + 0.5) * step, b.lo.y + (j + 0.5) * step, d == 3 ? b.lo.z + (k + 0.5) * step : 0.0};
                    if (!region_.inside(p)) continue;
                    const double depth = clearance(p);
                    if (depth > hole_) found.push_back({depth, p});
                }
        std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
        return found;
    }

    // An element into the place at p if it is still a hole and a shape fits.
    bool fill(const Vec3& p) {
        if (!(clearance(p) > hole_)) return false;
        const int nearest = nearest_element(p);
        const Vec3 near_input = nearest >= 0 && g_.out[nearest].match >= 0 ? g_.input.centroid[g_.out[nearest].match] : Vec3{};
        std::vector<int> types(g_.exemplar.types.size());
        for (size_t t = 0; t < types.size(); ++t) types[t] = static_cast<int>(t);
        std::stable_sort(types.begin(), types.end(), [&](int a, int b) { return balance_.deficit(a) > balance_.deficit(b); });
        for (const int t : types) {
            const std::vector<int>& pool = g_.input.pool[t];
            if (pool.empty()) continue;
            const int first = g_.input.nearest_in_pool(t, near_input, 1e300);
            for (int k = 0; k < std::min<int>(kShapeTries, static_cast<int>(pool.size())); ++k) {
                const int source = k == 0 ? first : pool[(static_cast<size_t>(k) * pool.size()) / kShapeTries];
                if (source < 0 || (k > 0 && source == first)) continue;
                if (fits(t, source, p)) {
                    add(t, source, p);
                    return true;
                }
            }
        }
        return false;
    }

    int added() const { return added_; }

private:
    // Distance from p to the nearest sample, capped at kDepthCap holes.
    double clearance(const Vec3& p) const {
        double best = kDepthCap * hole_;
        samples_.for_each_within(p, best, [&](int s) { best = std::min(best, norm(samples_.at(s) - p)); });
        return best;
    }

    int nearest_element(const Vec3& p) const {
        int best = -1;
        double d = 1e300;
        samples_.for_each_within(p, kDepthCap * hole_ + g_.extent, [&](int s) {
                const double e = norm(samples_.at(s) - p);
                if (e < d || (e == d && samples_.owner(s) < best)) d = e, best = samples_.owner(s);
            });
        return best;
    }

    bool fits(int t, int source, const Vec3& p) {
        const Quat frame = g_.frame_at(p);
        if (!g_.fits_region(region_, -1, source, frame, p, mine_)) return false;
        g_.sample_positions(-1, source, frame, p, mine_);
        for (const Vec3& q : mine_) {
            bool clash = false;
            samples_.for_each_within(q, g_.reach + g_.metric.params.spacing, [&](int s) {
                    const double core = g_.sample_core(t, g_.out[samples_.owner(s)].type);
                    clash = clash || norm(samples_.at(s) - q) < core;
                });
            if (clash) return false;
        }
        bool near = false;
        g_.grid.for_each_within(
            p, g_.reach, [&](int j) { return g_.out[j].p; },
            [&](int j) { near = near || norm(g_.out[j].p - p) < g_.hard_core(t, g_.out[j].type); });
        return !near && g_.crowd_allows(p);
    }

    void add(int t, int source, const Vec3& p) {
        samples_.add(g_.add_filling(t, source, p));
        balance_.add(t);
        ++added_;
    }

    Grower::Impl& g_;
    const Domain& region_;
    const double hole_;
    SampleIndex samples_;
    TypeBalance balance_;
    std::vector<Vec3> mine_;
    int added_ = 0;
};

}  // namespace

int fill_sample_holes(Grower::Impl& g, const Domain& region) {
    // A world's tile (an open region) is left alone: its faces towards tiles not grown yet
    // look like holes from inside (filled, single-sample tiles crowded their seams).
    if (!g.bounds.has_samples || g.layer_registered || g.open_region || g.out.empty()) return 0;
    const double hole = largest_empty_circle(g.exemplar, g.threads).radius;
    if (!(hole > 0.0)) return 0;
    SampleHoles holes(g, region, hole);
    for (const auto& [depth, p] : holes.places()) {
        g.interrupt.check(0);
        holes.fill(p);
    }
    return holes.added();
}

}  // namespace tessera::grow
