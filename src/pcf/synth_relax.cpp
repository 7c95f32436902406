// The final pair correlation relaxation of PCF outputs (synth_relax.hpp).
#include "pcf/synth_relax.hpp"

#include "core/parallel.hpp"
#include "det/input_index.hpp"
#include "det/pair_relaxation.hpp"

namespace tessera::pcf {
namespace {

// The exemplar with its types in the output's order (the model's), so class indices agree.
Exemplar in_output_order(const Exemplar& exemplar, const Arrangement& out, bool& complete) {
    Exemplar ordered = exemplar;
    std::vector<int> to_output(exemplar.types.size(), -1);
    complete = exemplar.types.size() == out.types.size();
    for (size_t t = 0; t < out.types.size() && complete; ++t) {
        const int e = exemplar.find_type(out.types[t].name);
        if (e < 0) complete = false; else to_output[e] = static_cast<int>(t), ordered.types[t] = exemplar.types[e];
    }
    if (!complete) return ordered;
    for (Element& e : ordered.elements) e.type = to_output[e.type];
    return ordered;
}

}  // namespace

void relax_output(const Exemplar& exemplar, const Domain& domain, const PcfSynthOptions& options, Arrangement& out) {
    if (out.dimension != 2 || out.elements.empty() || options.relax_sweeps == 0) return;
    // Disks are matched on the disk metric's axis (Eq. 7-10), whose envelopes the plain
    // distances' pair correlation would pull the output out of: points only.
    for (const Element& e : exemplar.elements)
        if (e.radius > 0.0) return;
    bool complete = false;
    const Exemplar ordered = in_output_order(exemplar, out, complete);
    if (!complete) return;
    const det::Params params = det::resolve_params(ordered, DetOptions{});
    const det::PairRelaxation relaxation(ordered, params);
    if (!relaxation.applies()) return;
    relaxation.relax(out, domain, {}, options.relax_sweeps, options.seed, core::resolve_threads(options.threads));
}

}  // namespace tessera::pcf
