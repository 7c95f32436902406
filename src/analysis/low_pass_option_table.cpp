// The options of the motion analysis (LowPassOptions, tessera/motion_analysis.hpp), one row
// each: `tessera analyze --decompose` makes its flags from this table, Python's
// tessera.decompose its keywords, and decompose_motion checks a struct against it.
#include "core/option_rows.hpp"
#include "tessera/motion_analysis.hpp"
#include "tessera/option_table.hpp"

namespace tessera {

namespace {

using namespace options;
using O = LowPassOptions;

OptionTable<O> make_table() {
    OptionTable<O> t;
    t.push_back(number_row<O>(
        "spatial_radius",
        "Particles: radius of the Gaussian kernel over the samples of other elements at the "
        "same frame, in the exemplar's units (sigma = radius / 2, weights falling to 0 at the "
        "edge; shrunk to the distance to the domain's bounding box); 0 = automatic (2 x the "
        "mean nearest-neighbour distance of frame 0).",
        [](auto& o) -> auto& { return o.spatial_radius; }, at_least(0)));
    t.push_back(integer_row<O>(
        "topology_radius",
        "Threads and sheets: kernel half-width in samples along the element's own topology "
        "(thread index; sheet rows and columns), shrunk symmetrically at the ends; 0 = none.",
        [](auto& o) -> auto& { return o.topology_radius; }, between(0, 1000000)));
    t.push_back(integer_row<O>(
        "temporal_radius",
        "Kernel half-width in frames, shrunk symmetrically at the first and last frames; "
        "0 = none.",
        [](auto& o) -> auto& { return o.temporal_radius; }, between(0, 1000000)));
    t.push_back(threads_row<O>([](auto& o) -> auto& { return o.threads; }));
    return t;
}

}  // namespace

const OptionTable<LowPassOptions>& low_pass_option_table() {
    static const OptionTable<LowPassOptions> table = make_table();
    return table;
}

}  // namespace tessera
