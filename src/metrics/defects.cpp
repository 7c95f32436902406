// Defects a user sees at a glance, as numbers (docs/metrics.md, "Defects"): crowded and
// coincident elements, holes, deformed shapes, samples outside the domain. Averages such
// as the pair correlation hide them: a few stacked elements or one vacancy barely move a
// PCF but are the first thing a viewer notices.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/empty_space.hpp"
#include "core/nearest_by_type.hpp"
#include "core/parallel.hpp"
#include "core/spatial_grid.hpp"
#include "metrics/points.hpp"
#include "tessera/error.hpp"
#include "tessera/metrics.hpp"

namespace tessera {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Per ordered class pair (a, b): the distances from each a element to its nearest b.
std::vector<std::vector<double>> nearest_distances_by_pair(const Exemplar& data, double reach) {
    const int types = static_cast<int>(data.types.size());
    const std::vector<Vec3> p = core::centroids_of(data);
    core::SpatialGrid grid;
    grid.build(p, metrics::grid_cell(p, std::max(reach, metrics::typical_spacing(p, data.dimension))), data.dimension);
    const std::vector<double> nearest = core::nearest_by_type(data, p, grid, reach);
    std::vector<std::vector<double>> by_pair(static_cast<size_t>(types) * types);
    for (size_t i = 0; i < p.size(); ++i) {
        const int a = data.elements[i].type;
        for (int b = 0; b < types; ++b)
            if (std::isfinite(nearest[i * types + b])) by_pair[a * types + b].push_back(nearest[i * types + b]);
    }
    return by_pair;
}

}  // namespace

std::vector<CrowdingPair> crowding(const Exemplar& exemplar, const Exemplar& output, double quantile) {
    metrics::check_points(exemplar, "crowding: exemplar");
    metrics::check_points(output, "crowding: output");
    if (!(quantile > 0.0 && quantile < 1.0)) throw Error(ErrorKind::option, "crowding: the quantile must lie in (0, 1)");
    const int types = static_cast<int>(exemplar.types.size());
    const std::vector<Vec3> pe = core::centroids_of(exemplar);
    std::vector<std::vector<double>> ex = nearest_distances_by_pair(exemplar, metrics::bounding_diagonal(pe) * 1.001 + 1e-300);
    std::vector<CrowdingPair> result;
    for (int a = 0; a < types; ++a)
        for (int b = 0; b < types; ++b) {
            std::vector<double>& d = ex[a * types + b];
            if (d.size() < 2) continue;
            const int oa = output.find_type(exemplar.types[a].name), ob = output.find_type(exemplar.types[b].name);
            if (oa < 0 || ob < 0) continue;
            CrowdingPair pair;
            pair.class_a = a, pair.class_b = b;
            pair.name_a = exemplar.types[a].name, pair.name_b = exemplar.types[b].name;
            pair.threshold = core::quantile_of(d, quantile);
            const double close = pair.threshold / 100.0;
            for (double v : d) {
                pair.exemplar_share += v <= pair.threshold;
                pair.exemplar_coincident += v < close;
            }
            pair.exemplar_share /= static_cast<double>(d.size());
            result.push_back(pair);
        }
    // The output's distances are needed only up to the largest threshold.
    double reach = 0.0;
    for (const CrowdingPair& c : result) reach = std::max(reach, c.threshold);
    if (result.empty() || output.elements.empty()) return result;
    const std::vector<std::vector<double>> out = nearest_distances_by_pair(output, reach * 1.0001 + 1e-300);
    const int out_types = static_cast<int>(output.types.size());
    std::vector<long> count(out_types, 0);
    for (const Element& e : output.elements) ++count[e.type];
    for (CrowdingPair& c : result) {
        const int oa = output.find_type(c.name_a), ob = output.find_type(c.name_b);
        for (double v : out[oa * out_types + ob]) {
            c.output_share += v <= c.threshold;
            c.output_coincident += v < c.threshold / 100.0;
        }
        c.output_elements = count[oa];
        c.output_share = count[oa] > 0 ? c.output_share / static_cast<double>(count[oa]) : 0.0;
    }
    return result;
}

EmptyCircle largest_empty_circle(const Exemplar& data, int threads) {
    metrics::check_points(data, "largest empty circle");
    std::vector<Vec3> p;
    std::vector<double> rim;  // per sample: the radius of its element
    for (const Sample& s : data.samples) {
        Vec3 q = s.p;
        if (data.dimension == 2) q.z = 0.0;
        p.push_back(q);
        rim.push_back(data.elements[s.element].radius);
    }
    if (p.empty()) return {};
    // A lattice of a fifth of the typical spacing in 2D, a third in 3D, refined by a pattern search.
    const double step = metrics::typical_spacing(p, data.dimension) / (data.dimension == 2 ? 5.0 : 3.0);
    const core::EmptyBall ball = core::largest_empty_ball(p, rim, data.domain, data.dimension, step, threads);
    return {ball.radius, ball.center};
}

std::vector<ShapeStats> shape_statistics(const Exemplar& exemplar, const Exemplar& output) {
    metrics::check_points(exemplar, "shape statistics: exemplar");
    metrics::check_points(output, "shape statistics: output");
    std::vector<ShapeStats> result;
    constexpr double kDegrees = 180.0 / 3.14159265358979323846;
    // Segment lengths per segment index and the bend at each inner sample, in degrees.
    const auto measure = [&](const Exemplar& data, int type, std::vector<std::vector<double>>& lengths,
                             std::vector<double>& bends) {
        for (const Element& e : data.elements) {
            if (e.type != type || e.sample_count < 2) continue;
            if (lengths.size() < static_cast<size_t>(e.sample_count - 1)) lengths.resize(e.sample_count - 1);
            for (int s = 0; s + 1 < e.sample_count; ++s) {
                const Vec3 u = data.samples[e.first_sample + s + 1].p - data.samples[e.first_sample + s].p;
                lengths[s].push_back(norm(u));
                if (s + 2 >= e.sample_count) continue;
                const Vec3 v = data.samples[e.first_sample + s + 2].p - data.samples[e.first_sample + s + 1].p;
                const double c = dot(u, v) / std::max(norm(u) * norm(v), 1e-300);
                bends.push_back(std::acos(std::clamp(c, -1.0, 1.0)) * kDegrees);
            }
        }
    };
    for (size_t t = 0; t < exemplar.types.size(); ++t) {
        const int ot = output.find_type(exemplar.types[t].name);
        if (ot < 0) continue;
        std::vector<std::vector<double>> ex_len, out_len;
        std::vector<double> ex_bend, out_bend;
        measure(exemplar, static_cast<int>(t), ex_len, ex_bend);
        measure(output, ot, out_len, out_bend);
        if (ex_len.empty() || out_len.empty()) continue;
        ShapeStats s;
        s.type = exemplar.types[t].name;
        s.rigid = exemplar.types[t].rigid;
        double ex_sum = 0.0, out_sum = 0.0;
        size_t ex_n = 0, out_n = 0;
        std::vector<double> deviation;
        for (size_t k = 0; k < ex_len.size() && k < out_len.size(); ++k) {
            double mean = 0.0;
            for (double v : ex_len[k]) mean += v;
            mean /= std::max<size_t>(1, ex_len[k].size());
            ex_sum += mean * ex_len[k].size(), ex_n += ex_len[k].size();
            for (double v : out_len[k]) {
                out_sum += v, ++out_n;
                if (mean > 0.0) deviation.push_back(std::abs(v / mean - 1.0));
            }
        }
        s.spacing_exemplar = ex_n ? ex_sum / ex_n : 0.0;
        s.spacing_output = out_n ? out_sum / out_n : 0.0;
        s.spacing_deviation_p95 = deviation.empty() ? 0.0 : core::quantile_of(deviation, 0.95);
        s.bend_exemplar_p95 = ex_bend.empty() ? 0.0 : core::quantile_of(ex_bend, 0.95);
        s.bend_output_p95 = out_bend.empty() ? 0.0 : core::quantile_of(out_bend, 0.95);
        result.push_back(s);
    }
    return result;
}

double inside_fraction(const Exemplar& data) {
    if (data.samples.empty()) return 1.0;
    long inside = 0;
    for (const Sample& s : data.samples) inside += data.domain.inside(s.p);
    return static_cast<double>(inside) / static_cast<double>(data.samples.size());
}

}  // namespace tessera
