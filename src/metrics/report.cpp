// The metrics report: what `tessera metrics` prints to compare an output with
// its exemplar. Both PCFs use one r grid and bandwidth (resolved from the
// exemplar unless given), so their curves can be compared bin by bin. Numbers
// that are not finite (g at r = 0, undefined statistics) are written as null,
// since JSON has no infinities.
#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tessera/error.hpp"
#include "tessera/metrics.hpp"

namespace tessera {
namespace {

using Json = nlohmann::ordered_json;

Json finite_or_null(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

Json pcf_json(const PcfResult& pcf) {
    Json out;
    out["bandwidth"] = pcf.bandwidth;
    out["r"] = pcf.r;
    Json pairs = Json::array();
    for (const auto& c : pcf.curves) {
        Json g = Json::array();
        for (const double v : c.g) g.push_back(finite_or_null(v));
        pairs.push_back({{"a", c.name_a}, {"b", c.name_b}, {"g", std::move(g)}});
    }
    out["pairs"] = std::move(pairs);
    return out;
}

struct Summary {
    Json json;
    NearestNeighborStats nn;
    double psi6 = std::nan("");
};

Summary summarize(const Exemplar& data, const PcfResult& pcf) {
    Summary s;
    s.nn = nearest_neighbor_distances(data);
    const bool has_nn = data.elements.size() >= 2;
    Json& j = s.json;
    j["elements"] = data.elements.size();
    std::vector<long long> count(data.types.size(), 0);
    for (const auto& e : data.elements) ++count[e.type];  // types checked by nearest_neighbor_distances
    Json per_class = Json::object();
    for (size_t t = 0; t < data.types.size(); ++t) per_class[data.types[t].name] = count[t];
    j["count_per_class"] = std::move(per_class);
    j["density"] = static_cast<double>(data.elements.size()) / data.domain.measure();
    j["nearest_neighbor"] = {{"mean", has_nn ? Json(s.nn.mean) : Json(nullptr)},
                             {"stddev", has_nn ? Json(s.nn.stddev) : Json(nullptr)},
                             {"min", has_nn ? Json(s.nn.min) : Json(nullptr)},
                             {"max", has_nn ? Json(s.nn.max) : Json(nullptr)}};
    if (data.dimension == 2) {
        s.psi6 = mean_psi6(data);
        j["mean_psi6"] = finite_or_null(s.psi6);
    }
    j["pcf"] = pcf_json(pcf);
    return s;
}

// Crowding, holes, shapes and the inside share (the "Defects" of docs/metrics.md).
Json defects_json(const Exemplar& exemplar, const Exemplar& output) {
    Json j;
    Json pairs = Json::array();
    for (const CrowdingPair& c : crowding(exemplar, output))
        pairs.push_back({{"a", c.name_a},
                         {"b", c.name_b},
                         {"threshold", c.threshold},
                         {"exemplar_share", c.exemplar_share},
                         {"output_share", c.output_share},
                         {"exemplar_coincident", c.exemplar_coincident},
                         {"output_coincident", c.output_coincident}});
    j["crowding"] = std::move(pairs);
    const EmptyCircle ex = largest_empty_circle(exemplar), out = largest_empty_circle(output);
    j["largest_empty_circle"] = {{"exemplar", ex.radius},
                                 {"output", out.radius},
                                 {"ratio", ex.radius > 0.0 ? Json(out.radius / ex.radius) : Json(nullptr)},
                                 {"output_center", {out.center.x, out.center.y, out.center.z}}};
    Json shapes = Json::array();
    for (const ShapeStats& s : shape_statistics(exemplar, output))
        shapes.push_back({{"type", s.type},
                          {"rigid", s.rigid},
                          {"spacing_exemplar", s.spacing_exemplar},
                          {"spacing_output", s.spacing_output},
                          {"spacing_deviation_p95", s.spacing_deviation_p95},
                          {"bend_exemplar_p95", s.bend_exemplar_p95},
                          {"bend_output_p95", s.bend_output_p95}});
    j["shapes"] = std::move(shapes);
    j["inside_fraction"] = inside_fraction(output);
    return j;
}

}  // namespace

std::string metrics_report_json(const Exemplar& exemplar, const Exemplar& output, const PcfOptions& options) {
    if (exemplar.dimension != output.dimension)
        throw Error(ErrorKind::input, "metrics: the exemplar is " + std::to_string(exemplar.dimension) +
                                          "D but the output is " + std::to_string(output.dimension) + "D");
    const PcfResult pcf_exemplar = pair_correlation(exemplar, options);
    const PcfResult pcf_output = pair_correlation_on_grid_of(output, pcf_exemplar);

    const Summary ex = summarize(exemplar, pcf_exemplar);
    const Summary out = summarize(output, pcf_output);
    Json report;
    report["dimension"] = exemplar.dimension;
    report["exemplar"] = ex.json;
    report["output"] = out.json;
    report["pcf_relative_error"] = finite_or_null(pcf_relative_error(pcf_exemplar, pcf_output));
    const bool nn_defined = exemplar.elements.size() >= 2 && output.elements.size() >= 2 && ex.nn.mean > 0.0;
    report["nn_mean_relative_difference"] = nn_defined ? Json((out.nn.mean - ex.nn.mean) / ex.nn.mean) : Json(nullptr);
    if (exemplar.dimension == 2) report["psi6_difference"] = finite_or_null(out.psi6 - ex.psi6);
    report["defects"] = defects_json(exemplar, output);
    return report.dump(2);
}

}  // namespace tessera
