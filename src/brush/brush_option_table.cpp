// The options of brushing (BrushOptions, tessera/brush.hpp), one row each: `tessera brush`
// makes its flags from this table, a session file's "options" and the studio's requests are
// checked against it (tessera/option_table.hpp); BrushCanvas's constructor checks a struct.
#include "core/option_rows.hpp"
#include "tessera/brush.hpp"
#include "tessera/option_table.hpp"

namespace tessera {

namespace {

using namespace options;
using O = BrushOptions;

void add_weights(OptionTable<O>& t) {
    t.push_back(number_row<O>("w_distribution", "Weight of the distribution term (Eq. 1).",
                              [](auto& o) -> auto& { return o.w_distribution; }, at_least(0)));
    t.push_back(number_row<O>("w_conflict", "Weight of the conflict check (Eq. 3).",
                              [](auto& o) -> auto& { return o.w_conflict; }, at_least(0)));
    t.push_back(number_row<O>("w_graph", "Weight of the graph similarity that keeps element shapes (Eq. 4).",
                              [](auto& o) -> auto& { return o.w_graph; }, above(0)));
    t.push_back(number_row<O>("w_alignment", "Weight of the field alignment to the strokes (Eq. 5).",
                              [](auto& o) -> auto& { return o.w_alignment; }, at_least(0)));
    t.push_back(number_row<O>("w_continuity", "Weight of the field continuity between nearby samples (Eq. 6).",
                              [](auto& o) -> auto& { return o.w_continuity; }, at_least(0)));
    t.push_back(number_row<O>("w_rigidity", "Weight of the rigidity of deformable elements (Eq. 7).",
                              [](auto& o) -> auto& { return o.w_rigidity; }, at_least(0)));
}

OptionTable<O> make_table() {
    OptionTable<O> t;
    t.push_back(seed_row<O>([](auto& o) -> auto& { return o.seed; }));
    t.push_back(threads_row<O>([](auto& o) -> auto& { return o.threads; }));
    t.push_back(number_row<O>("radius", "Neighbourhood radius of the distribution term, in spacings.",
                              [](auto& o) -> auto& { return o.radius; }, above(0)));
    t.push_back(integer_row<O>("iterations", "Solver iterations of fill and optimize (search/assign + L-BFGS).",
                               [](auto& o) -> auto& { return o.iterations; }, between(0, 1000)));
    t.push_back(integer_row<O>("lbfgs_iterations", "Bound on the iterations of one L-BFGS orientation solve.",
                               [](auto& o) -> auto& { return o.lbfgs_iterations; }, between(1, 100000)));
    t.push_back(number_row<O>("sigma", "sigma of the falloffs of Eq. 5 and Eq. 6, in spacings.",
                              [](auto& o) -> auto& { return o.sigma; }, above(0)));
    add_weights(t);
    t.push_back(number_row<O>("stroke_width", "Width of a paint or erase stroke that gives none, in spacings.",
                              [](auto& o) -> auto& { return o.stroke_width; }, above(0)));
    return t;
}

}  // namespace

const OptionTable<BrushOptions>& brush_option_table() {
    static const OptionTable<BrushOptions> table = make_table();
    return table;
}

}  // namespace tessera
