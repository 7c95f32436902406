// The options of neighbourhood-guided editing (EditOptions, tessera/edit.hpp), one row each:
// `tessera edit` makes its flags from this table and edit_elements checks a struct against it.
#include "core/option_rows.hpp"
#include "tessera/edit.hpp"
#include "tessera/option_table.hpp"

namespace tessera {

namespace {

using namespace options;
using O = EditOptions;

OptionTable<O> make_table() {
    OptionTable<O> t;
    t.push_back(number_row<O>(
        "threshold",
        "Largest neighbourhood distance (Eq. 1, squared length units) of an element that receives the "
        "edit; negative = automatic (0.1 x spacing^2 per neighbour of the edited element).",
        [](auto& o) -> auto& { return o.threshold; }, any_finite()));
    t.push_back(number_row<O>(
        "radius", "Neighbourhood radius; 0 = automatic (2 spacings in 2D, 1.5 in 3D).",
        [](auto& o) -> auto& { return o.radius; }, at_least(0)));
    t.push_back(threads_row<O>([](auto& o) -> auto& { return o.threads; }));
    return t;
}

}  // namespace

const OptionTable<EditOptions>& edit_option_table() {
    static const OptionTable<EditOptions> table = make_table();
    return table;
}

}  // namespace tessera
