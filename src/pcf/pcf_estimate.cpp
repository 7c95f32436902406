// Mean PCFs and envelopes (Eq. 2 and 3, section 5.1). Every reference element is
// visited once: its neighbours within the axis's Euclidean reach come from a
// NeighbourGrid, each neighbour adds its kernel to the kernel sums of the PCF linking
// the two classes (if the DAG has one), and the element's individual PCFs are folded
// into the running sums (for the means) and minima / maxima (the envelopes).
#include "pcf/pcf_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel.hpp"
#include "pcf/neighbour_grid.hpp"
#include "pcf/pair_distance.hpp"
#include "pcf/pcf_accumulate.hpp"
#include "tessera/error.hpp"

namespace tessera::pcf {

PcfPoints pcf_points(const Exemplar& data, const std::vector<int>& class_of_type, const std::string& what) {
    if (data.dimension != 2 || data.domain.dimension() != 2)
        throw Error(ErrorKind::input, what + ": the PCF method works on 2D data, got " +
                                          std::to_string(data.dimension) + "D");
    PcfPoints pts;
    for (size_t i = 0; i < data.elements.size(); ++i) {
        const Element& e = data.elements[i];
        const int t = e.type;
        if (t < 0 || t >= static_cast<int>(data.types.size()))
            throw Error(ErrorKind::input, what + ": element " + std::to_string(i) + " has an unknown element type");
        const std::string name = "'" + data.types[t].name + "'";
        if (e.sample_count != 1)
            throw Error(ErrorKind::input, what + ": class " + name +
                                              " has multi-sample elements; the PCF method needs one point per element");
        if (!(e.radius >= 0.0) || !std::isfinite(e.radius))
            throw Error(ErrorKind::input, what + ": class " + name + " has an element with radius " +
                                              std::to_string(e.radius) + "; radii must be >= 0");
        const Vec3& p = data.samples[e.first_sample].p;
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            throw Error(ErrorKind::input, what + ": element " + std::to_string(i) + " has a position that is not finite");
        pts.p.push_back({p.x, p.y, 0.0});
        pts.radius.push_back(e.radius);
        pts.cls.push_back(class_of_type[t]);
    }
    return pts;
}

namespace {

// Running sums and envelopes of one block of reference elements.
struct BlockResult {
    std::vector<double> sum, lower, upper;  // pairs x bins
};

}  // namespace

std::vector<PcfEnvelope> estimate_pcfs(const PcfPoints& points, int classes, const Domain& domain, double area,
                                       double r_max, const Axis& axis, const std::vector<PcfEnvelope>& pairs,
                                       int threads) {
    const int n = static_cast<int>(points.p.size());
    const int bins = axis.bins;
    const int npairs = static_cast<int>(pairs.size());

    std::vector<int> count(classes, 0);
    double largest = 0.0;
    bool has_points = false;
    for (int i = 0; i < n; ++i) {
        if (points.cls[i] < 0) continue;
        ++count[points.cls[i]];
        largest = std::max(largest, points.radius[i]);
        has_points = has_points || !(points.radius[i] > 0.0);
    }
    // slot[child][parent]: the PCF a (reference, neighbour) pair of these classes feeds.
    std::vector<std::vector<int>> slot(classes, std::vector<int>(classes, -1));
    for (int q = 0; q < npairs; ++q) slot[pairs[q].child][pairs[q].parent] = q;

    const double reach = max_pair_reach(axis, r_max, largest, has_points);
    NeighbourGrid grid(domain.bounds(), reach, n);
    for (int i = 0; i < n; ++i)
        if (points.cls[i] >= 0) grid.insert(i, points.p[i]);
    const PcfNormaliser normaliser(axis, r_max, area);

    // A fixed split into blocks (independent of the thread count), reduced in block
    // order: the same bits on any machine.
    const int blocks = std::clamp(n / 256 + 1, 1, 64);
    std::vector<BlockResult> results(blocks);
    core::parallel_for(blocks, core::resolve_threads(threads), [&](int block_begin, int block_end, int) {
        std::vector<double> acc(static_cast<size_t>(npairs) * bins), individual(bins);
        for (int block = block_begin; block < block_end; ++block) {
            BlockResult& r = results[block];
            r.sum.assign(static_cast<size_t>(npairs) * bins, 0.0);
            r.lower.assign(r.sum.size(), std::numeric_limits<double>::infinity());
            r.upper.assign(r.sum.size(), -std::numeric_limits<double>::infinity());
            const int begin = static_cast<int>(static_cast<long long>(n) * block / blocks);
            const int end = static_cast<int>(static_cast<long long>(n) * (block + 1) / blocks);
            for (int i = begin; i < end; ++i) {
                const int child = points.cls[i];
                if (child < 0) continue;
                const double ri = points.radius[i];
                std::fill(acc.begin(), acc.end(), 0.0);
                const double query = std::max(pair_reach(axis, r_max, ri, largest),
                                              has_points ? pair_reach(axis, r_max, ri, 0.0) : 0.0);
                const double free = domain.distance_to_boundary(points.p[i]);
                grid.for_each_within(points.p[i], query, [&](int j, double d2) {
                    if (j == i) return;
                    const int q = slot[child][points.cls[j]];
                    if (q < 0) return;
                    const double d = std::sqrt(d2);
                    const double x = disk_metric_normalised(d, ri, points.radius[j], r_max);
                    if (x > axis.x_limit()) return;
                    add_kernel(axis, x, boundary_weight(domain, points.p[i], free, d),
                               acc.data() + static_cast<size_t>(q) * bins);
                });
                for (int q = 0; q < npairs; ++q) {
                    if (pairs[q].child != child) continue;
                    const int parent = pairs[q].parent;
                    const double neighbours = count[parent] - (parent == child ? 1.0 : 0.0);
                    normaliser.individual(acc.data() + static_cast<size_t>(q) * bins, neighbours, individual.data());
                    const size_t at = static_cast<size_t>(q) * bins;
                    for (int k = 0; k < bins; ++k) {
                        r.sum[at + k] += individual[k];
                        r.lower[at + k] = std::min(r.lower[at + k], individual[k]);
                        r.upper[at + k] = std::max(r.upper[at + k], individual[k]);
                    }
                }
            }
        }
    });

    std::vector<PcfEnvelope> out = pairs;
    for (int q = 0; q < npairs; ++q) {
        PcfEnvelope& e = out[q];
        e.mean.assign(bins, 0.0);
        e.lower.assign(bins, 0.0);
        e.upper.assign(bins, 0.0);
        const int nc = count[e.child];
        if (nc == 0) continue;  // no reference element: nothing observed
        std::fill(e.lower.begin(), e.lower.end(), std::numeric_limits<double>::infinity());
        std::fill(e.upper.begin(), e.upper.end(), -std::numeric_limits<double>::infinity());
        const size_t at = static_cast<size_t>(q) * bins;
        for (const BlockResult& r : results)
            for (int k = 0; k < bins; ++k) {
                e.mean[k] += r.sum[at + k];
                e.lower[k] = std::min(e.lower[k], r.lower[at + k]);
                e.upper[k] = std::max(e.upper[k], r.upper[at + k]);
            }
        for (int k = 0; k < bins; ++k) {
            e.mean[k] /= nc;
            // The average of values lies between their extremes; rounding must not say otherwise.
            e.mean[k] = std::clamp(e.mean[k], e.lower[k], e.upper[k]);
        }
    }
    return out;
}

std::vector<double> closest_approaches(const PcfPoints& points, const Domain& domain, double r_max,
                                       const std::vector<std::pair<int, int>>& pairs, int classes, double cap) {
    std::vector<double> out(pairs.size(), cap);
    if (pairs.empty()) return out;
    std::vector<std::vector<int>> slot(classes, std::vector<int>(classes, -1));
    for (size_t q = 0; q < pairs.size(); ++q) {
        slot[pairs[q].first][pairs[q].second] = static_cast<int>(q);
        slot[pairs[q].second][pairs[q].first] = static_cast<int>(q);
    }
    const int n = static_cast<int>(points.p.size());
    double largest = 0.0;
    bool has_points = false;
    for (int i = 0; i < n; ++i) {
        largest = std::max(largest, points.radius[i]);
        has_points = has_points || !(points.radius[i] > 0.0);
    }
    // Centre distance within which a pair can be closer than cap on the axis.
    const auto reach = [&](double ra, double rb) {
        if (!(ra > 0.0) && !(rb > 0.0)) return cap * r_max;
        return std::max(0.0, cap - 3.0) * r_max + ra + rb;
    };
    const double cell = std::max({reach(largest, largest), has_points ? reach(0.0, 0.0) : 0.0, 1e-12 * r_max});
    NeighbourGrid grid(domain.bounds(), cell, n);
    for (int i = 0; i < n; ++i)
        if (points.cls[i] >= 0) grid.insert(i, points.p[i]);
    for (int i = 0; i < n; ++i) {
        const int a = points.cls[i];
        if (a < 0) continue;
        const double ri = points.radius[i];
        const double query = std::max(reach(ri, largest), !(ri > 0.0) && has_points ? reach(0.0, 0.0) : 0.0);
        grid.for_each_within(points.p[i], query, [&](int j, double d2) {
            if (j <= i || points.cls[j] < 0) return;
            const int q = slot[a][points.cls[j]];
            if (q < 0) return;
            const double x = normalised_pair_distance(std::sqrt(d2), ri, points.radius[j], r_max);
            out[q] = std::min(out[q], x);
        });
    }
    return out;
}

}  // namespace tessera::pcf
