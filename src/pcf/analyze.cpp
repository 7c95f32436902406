// analyze_distribution: the analysis stage of the PCF method (sections 3 to 5). Checks
// the exemplar and the settings, builds the dependency DAG and its topological order,
// and estimates one PCF per class and per DAG edge with the envelopes of the individual
// PCFs, on the normalised axis of tessera/pcf_synthesis.hpp.
#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "pcf/dependency_graph.hpp"
#include "pcf/pcf_estimate.hpp"
#include "pcf/pcf_math.hpp"
#include "pcf/sparse_classes.hpp"
#include "tessera/error.hpp"
#include "tessera/option_table.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera {
namespace pcf {
namespace {

// More bins than this is a mistake (step far too small for the extent), not a wish.
constexpr int max_bins = 100000;

std::string number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

}  // namespace

void check_analysis_settings(const PcfAnalysisSettings& s) {
    check_options(pcf_analysis_option_table(), s);  // each field against its row, naming it
    if ((3.0 + s.extent) / s.step > max_bins)
        throw Error(ErrorKind::option, "pcf extent / step gives more than " + std::to_string(max_bins) +
                                           " values on the axis (extent " + number(s.extent) + ", step " +
                                           number(s.step) + ")");
}

namespace {

// The PCFs of a DAG: for each class in topological order, its own PCF, then one per
// parent in the order of parents[c]. Synthesis then finds a class's active PCFs together.
std::vector<PcfEnvelope> pcf_pairs(const std::vector<std::vector<int>>& parents,
                                   const std::vector<int>& order) {
    std::vector<PcfEnvelope> pairs;
    for (int c : order) {
        PcfEnvelope within;
        within.parent = within.child = c;
        pairs.push_back(within);
        for (int p : parents[c]) {
            PcfEnvelope edge;
            edge.parent = p;
            edge.child = c;
            pairs.push_back(edge);
        }
    }
    return pairs;
}

}  // namespace
}  // namespace pcf

PcfModel analyze_distribution(const Exemplar& exemplar, const PcfAnalysisSettings& settings, int threads) {
    pcf::check_analysis_settings(settings);
    const int classes = static_cast<int>(exemplar.types.size());
    std::vector<int> class_of_type(classes);
    for (int t = 0; t < classes; ++t) class_of_type[t] = t;
    const pcf::PcfPoints points = pcf::pcf_points(exemplar, class_of_type, "PCF analysis");

    PcfModel model;
    model.settings = settings;
    for (const auto& t : exemplar.types) model.classes.push_back(t.name);
    model.counts.assign(classes, 0);
    model.radii.assign(classes, {});
    for (size_t i = 0; i < points.p.size(); ++i) {
        ++model.counts[points.cls[i]];
        model.radii[points.cls[i]].push_back(points.radius[i]);
        model.disks = model.disks || points.radius[i] > 0.0;
    }
    if (points.p.empty()) throw Error(ErrorKind::input, "PCF analysis: the exemplar has no elements");
    for (int c = 0; c < classes; ++c) {
        // A class with 1 to 3 elements is placed by the fallback of PcfSparseClass.
        if (model.counts[c] < 1)
            throw Error(ErrorKind::input, "PCF analysis: class '" + model.classes[c] +
                                              "' has no elements; each class needs at least 1");
        std::sort(model.radii[c].begin(), model.radii[c].end(), std::greater<>());
    }
    model.parents = pcf::dependency_parents(exemplar.types);
    model.order = pcf::topological_order(model.parents, model.classes);

    model.area = exemplar.domain.measure();
    if (!(model.area > 0.0))
        throw Error(ErrorKind::domain, "PCF analysis: the exemplar's domain has no area");
    model.r_max = pcf_r_max(model.area, static_cast<int>(points.p.size()));
    const pcf::Axis axis = pcf::make_axis(settings, model.disks);
    model.x.resize(axis.bins);
    for (int k = 0; k < axis.bins; ++k) model.x[k] = axis.x(k);
    model.pcfs = pcf::estimate_pcfs(points, classes, exemplar.domain, model.area, model.r_max, axis,
                                    pcf::pcf_pairs(model.parents, model.order), threads);
    // Class pairs without a PCF: their closest approach, up to the salient configurations.
    std::vector<std::pair<int, int>> unrelated;
    for (int a = 0; a < classes; ++a)
        for (int b = a + 1; b < classes; ++b) {
            const auto depends = [&](int child, int parent) {
                return std::find(model.parents[child].begin(), model.parents[child].end(), parent) !=
                       model.parents[child].end();
            };
            if (!depends(a, b) && !depends(b, a)) unrelated.push_back({a, b});
        }
    const std::vector<double> closest = pcf::closest_approaches(
        points, exemplar.domain, model.r_max, unrelated, classes, pcf::separation_cap(settings, model.disks));
    for (size_t q = 0; q < unrelated.size(); ++q)
        model.separations.push_back({unrelated[q].first, unrelated[q].second, closest[q]});
    model.sparse = pcf::analyse_sparse_classes(points, model);
    return model;
}

}  // namespace tessera
