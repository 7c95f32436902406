// measure_distribution and compare_distribution: an arrangement's PCFs on a model's
// axis and class pairs, and the acceptance measures that hold an output against the
// model it was synthesised from (tessera/pcf_synthesis.hpp).
#include <algorithm>
#include <cmath>

#include "pcf/pcf_estimate.hpp"
#include "pcf/pcf_math.hpp"
#include "tessera/error.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera {

std::vector<PcfEnvelope> measure_distribution(const PcfModel& model, const Exemplar& data, int threads) {
    pcf::check_analysis_settings(model.settings);
    if (!(model.r_max > 0.0)) throw Error(ErrorKind::option, "PCF measure: the model's r_max must be > 0");
    const int classes = static_cast<int>(model.classes.size());
    for (const PcfEnvelope& e : model.pcfs)
        if (e.parent < 0 || e.parent >= classes || e.child < 0 || e.child >= classes)
            throw Error(ErrorKind::option, "PCF measure: the model has a PCF with an unknown class index");
    // Classes are matched by name: an output may list its types in another order, and
    // types the model does not know are left out.
    std::vector<int> class_of_type(data.types.size(), -1);
    for (size_t t = 0; t < data.types.size(); ++t) {
        const auto it = std::find(model.classes.begin(), model.classes.end(), data.types[t].name);
        if (it != model.classes.end()) class_of_type[t] = static_cast<int>(it - model.classes.begin());
    }
    const pcf::PcfPoints points = pcf::pcf_points(data, class_of_type, "PCF measure");
    const double area = data.domain.measure();
    if (!(area > 0.0)) throw Error(ErrorKind::domain, "PCF measure: the arrangement's domain has no area");
    return pcf::estimate_pcfs(points, classes, data.domain, area, model.r_max,
                              pcf::make_axis(model.settings, model.disks), model.pcfs, threads);
}

PcfQuality compare_distribution(const PcfModel& model, const Exemplar& exemplar, const Exemplar& output) {
    PcfQuality q;
    const std::vector<PcfEnvelope> measured = measure_distribution(model, output);
    for (size_t p = 0; p < measured.size(); ++p) {
        const PcfEnvelope& target = model.pcfs[p];
        const std::vector<double>& mean = measured[p].mean;
        int inside = 0;
        for (size_t k = 0; k < mean.size(); ++k) {
            // A relative slack of 1e-9 so that bins where the envelope is a single value
            // (0 below a hard-core distance) count as inside when the output matches it.
            const double slack = 1e-9 * std::max(1.0, std::abs(target.upper[k]));
            inside += mean[k] >= target.lower[k] - slack && mean[k] <= target.upper[k] + slack;
        }
        q.inside_fraction.push_back(mean.empty() ? 0.0 : static_cast<double>(inside) / mean.size());
    }
    const double area = output.domain.measure();
    for (size_t c = 0; c < model.classes.size(); ++c) {
        int count = 0;
        for (const Element& e : output.elements)
            count += e.type >= 0 && e.type < static_cast<int>(output.types.size()) &&
                     output.types[e.type].name == model.classes[c];
        const double expected = model.counts[c] / model.area * area;
        q.count_ratio.push_back(expected > 0.0 ? count / expected : 0.0);
    }
    q.input_shares = disk_configurations(exemplar, model.r_max);
    q.output_shares = disk_configurations(output, model.r_max);
    return q;
}

}  // namespace tessera
