// The options of the PCF method's analysis (PcfAnalysisSettings, tessera/pcf_synthesis.hpp),
// one row each: `tessera analyze` makes its flags from this table, analyze_distribution checks
// a struct against it, and the synthesis table (pcf_option_table.cpp) reuses its rows.
#include "core/option_rows.hpp"
#include "tessera/option_table.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera {

namespace {

using namespace options;
using O = PcfAnalysisSettings;

OptionTable<O> make_table() {
    OptionTable<O> t;
    t.push_back(number_row<O>(
        "sigma", "Width of the Gaussian kernel on the normalised distance axis.",
        [](auto& o) -> auto& { return o.sigma; }, above(0)));
    t.push_back(number_row<O>(
        "step", "Spacing of the PCF's values on the normalised distance axis.",
        [](auto& o) -> auto& { return o.step; }, above(0)));
    t.push_back(number_row<O>(
        "extent",
        "Neighbourhood of the PCFs on the normalised axis (points up to extent, disks up to "
        "3 + extent).",
        [](auto& o) -> auto& { return o.extent; }, above(0)));
    return t;
}

}  // namespace

const OptionTable<PcfAnalysisSettings>& pcf_analysis_option_table() {
    static const OptionTable<PcfAnalysisSettings> table = make_table();
    return table;
}

}  // namespace tessera
