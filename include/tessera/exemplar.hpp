// tessera/exemplar.hpp — the data model shared by every method (DESIGN.md, "Data model").
//
// A sample is a point p with attributes q (element, sample id within its element,
// and through its element: type, radius, orientation, free attributes).
// An element is an ordered run of samples of one type; an element type names a
// kind of element and fixes its sample layout. An Exemplar is element types +
// elements + samples + the domain they were observed in. An Arrangement (the
// output of a method) is the same plus run statistics.
//
// Storage is flat (all samples in one vector, elements refer to a contiguous
// run) so that neighbour queries and solvers work on plain arrays.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tessera/domain.hpp"
#include "tessera/vec.hpp"

namespace tessera {

struct Sample {
    Vec3 p;               // position (z = 0 in 2D)
    int element = -1;     // index of the owning element in Exemplar::elements
    int sample_id = 0;    // position of this sample within its element (0-based)
    double time = 0.0;    // time stamp; 0 for static data (space-time synthesis later)
};

// How a single-sample element is drawn in 2D pictures (render.hpp): a disk, or a fish
// heading along the element's x axis (in an animation, along its motion).
enum class ElementGlyph { disk, fish };

// How the samples of an element hang together in space-time synthesis (animation.hpp):
// automatic = none for single-sample elements and thread for multi-sample ones.
enum class ElementTopology { automatic, none, thread, sheet };

struct ElementType {
    std::string name;     // class name, e.g. "tree", "stick"; unique within an exemplar
    bool rigid = true;    // rigid elements keep the exact shape of an input element
    bool floor = false;   // floor elements (used by constrained selection, later)
    std::string mesh;     // optional mesh file (OBJ / ASCII PLY) for rebuilding geometry (geometry.hpp)
    // Optional reference sample layout in the mesh's local frame (geometry.hpp); empty =
    // derived from the first element of the type. Required for deformable types with a mesh.
    std::vector<Vec3> reference;
    // Classes this one depends on in the PCF method's dependency graph (pcf_synthesis.hpp),
    // by name; unset = every earlier type; an empty list = none (an independent class).
    std::optional<std::vector<std::string>> depends_on;
    // Optional colour of the type in pictures: "#rrggbb", "#rgb" or a colour name
    // (render.hpp, parse_color); empty = its name when that is a colour, else the palette.
    // Last and with an initializer, so that brace initialisations of the fields above stay
    // valid and warning-free.
    std::string color = {};
    // Brushing (brush.hpp): the weight of each sample (a bounding radius, by sample id) and
    // the element graph (edges between sample ids); empty = the defaults of
    // brush_sample_weights() and brush_element_graph().
    std::vector<double> weights = {};
    std::vector<std::array<int, 2>> graph = {};
    // Space-time synthesis (animation.hpp): the type's topology, and for a sheet the number
    // of columns of its sample grid (sample id = row x columns + column).
    ElementTopology topology = ElementTopology::automatic;
    int sheet_columns = 0;
    // 2D pictures of single-sample elements: disk (the default) or fish.
    ElementGlyph glyph = ElementGlyph::disk;
};

struct Element {
    int type = 0;             // index into Exemplar::types
    int first_sample = 0;     // samples [first_sample, first_sample + sample_count)
    int sample_count = 1;
    double radius = 0.0;      // 0 = no radius
    Vec3 position;            // pose: centroid of the samples
    Quat orientation;         // pose: rotation from the element's reference frame
    double scale = 1.0;       // pose: uniform scale
    std::vector<double> attributes;  // values of Exemplar::attribute_names, in order
    std::uint64_t id = 0;     // stable element id (kept through synthesis)
    bool locked = false;      // locked elements are never moved by a method
};

struct Exemplar {
    int dimension = 2;                       // 2 or 3
    std::vector<ElementType> types;
    std::vector<Element> elements;
    std::vector<Sample> samples;
    std::vector<std::string> attribute_names;  // names of the free numeric attributes
    Domain domain = Domain::box({0, 0, 0}, {1, 1, 0}, 2);

    // Index of the type with this name, or -1.
    int find_type(const std::string& name) const;
    // Index of the type with this name, appended if missing.
    int type_index(const std::string& name);
    // Appends an element made of `positions` (sample ids 0..n-1) and returns its index.
    int add_element(int type, const std::vector<Vec3>& positions, double radius = 0.0);
    // Recomputes each unlocked element's position (centroid) from its samples.
    void update_positions();
    // True when some element has more than one sample.
    bool has_multi_sample_elements() const;
    // Throws Error(input) naming `source` if the data break the model's invariants:
    // no elements, non-finite coordinates, bad indices, radius < 0, unknown types,
    // elements of one type with different sample counts, a type's reference layout
    // that is not finite or whose size differs from its elements' sample count.
    void validate(const std::string& source) const;
};

// Statistics a method reports about its run.
struct RunStats {
    std::string method;                  // "det", "pcf"
    std::vector<double> energy;          // energy found by each iteration's search (Eq. 2)
    double final_energy = 0.0;           // energy of the returned arrangement
    double radius = 0.0;                 // neighbourhood radius used
    int solver_bound_hits = 0;           // iterations whose linear solve hit its iteration bound
                                         // (pcf: refinements that stopped at max_iterations)
    int fallbacks = 0;                   // work done by a slower fallback path (pcf: elements
                                         // placed by grid search instead of dart throwing)
    std::vector<std::string> notes;      // one line per remark worth telling a user (fallbacks, ...)
    // Interleaved physics (when used): interpenetrating element pairs, deepest overlap
    // and floating elements before the first physics step and in the result.
    bool physics = false;
    int penetrations_before = 0, penetrations_after = 0;
    double max_depth_before = 0.0, max_depth_after = 0.0;
    int floating_before = 0, floating_after = 0;
    std::vector<double> iteration_seconds;
    double init_seconds = 0.0;
    double total_seconds = 0.0;
    int threads = 1;
    std::uint64_t seed = 0;
};

struct Arrangement : Exemplar {
    RunStats stats;
};

}  // namespace tessera
