// synthesize_pcf from an exemplar: analyze_distribution + synthesis of the model, with
// the exemplar's element types (meshes, flags) carried over to the output by name, then
// the crowding repair against the exemplar's close-distance tails (synth_repair.hpp).
#include "pcf/synth_repair.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera {

Arrangement synthesize_pcf(const Exemplar& exemplar, const Domain& domain, const PcfSynthOptions& options,
                           const Progress& progress) {
    const PcfModel model = analyze_distribution(exemplar, options.analysis);
    Arrangement out = synthesize_pcf(model, domain, options, progress);
    for (ElementType& type : out.types) {
        const int t = exemplar.find_type(type.name);
        if (t < 0) continue;
        const auto depends_on = type.depends_on;
        type = exemplar.types[t];
        type.depends_on = depends_on;
    }
    pcf::repair_output(exemplar, domain, options, out);
    return out;
}

}  // namespace tessera
