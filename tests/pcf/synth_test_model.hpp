// A small reference analysis for the synthesis tests: builds a PcfModel from an exemplar
// with the formulas of include/tessera/pcf_synthesis.hpp, by brute force over all pairs.
// It exists so that the synthesis can be tested before (and independently of) the
// library's analyze_distribution; it is not a second implementation to keep: tests
// may switch to analyze_distribution once both are in the library.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "pcf/pair_distance.hpp"
#include "pcf/pcf_math.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera::test {

inline PcfModel reference_model(const Exemplar& ex, const PcfAnalysisSettings& settings = {}) {
    PcfModel m;
    m.settings = settings;
    const int classes = static_cast<int>(ex.types.size());
    for (const ElementType& t : ex.types) m.classes.push_back(t.name);
    m.parents.assign(classes, {});
    for (int c = 0; c < classes; ++c) {
        if (!ex.types[c].depends_on) {
            for (int p = 0; p < c; ++p) m.parents[c].push_back(p);
        } else {
            for (const std::string& name : *ex.types[c].depends_on) m.parents[c].push_back(ex.find_type(name));
        }
    }
    // A topological order, earliest index first among the ready classes.
    std::vector<bool> done(classes, false);
    while (static_cast<int>(m.order.size()) < classes)
        for (int c = 0; c < classes; ++c) {
            if (done[c]) continue;
            const bool ready =
                std::all_of(m.parents[c].begin(), m.parents[c].end(), [&](int p) { return done[p]; });
            if (ready) {
                done[c] = true;
                m.order.push_back(c);
                break;
            }
        }
    m.counts.assign(classes, 0);
    m.radii.assign(classes, {});
    for (const Element& e : ex.elements) {
        ++m.counts[e.type];
        m.radii[e.type].push_back(e.radius);
        m.disks = m.disks || e.radius > 0.0;
    }
    for (auto& r : m.radii) std::sort(r.begin(), r.end(), std::greater<>());
    m.area = ex.domain.measure();
    const int n = static_cast<int>(ex.elements.size());
    m.r_max = 2.0 * std::sqrt(m.area / (2.0 * std::sqrt(3.0) * n));
    const pcf::Axis axis = pcf::make_axis(settings, m.disks);
    for (int k = 0; k < axis.bins; ++k) m.x.push_back(axis.x(k));

    // Boundary correction per element and bin, at the element's own position.
    std::vector<std::vector<double>> frac(n, std::vector<double>(axis.bins));
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < axis.bins; ++k)
            frac[i][k] = pcf::circle_inside_fraction(ex.domain, ex.elements[i].position, axis.x(k) * m.r_max);

    const auto add_pcf = [&](int parent, int child) {
        PcfEnvelope env;
        env.parent = parent;
        env.child = child;
        env.mean.assign(axis.bins, 0.0);
        env.lower.assign(axis.bins, 1e300);
        env.upper.assign(axis.bins, 0.0);
        const double n_parent = m.counts[parent];
        const double n_parent_pairs = parent == child ? n_parent - 1.0 : n_parent;
        for (int i = 0; i < n; ++i) {
            const Element& a = ex.elements[i];
            if (a.type != child) continue;
            std::vector<double> sum(axis.bins, 0.0);
            for (int j = 0; j < n; ++j) {
                const Element& b = ex.elements[j];
                if (j == i || b.type != parent) continue;
                const double d = norm(a.position - b.position);
                const double x = pcf::normalised_pair_distance(d, a.radius, b.radius, m.r_max);
                int lo = 0, hi = 0;
                axis.bin_range(x, lo, hi);
                for (int k = lo; k <= hi; ++k) sum[k] += pcf::kernel(axis.x(k) - x, axis.sigma);
            }
            for (int k = 0; k < axis.bins; ++k) {
                const double ring = axis.ring_area(k, m.r_max);
                const double individual = m.area / (ring * n_parent) * sum[k] / frac[i][k];
                env.lower[k] = std::min(env.lower[k], individual);
                env.upper[k] = std::max(env.upper[k], individual);
                if (n_parent_pairs > 0.0)
                    env.mean[k] += m.area / (ring * m.counts[child] * n_parent_pairs) * sum[k] / frac[i][k];
            }
        }
        m.pcfs.push_back(env);
    };
    for (int c = 0; c < classes; ++c) {
        add_pcf(c, c);
        for (int p : m.parents[c]) add_pcf(p, c);
    }
    return m;
}

// A hard-core (Poisson-disk) point set by dart throwing: up to n points at least
// `min_distance` apart in the box [0, size]^2.
inline Exemplar poisson_disk(int n, double size, double min_distance, std::uint64_t seed, double radius = 0.0) {
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {size, size, 0}, 2);
    ex.type_index("dot");
    const core::KeyedRng rng(seed, core::Purpose::test);
    std::vector<Vec3> points;
    for (std::uint64_t a = 0; a < 200000 && static_cast<int>(points.size()) < n; ++a) {
        const Vec3 p{size * rng.uniform(2 * a), size * rng.uniform(2 * a + 1), 0.0};
        const bool free = std::all_of(points.begin(), points.end(),
                                      [&](const Vec3& q) { return norm(p - q) >= min_distance; });
        if (free) points.push_back(p);
    }
    for (const Vec3& p : points) ex.add_element(0, {p}, radius);
    return ex;
}

}  // namespace tessera::test
