#include "det/shape_matching.hpp"

#include <algorithm>
#include <cmath>

#include "core/parallel.hpp"
#include "core/rigid_fit.hpp"

namespace tessera::det {

namespace {

// A cluster reaches this many times the source element's mean spacing between consecutive samples.
constexpr double kClusterReach = 2.0;

// Per-thread buffers: no allocation per element once grown.
struct ShapeScratch {
    std::vector<Vec3> goal, from, to;
    std::vector<int> hits, members;
};

// One round of shape matching for one element: `src` the source samples, `cur` the current.
void match_once(const Element& src, const Exemplar& exemplar, Vec3* cur, int dimension, ShapeScratch& s) {
    const int n = src.sample_count;
    const Vec3* a = &exemplar.samples[src.first_sample].p;
    double spacing = 0.0;
    for (int k = 0; k + 1 < n; ++k) spacing += norm(exemplar.samples[src.first_sample + k + 1].p - a[k]);
    spacing /= std::max(1, n - 1);
    const double reach2 = kClusterReach * kClusterReach * spacing * spacing;
    s.goal.assign(n, Vec3{});
    s.hits.assign(n, 0);
    for (int c = 0; c < n; ++c) {
        s.members.clear();
        for (int k = 0; k < n; ++k)
            if (squared_norm(exemplar.samples[src.first_sample + k].p - a[c]) <= reach2 + 1e-12) s.members.push_back(k);
        if (s.members.size() < 2) continue;
        s.from.clear();
        s.to.clear();
        for (int k : s.members) s.from.push_back(exemplar.samples[src.first_sample + k].p), s.to.push_back(cur[k]);
        Quat r;
        Vec3 t;
        core::best_rigid_fit(s.from.data(), s.to.data(), static_cast<int>(s.members.size()), dimension, r, t);
        for (size_t m = 0; m < s.members.size(); ++m) {
            s.goal[s.members[m]] += r.rotate(s.from[m]) + t;
            ++s.hits[s.members[m]];
        }
    }
    for (int k = 0; k < n; ++k)
        if (s.hits[k] > 0) {
            cur[k] = s.goal[k] * (1.0 / s.hits[k]);
            if (dimension == 2) cur[k].z = 0.0;
        }
}

}  // namespace

void match_deformable_shapes(OutputState& state, const Exemplar& exemplar, int dimension, int threads, int rounds) {
    Arrangement& out = state.arrangement;
    const int count = static_cast<int>(out.elements.size());
    std::vector<ShapeScratch> scratch(core::resolve_threads(threads));
    core::parallel_for(count, static_cast<int>(scratch.size()), [&](int begin, int end, int thread) {
        std::vector<Vec3> cur;
        for (int e = begin; e < end; ++e) {
            const Element& el = out.elements[e];
            if (el.sample_count < 3 || el.locked || out.types[el.type].rigid) continue;
            const Element& src = exemplar.elements[state.source_element[e]];
            if (src.sample_count != el.sample_count) continue;
            cur.resize(el.sample_count);
            for (int k = 0; k < el.sample_count; ++k) cur[k] = out.samples[el.first_sample + k].p;
            for (int round = 0; round < rounds; ++round) match_once(src, exemplar, cur.data(), dimension, scratch[thread]);
            for (int k = 0; k < el.sample_count; ++k) out.samples[el.first_sample + k].p = cur[k];
        }
    });
}

}  // namespace tessera::det
