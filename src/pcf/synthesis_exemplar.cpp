// synthesize_pcf from an exemplar: analyze_distribution + synthesis of the model, with
// the exemplar's element types (meshes, flags) carried over to the output by name, then
// the crowding repair against the exemplar's close-distance tails (synth_repair.hpp).
#include "core/run_clock.hpp"
#include "pcf/synth_holes.hpp"
#include "pcf/synth_relax.hpp"
#include "pcf/synth_repair.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera {

Arrangement synthesize_pcf(const Exemplar& exemplar, const Domain& domain, const PcfSynthOptions& options,
                           const Progress& progress) {
    const auto t0 = core::Clock::now();
    core::report(progress, {"analysis", -1, 0, 0.0, 0.0});
    const PcfModel model = analyze_distribution(exemplar, options.analysis, options.threads);
    // The model's synthesis reports its stages; its "done" waits for the repair.
    ProgressEvent done;
    const Progress inner = [&](const ProgressEvent& e) {
        if (e.stage == "done") {
            done = e;
            return true;
        }
        ProgressEvent scaled = e;  // the model's synthesis is 5% to 90% of this run
        scaled.fraction = 0.05 + 0.85 * e.fraction;
        return !progress || progress(scaled);
    };
    Arrangement out = synthesize_pcf(model, domain, options, progress ? inner : Progress{});
    for (ElementType& type : out.types) {
        const int t = exemplar.find_type(type.name);
        if (t < 0) continue;
        const auto depends_on = type.depends_on;
        type = exemplar.types[t];
        type.depends_on = depends_on;
    }
    core::report(progress, {"repair", -1, 0, 0.0, core::seconds_since(t0), 0.9});
    pcf::relax_output(exemplar, domain, options, out);
    pcf::close_holes(exemplar, domain, options, out);
    pcf::repair_output(exemplar, domain, options, out);
    out.stats.total_seconds = core::seconds_since(t0);
    done.elapsed_s = out.stats.total_seconds;
    done.fraction = 1.0;
    core::report(progress, done);
    return out;
}

Arrangement synthesize_pcf_next_to(const Exemplar& exemplar, const PcfModel& model, const Domain& domain,
                                   const Exemplar& fixed, const Domain& fill, const PcfSynthOptions& options,
                                   const Progress& progress) {
    const Arrangement fresh = synthesize_pcf_next_to(model, domain, fixed, fill, options, progress);
    // The exemplar-level passes see the fixed elements (locked: they never move) next to
    // the new ones, so that the relaxation, the hole filling and the crowding repair
    // measure the neighbourhoods the user will see across the fixed elements' border.
    Arrangement both = fresh;
    for (ElementType& type : both.types)
        if (const int t = exemplar.find_type(type.name); t >= 0) {
            const auto depends_on = type.depends_on;
            type = exemplar.types[t];
            type.depends_on = depends_on;
        }
    both.elements.clear();
    both.samples.clear();
    for (const Element& e : fixed.elements) both.elements[both.add_element(e.type, {e.position}, e.radius)].locked = true;
    for (const Element& e : fresh.elements) both.add_element(e.type, {e.position}, e.radius);
    // Their domain is the region to fill: they move new elements only within it, and look
    // for holes only there (the fixed elements' part is theirs to answer for).
    pcf::relax_output(exemplar, fill, options, both);
    pcf::close_holes(exemplar, fill, options, both);
    pcf::repair_output(exemplar, fill, options, both);
    Arrangement out = both;
    out.elements.clear();
    out.samples.clear();
    for (const Element& e : both.elements)
        if (!e.locked) out.add_element(e.type, {e.position}, e.radius);
    return out;
}

}  // namespace tessera
