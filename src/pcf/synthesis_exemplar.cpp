// synthesize_pcf from an exemplar: analyze_distribution + synthesis of the model, with
// the exemplar's element types (meshes, flags) carried over to the output by name.
#include "tessera/error.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera {

// MERGE NOTE: analyze_distribution is defined by the PCF analysis (developed on a
// separate branch). Until it is part of the library this reference is weak, so that the
// library, the CLI and the tests link without it and the call below reports the gap.
// Remove this declaration and the null check once the analysis is merged: a weak
// reference does not pull the analysis out of the static library by itself.
PcfModel analyze_distribution(const Exemplar& exemplar, const PcfAnalysisSettings& settings) __attribute__((weak));

Arrangement synthesize_pcf(const Exemplar& exemplar, const Domain& domain, const PcfSynthOptions& options,
                           const Progress& progress) {
    if (&analyze_distribution == nullptr)
        throw Error(ErrorKind::internal, "the PCF analysis (analyze_distribution) is not part of this build");
    const PcfModel model = analyze_distribution(exemplar, options.analysis);
    Arrangement out = synthesize_pcf(model, domain, options, progress);
    for (ElementType& type : out.types) {
        const int t = exemplar.find_type(type.name);
        if (t < 0) continue;
        const auto depends_on = type.depends_on;
        type = exemplar.types[t];
        type.depends_on = depends_on;
    }
    return out;
}

}  // namespace tessera
