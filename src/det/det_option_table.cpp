// The options of neighbourhood-matching synthesis (DetOptions, tessera/det.hpp), one row
// each: `tessera synth --method det` makes its flags from this table and
// tessera.synthesize(method="det") its keywords (tessera/option_table.hpp).
#include <cstdio>
#include <cstdlib>

#include "core/option_rows.hpp"
#include "tessera/det.hpp"
#include "tessera/error.hpp"
#include "tessera/option_table.hpp"
#include "tessera/option_text.hpp"

namespace tessera {

namespace {

using namespace options;
using O = DetOptions;

// Gravity as an axis with its sign ("-z") or as its components ("0,0,-1").
Vec3 parse_gravity(const std::string& text, const std::string& as_written) {
    if (text.find(',') == std::string::npos) return parse_axis_direction(text, as_written);
    if (const std::optional<Vec3> v = parse_vector_components(text)) return *v;
    throw Error(ErrorKind::option, as_written + " must be an axis with its sign (-x, +x, -y, +y, -z, +z) or "
                                                "a vector X,Y[,Z], got '" + text + "'");
}

std::string gravity_text(const O& o) { return vector_text(o.gravity); }

std::string boundary_text(const O& o) {
    std::string text;
    for (const auto& side : o.boundary_sides)
        text += std::string(text.empty() ? "" : ",") + (side.sign < 0 ? "-" : "+") + static_cast<char>('x' + side.axis);
    return text;
}

OptionTable<O> make_table() {
    OptionTable<O> t;
    t.push_back(seed_row<O>([](auto& o) -> auto& { return o.seed; }));
    t.push_back(integer_row<O>("iterations",
                               "Iterations of search + assignment (0 = the patch-copy initialization only).",
                               [](auto& o) -> auto& { return o.iterations; }, at_least(0)));
    t.push_back(threads_row<O>([](auto& o) -> auto& { return o.threads; }));
    t.push_back(number_row<O>("radius",
                              "Neighbourhood radius in the exemplar's units; 0 = automatic (mean nearest-neighbour "
                              "distance x 2 in 2D, x 1.5 in 3D).",
                              [](auto& o) -> auto& { return o.radius; }, at_least(0)));
    t.push_back(integer_row<O>("k", "Size of each exemplar sample's similarity set for k-coherence search.",
                               [](auto& o) -> auto& { return o.k; }, at_least(1)));
    t.push_back(choice_row<O>("search",
                              "Candidate search: kcoherence (fast, the paper's) or exhaustive (every exemplar sample).",
                              [](auto& o) -> auto& { return o.search; },
                              std::vector<std::pair<std::string, SearchMode>>{{"kcoherence", SearchMode::kcoherence},
                                                                              {"exhaustive", SearchMode::exhaustive}}));
    t.push_back(choice_row<O>("matching",
                              "Pairing of neighbourhood samples: greedy (the paper's) or hungarian (exact, slower).",
                              [](auto& o) -> auto& { return o.matching; },
                              std::vector<std::pair<std::string, Matching>>{{"greedy", Matching::greedy},
                                                                            {"hungarian", Matching::hungarian}}));
    t.push_back(number_row<O>("alpha",
                              "Weight of the attribute (type) term, in squared length units; negative = automatic "
                              "(mean nearest-neighbour distance squared).",
                              [](auto& o) -> auto& { return o.alpha; }, any_finite()));
    t.push_back(number_row<O>("lambda",
                              "Weight of the domain boundary term, in squared length units; negative = automatic "
                              "(mean nearest-neighbour distance squared).",
                              [](auto& o) -> auto& { return o.lambda; }, any_finite()));
    t.push_back(number_row<O>("patch_size",
                              "Side of the patches copied at initialization; 0 = automatic: 2 x radius, or twice the "
                              "distance over which the exemplar's pair correlation shows structure when that is "
                              "larger (clusters, lattices; not with --field), at most half the exemplar's smallest "
                              "extent (docs/det.md).",
                              [](auto& o) -> auto& { return o.patch_size; }, at_least(0)));
    t.push_back(integer_row<O>("patch_candidates", "Random candidate patches tried per cell at initialization.",
                               [](auto& o) -> auto& { return o.patch_candidates; }, at_least(1)));
    t.push_back(integer_row<O>("relax_sweeps",
                               "Sweeps of the pair-correlation relaxation at the end (exemplars of single-sample "
                               "elements): small moves towards the exemplar's pair correlation of every class "
                               "pair; 0 = off.",
                               [](auto& o) -> auto& { return o.relax_sweeps; }, between(0, 1000)));
    t.push_back(flag_row<O>("physics",
                            "Interleaved physics: after every iteration, rigid-body steps (Bullet) resolve "
                            "interpenetration and let elements settle under gravity; reports interpenetration and "
                            "floating elements before and after.",
                            [](auto& o) -> auto& { return o.physics; }));
    t.push_back(integer_row<O>("physics_substeps", "Rigid-body steps per iteration with --physics.",
                               [](auto& o) -> auto& { return o.physics_options.substeps; }, between(0, 10000)));
    t.push_back(text_row<O>(
        "gravity",
        "Direction of gravity, an axis with its sign (-x, +x, -y, +y, -z, +z) or a vector X,Y[,Z] along one "
        "axis. Default: -y in 2D, -z in 3D.",
        gravity_text, [](O& o, const std::string& text, const OptionContext& c) {
            o.gravity = text.empty() ? Vec3{} : parse_gravity(text, c.as_written);
        }));
    t.push_back(number_row<O>("floor_distance",
                              "Constrained selection at the floor: elements whose lowest sample is within this "
                              "distance of the domain boundary below them (and elements of types marked floor) "
                              "are floor elements; output floor elements copy only input floor elements and keep "
                              "their elevation. 0 = only types marked floor.",
                              [](auto& o) -> auto& { return o.floor_distance; }, at_least(0)));
    t.push_back(text_row<O>(
        "boundary",
        "Constrained selection at other boundaries than the floor: sides such as -x,+x (walls) or +y (a "
        "ceiling). Elements within --boundary-distance of the domain's boundary on a listed side copy only "
        "input elements touching the same sides; interior elements only interior ones.",
        boundary_text, [](O& o, const std::string& text, const OptionContext& c) {
            o.boundary_sides = text.empty() ? std::vector<O::BoundarySide>{} : parse_boundary_sides(text, c.as_written);
        }));
    t.push_back(number_row<O>("boundary_distance",
                              "Distance from a --boundary side within which an element touches it (data units, "
                              "> 0 with --boundary).",
                              [](auto& o) -> auto& { return o.boundary_distance; }, at_least(0)));
    t.push_back(text_row<O>(
        "field", field_doc, [](const O& o) { return o.field.active() ? o.field.describe() : std::string(); },
        [](O& o, const std::string& text, const OptionContext& c) {
            o.field = text.empty() ? OrientationField{} : OrientationField::parse(text, c.dimension, c.as_written);
        },
        true));
    return t;
}

}  // namespace

const OptionTable<DetOptions>& det_option_table() {
    static const OptionTable<DetOptions> table = make_table();
    return table;
}

}  // namespace tessera
