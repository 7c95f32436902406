// The options of dynamic synthesis (DynamicOptions, tessera/dynamic.hpp), one row each:
// `tessera synth --method dynamic` makes its flags from this table and Python's
// synthesize(method="dynamic") its keywords (tessera/option_table.hpp).
#include "core/option_rows.hpp"
#include "dynamic/graph_exemplar.hpp"
#include "dynamic/st_neighbourhood.hpp"
#include "tessera/dynamic.hpp"
#include "tessera/error.hpp"
#include "tessera/option_table.hpp"

namespace tessera {

namespace {

using namespace options;
using O = DynamicOptions;

Vec3 parse_flow(const std::string& text, const std::string& as_written) {
    if (const std::optional<Vec3> v = parse_vector_components(text)) return *v;
    throw Error(ErrorKind::option, as_written + " must be a vector X,Y or X,Y,Z of finite numbers, got '" + text + "'");
}

void add_neighbourhood_rows(OptionTable<O>& t) {
    t.push_back(number_row<O>("radius",
                              "Spatial neighbourhood radius in the exemplar's units; 0 = automatic (1.5 x the "
                              "mean nearest-neighbour distance: the 1-ring).",
                              [](auto& o) -> auto& { return o.radius; }, at_least(0)));
    t.push_back(integer_row<O>("temporal_size", "Frames in a neighbourhood, the sample's own included (causal).",
                               [](auto& o) -> auto& { return o.temporal_size; }, between(1, dynamic::max_temporal)));
    t.push_back(choice_row<O>(
        "shape",
        "Neighbourhood shape: compact (spatial neighbours + the sample's temporal trail) or full (every "
        "sample within the radius in every frame of the window).",
        [](auto& o) -> auto& { return o.shape; },
        std::vector<std::pair<std::string, NeighbourhoodShape>>{{"compact", NeighbourhoodShape::compact},
                                                                {"full", NeighbourhoodShape::full}}));
    t.push_back(number_row<O>("sigma_p",
                              "Smooth synthesis: spatial falloff sigma_p of Eq. 10, in neighbourhood radii; 0 = none.",
                              [](auto& o) -> auto& { return o.sigma_p; }, at_least(0)));
    t.push_back(number_row<O>("sigma_t", "Smooth synthesis: temporal falloff sigma_t of Eq. 10, in frames; 0 = none.",
                              [](auto& o) -> auto& { return o.sigma_t; }, at_least(0)));
    t.push_back(number_row<O>("alpha",
                              "Weight of a type mismatch between paired neighbours, in squared length units; "
                              "negative = automatic (mean nearest-neighbour distance squared).",
                              [](auto& o) -> auto& { return o.alpha; }, any_finite()));
}

void add_solver_rows(OptionTable<O>& t) {
    t.push_back(integer_row<O>("frames", "Output frames; 0 = as many as the exemplar has.",
                               [](auto& o) -> auto& { return o.frames; }, between(0, 1000000)));
    t.push_back(dynamic::graph_frames_row());  // graph synthesis for a still (graph_exemplar.cpp)
    t.push_back(integer_row<O>("matches",
                               "N best input matches blended by Eq. 11-12 (smooth synthesis); 1 = the basic algorithm.",
                               [](auto& o) -> auto& { return o.matches; }, between(1, 8)));
    t.push_back(integer_row<O>("iterations", "Search + assignment rounds per frame after the advection.",
                               [](auto& o) -> auto& { return o.iterations; }, between(0, 100)));
    t.push_back(choice_row<O>(
        "sequencing",
        "frame (each frame advected from the last, temporal-causal neighbourhoods) or all (spatio-temporal "
        "patches copied into every frame, then optimised together with temporal-non-causal neighbourhoods).",
        [](auto& o) -> auto& { return o.sequencing; },
        std::vector<std::pair<std::string, Sequencing>>{{"frame", Sequencing::frame}, {"all", Sequencing::all}}));
    t.push_back(choice_row<O>("search",
                              "Candidate search: kcoherence (matches' continuations, shifted neighbour matches, "
                              "similarity sets) or exhaustive (every exemplar sample-frame).",
                              [](auto& o) -> auto& { return o.search; },
                              std::vector<std::pair<std::string, SearchMode>>{{"kcoherence", SearchMode::kcoherence},
                                                                              {"exhaustive", SearchMode::exhaustive}}));
    t.push_back(integer_row<O>("random_candidates", "Random exemplar samples tried per output sample and search.",
                               [](auto& o) -> auto& { return o.random_candidates; }, between(0, 1000)));
    t.push_back(text_row<O>(
        "flow", "Global flow X,Y[,Z] in units per unit of time, added to every element's motion; unset = none.",
        [](const O& o) { return vector_text(o.flow); },
        [](O& o, const std::string& text, const OptionContext& c) {
            o.flow = text.empty() ? Vec3{} : parse_flow(text, c.as_written);
        }));
    t.push_back(number_row<O>("flow_turn",
                              "Degrees per unit of time the flow turns about the z axis (a school wheeling); "
                              "0 = a steady flow.",
                              [](auto& o) -> auto& { return o.flow_turn; }, any_finite()));
    t.push_back(flag_row<O>("wrap",
                            "An element carried out of the domain re-enters on the opposite side of its bounding "
                            "box (periodic); off = it is put back at the nearest point inside.",
                            [](auto& o) -> auto& { return o.wrap; }));
    t.push_back(flag_row<O>("physics",
                            "A physics sub-step (Bullet, no gravity) pushes apart particles closer than the "
                            "exemplar's closest pair: frame by frame after each advection and each frame's "
                            "assignment; all frames after each round's assignment, on every frame.",
                            [](auto& o) -> auto& { return o.physics; }));
    t.push_back(flag_row<O>("keep_voids",
                            "Frame by frame: leave the voids wider than any the exemplar holds (a flow opens them, "
                            "past an obstacle above all); off = they are closed by moving the samples round them "
                            "towards their centre, a tenth of a spacing at a time.",
                            [](auto& o) -> auto& { return o.keep_voids; }));
}

// All-frame synthesis on a coarse motion (synthesize_on_coarse).
void add_coarse_rows(OptionTable<O>& t) {
    t.push_back(integer_row<O>("topology_size",
                               "On a coarse motion: width in samples of the grid neighbourhood of threads and "
                               "sheets (its half-width is size / 2: 7 = the paper's 7 x 7).",
                               [](auto& o) -> auto& { return o.topology_size; }, between(3, 15)));
    t.push_back(integer_row<O>("split_samples",
                               "On a coarse motion: half-width in samples along the elements of the low-pass "
                               "filter that splits the exemplar into coarse and detail motion.",
                               [](auto& o) -> auto& { return o.split_samples; }, between(0, 64)));
    t.push_back(integer_row<O>("split_frames",
                               "On a coarse motion: half-width in frames of that filter.",
                               [](auto& o) -> auto& { return o.split_frames; }, between(0, 64)));
    t.push_back(number_row<O>("cross_weight",
                              "On a coarse motion: weight of each sample of another element in a thread's or "
                              "sheet's neighbourhood (its detail relative to the centre's, paired by place with the "
                              "Hungarian algorithm), against a grid entry's 1; 0 = the grid part alone.",
                              [](auto& o) -> auto& { return o.cross_weight; }, at_least(0)));
}

OptionTable<O> make_table() {
    OptionTable<O> t;
    t.push_back(seed_row<O>([](auto& o) -> auto& { return o.seed; }));
    t.push_back(threads_row<O>([](auto& o) -> auto& { return o.threads; }));
    add_solver_rows(t);
    add_neighbourhood_rows(t);
    add_coarse_rows(t);
    return t;
}

}  // namespace

const OptionTable<DynamicOptions>& dynamic_option_table() {
    static const OptionTable<DynamicOptions> table = make_table();
    return table;
}

}  // namespace tessera
