// The options of on-demand growth (GrowOptions, tessera/grow.hpp), one row each:
// `tessera grow` makes its flags from this table and tessera.Grower its keywords
// (tessera/option_table.hpp); Grower's constructor checks a struct against it.
#include "core/option_rows.hpp"
#include "tessera/grow.hpp"
#include "tessera/option_table.hpp"

namespace tessera {

namespace {

using namespace options;
using O = GrowOptions;

OptionTable<O> make_table() {
    OptionTable<O> t;
    t.push_back(seed_row<O>([](auto& o) -> auto& { return o.seed; }));
    t.push_back(threads_row<O>([](auto& o) -> auto& { return o.threads; }));
    t.push_back(number_row<O>(
        "radius", "Neighbourhood radius; 0 = automatic (as 'tessera synth').",
        [](auto& o) -> auto& { return o.radius; }, at_least(0)));
    t.push_back(choice_row<O>(
        "choice",
        "How a round chooses its candidates: patch (copy the best-fitting input patch, then "
        "filter) or mcts (the paper's single-player Monte-Carlo tree search).",
        [](auto& o) -> auto& { return o.choice; },
        std::vector<std::pair<std::string, GrowChoice>>{{"patch", GrowChoice::patch},
                                                        {"mcts", GrowChoice::mcts}}));
    t.push_back(number_row<O>(
        "patch_extent", "patch: extent of the input patch copied at each horizon element, in radii.",
        [](auto& o) -> auto& { return o.patch_extent; }, at_least(1)));
    t.push_back(number_row<O>(
        "threshold", "Threshold c of the partial pair assignment, as a share of the mean spacing.",
        [](auto& o) -> auto& { return o.threshold; }, above_up_to(0, 1)));
    t.push_back(number_row<O>(
        "energy_factor", "t: candidates whose neighbourhood energy exceeds t x the round's mean are dropped.",
        [](auto& o) -> auto& { return o.energy_factor; }, above(1)));
    t.push_back(number_row<O>(
        "lock_distance",
        "Elements further than this from the horizon (in radii) are fixed in the position "
        "solve (Eq. 7).",
        [](auto& o) -> auto& { return o.lock_distance; }, above(0)));
    t.push_back(number_row<O>(
        "band_weight",
        "Weight of the pull toward the current position at the lock distance (Eq. 7's w), "
        "rising linearly from 0 at the horizon.",
        [](auto& o) -> auto& { return o.band_weight; }, at_least(0)));
    t.push_back(integer_row<O>(
        "solves", "Least-squares position solves per round (one search, then a pairing before each solve).",
        [](auto& o) -> auto& { return o.solves; }, between(0, 100)));
    t.push_back(integer_row<O>(
        "votes", "Votes an element needs before its type is reassigned (section V.B).",
        [](auto& o) -> auto& { return o.votes; }, at_least(1)));
    t.push_back(integer_row<O>(
        "k", "Size of each input element's similarity set (k-coherence).",
        [](auto& o) -> auto& { return o.k; }, at_least(1)));
    t.push_back(number_row<O>(
        "alpha",
        "Weight of the attribute (type) term, in squared length units; negative = automatic "
        "(mean nearest-neighbour distance squared).",
        [](auto& o) -> auto& { return o.alpha; }, any_finite()));
    t.push_back(integer_row<O>(
        "playouts", "mcts: play-outs per round.", [](auto& o) -> auto& { return o.playouts; },
        between(1, 100000)));
    t.push_back(number_row<O>(
        "explore", "mcts: the exploration constant C of the selection value (Eq. 5).",
        [](auto& o) -> auto& { return o.explore; }, at_least(0)));
    t.push_back(number_row<O>(
        "exploit", "mcts: the constant D of the selection value's deviation term (Eq. 5).",
        [](auto& o) -> auto& { return o.exploit; }, at_least(0)));
    t.push_back(integer_row<O>(
        "max_rounds", "Bound on the rounds of one grow call (reported when it stops the growth).",
        [](auto& o) -> auto& { return o.max_rounds; }, at_least(1)));
    t.push_back(flag_row<O>(
        "stop_at_horizon",
        "With a region: stop where the horizon proposes nothing (the paper's growth) instead "
        "of filling what it did not reach by neighbourhood synthesis next to it.",
        [](auto& o) -> auto& { return o.stop_at_horizon; }));
    t.push_back(integer_row<O>(
        "relax_sweeps",
        "With a region: sweeps of the final pair-correlation relaxation of the elements grown "
        "(as 'tessera synth'); 0 = none; negative = automatic (4 for a soft pattern, whose "
        "closest pairs lie well under its typical distance, else 1). Single-sample elements.",
        [](auto& o) -> auto& { return o.relax_sweeps; }, between(-1, 1000)));
    t.push_back(text_row<O>(
        "field", field_doc, [](const O& o) { return o.field.active() ? o.field.describe() : std::string(); },
        [](O& o, const std::string& text, const OptionContext& c) {
            o.field =
                text.empty() ? OrientationField{} : OrientationField::parse(text, c.dimension, c.as_written);
        },
        true));
    return t;
}

}  // namespace

const OptionTable<GrowOptions>& grow_option_table() {
    static const OptionTable<GrowOptions> table = make_table();
    return table;
}

}  // namespace tessera
