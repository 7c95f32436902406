// The options of synthesis from pair correlation functions (PcfSynthOptions,
// tessera/pcf_synthesis.hpp), one row each: `tessera synth --method pcf` makes its flags
// from this table and tessera.synthesize(method="pcf") its keywords (tessera/option_table.hpp).
#include "core/option_rows.hpp"
#include "tessera/option_table.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera {

namespace {

using namespace options;
using O = PcfSynthOptions;

OptionTable<O> make_table() {
    OptionTable<O> t;
    t.push_back(seed_row<O>([](auto& o) -> auto& { return o.seed; }));
    t.push_back(integer_row<O>(
        "iterations", "At most this many refinement sweeps per class (0 = no refinement).",
        [](auto& o) -> auto& { return o.max_iterations; }, at_least(0)));
    t.push_back(threads_row<O>([](auto& o) -> auto& { return o.threads; }));
    t.push_back(integer_row<O>(
        "relax_sweeps",
        "Sweeps of the pair-correlation relaxation at the end (synthesis from an exemplar): "
        "small moves towards the exemplar's pair correlation of every class pair; 0 = off.",
        [](auto& o) -> auto& { return o.relax_sweeps; }, between(0, 1000)));
    t.push_back(integer_row<O>(
        "max_fails",
        "Successive rejected candidates after which a class's remaining elements are placed "
        "by grid search (0 = grid search from the start).",
        [](auto& o) -> auto& { return o.max_fails; }, at_least(0)));
    t.push_back(integer_row<O>(
        "grid_cells", "Cells of the grid search along the longer side of the domain.",
        [](auto& o) -> auto& { return o.grid_cells; }, between(1, 4096)));
    t.push_back(number_row<O>(
        "epsilon0", "Error threshold of the first candidate of a class (Algorithm 1).",
        [](auto& o) -> auto& { return o.epsilon0; }, at_least(0)));
    t.push_back(number_row<O>(
        "epsilon_step", "Increase of the threshold with every successive rejection.",
        [](auto& o) -> auto& { return o.epsilon_step; }, at_least(0)));
    t.push_back(number_row<O>(
        "convergence",
        "A class's refinement stops when a sweep moves its elements by less than this x r_max "
        "in total (0: never).",
        [](auto& o) -> auto& { return o.convergence; }, at_least(0)));
    t.push_back(number_row<O>(
        "stall",
        "A class's refinement also stops when its lowest PCF error falls by less than this "
        "fraction per sweep over 10 sweeps (0: never).",
        [](auto& o) -> auto& { return o.stall; }, at_least(0)));
    t.push_back(integer_row<O>(
        "outlier_rounds", "Rounds of re-placing elements whose individual PCFs leave the validity region.",
        [](auto& o) -> auto& { return o.outlier_rounds; }, at_least(0)));
    // The analysis's rows, declared once in its own table, read through `analysis`.
    for (const OptionSpec<PcfAnalysisSettings>& a : pcf_analysis_option_table()) {
        OptionSpec<O> s;
        static_cast<OptionInfo&>(s) = a;
        s.get = [get = a.get](const O& o) { return get(o.analysis); };
        s.set = [set = a.set](O& o, const OptionValue& v, const OptionContext& c) { set(o.analysis, v, c); };
        t.push_back(std::move(s));
    }
    return t;
}

}  // namespace

const OptionTable<PcfSynthOptions>& pcf_option_table() {
    static const OptionTable<PcfSynthOptions> table = make_table();
    return table;
}

}  // namespace tessera
