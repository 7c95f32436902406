// The options of graph synthesis (GraphMotionOptions, tessera/graph_motion.hpp), one row
// each: enrich_by_graph checks them here, so a bad value is a one-line Error naming the field.
#include "core/option_rows.hpp"
#include "dynamic/graph_path.hpp"
#include "tessera/graph_motion.hpp"

namespace tessera {

namespace {

using namespace options;
using O = GraphMotionOptions;

OptionTable<O> make_table() {
    OptionTable<O> t;
    t.push_back(seed_row<O>([](auto& o) -> auto& { return o.seed; }));
    t.push_back(threads_row<O>([](auto& o) -> auto& { return o.threads; }));
    t.push_back(integer_row<O>("frames", "Frames of the enriched exemplar, the still's included.",
                               [](auto& o) -> auto& { return o.frames; }, between(2, 100000)));
    t.push_back(integer_row<O>("path_length", "n: the steps of every motion path s_0 .. s_n (Eq. 13).",
                               [](auto& o) -> auto& { return o.path_length; },
                               between(1, dynamic::max_path_steps)));
    t.push_back(number_row<O>("alpha", "Weight of Eq. 13's node diversity term (the paper's 0.5).",
                              [](auto& o) -> auto& { return o.alpha; }, at_least(0)));
    t.push_back(integer_row<O>("neighbours", "k: a node's immediate neighbours; s_b is the farthest of them.",
                               [](auto& o) -> auto& { return o.neighbours; }, between(1, 64)));
    t.push_back(integer_row<O>("anneal_iterations", "Simulated annealing iterations per path.",
                               [](auto& o) -> auto& { return o.anneal_iterations; }, between(1, 1000000)));
    t.push_back(integer_row<O>("max_nodes", "At most this many graph nodes (drawn by the seed).",
                               [](auto& o) -> auto& { return o.max_nodes; }, between(2, 100000)));
    t.push_back(number_row<O>("radius",
                              "Neighbourhood radius in the still's units; 0 = automatic (1.5 x the mean "
                              "nearest-neighbour distance).",
                              [](auto& o) -> auto& { return o.radius; }, at_least(0)));
    t.push_back(integer_row<O>("sweeps", "Jacobi sweeps of the least-squares assignment per frame (Eq. 7).",
                               [](auto& o) -> auto& { return o.sweeps; }, between(1, 10000)));
    return t;
}

}  // namespace

const OptionTable<GraphMotionOptions>& graph_motion_option_table() {
    static const OptionTable<GraphMotionOptions> table = make_table();
    return table;
}

}  // namespace tessera
