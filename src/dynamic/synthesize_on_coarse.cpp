// dynamic/synthesize_on_coarse.cpp — all-frame synthesis of detail motion on a coarse
// motion given for whole elements (section 4.1, all-frame sequencing; Figures 10 and 13):
// every noodle follows its coarse path, every paper scrap its coarse tumble, and the
// exemplar's fine motion is laid on top, all frames together.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>

#include "core/parallel.hpp"
#include "dynamic/cross_neighbours.hpp"
#include "dynamic/detail_field.hpp"
#include "dynamic/detail_patches.hpp"
#include "dynamic/element_contacts.hpp"
#include "dynamic/sheet_sides.hpp"
#include "dynamic/thread_sides.hpp"
#include "dynamic/element_lengths.hpp"
#include "dynamic/graph_exemplar.hpp"
#include "dynamic/local_frames.hpp"
#include "tessera/dynamic.hpp"
#include "tessera/error.hpp"
#include "tessera/motion_analysis.hpp"
#include "tessera/option_table.hpp"

namespace tessera {

namespace {

using namespace dynamic;

constexpr double length_tolerance = 0.005;  // edges within 0.5 % of their rest length
constexpr int length_sweeps = 200;          // bound on the projection's sweeps
constexpr double contact_quantile = 0.02;   // the exemplar's closest approach between elements
constexpr double contact_tolerance = 0.02;  // pairs within 2 % of their contact distance
constexpr int contact_sweeps = 50;          // bound on the contact sweeps per frame
constexpr int constraint_passes = 8;        // bound on the alternations of lengths and contacts

std::string topology_text(ElementTopology t) {
    return t == ElementTopology::thread ? "thread" : t == ElementTopology::sheet ? "sheet" : "none";
}

// Every coarse type must be an exemplar type of the same topology.
std::vector<int> coarse_types_in_exemplar(const Animation& exemplar, const Animation& coarse) {
    std::vector<int> map;
    for (size_t t = 0; t < coarse.structure.types.size(); ++t) {
        const std::string& name = coarse.structure.types[t].name;
        const int in = exemplar.structure.find_type(name);
        if (in < 0) throw Error(ErrorKind::input, "coarse: type '" + name + "' is not in the exemplar");
        const ElementTopology a = effective_topology(exemplar.structure, in);
        const ElementTopology b = effective_topology(coarse.structure, static_cast<int>(t));
        if (a != b)
            throw Error(ErrorKind::input, "coarse: type '" + name + "' is a " + topology_text(b) +
                                              " but the exemplar's is a " + topology_text(a));
        const auto has_type = [in](const Element& e) { return e.type == in; };
        if (std::none_of(exemplar.structure.elements.begin(), exemplar.structure.elements.end(), has_type))
            throw Error(ErrorKind::input, "coarse: type '" + name + "' has no element in the exemplar to copy");
        map.push_back(in);
    }
    return map;
}

void check_inputs(const Animation& exemplar, const Animation& coarse, const DynamicOptions& options) {
    check_options(dynamic_option_table(), options);
    exemplar.validate("exemplar");
    coarse.validate("coarse");
    if (coarse.structure.dimension != exemplar.structure.dimension)
        throw Error(ErrorKind::input, "coarse: it is " + std::to_string(coarse.structure.dimension) +
                                          "D but the exemplar is " + std::to_string(exemplar.structure.dimension) + "D");
    if (exemplar.frame_count() < options.temporal_size)
        throw Error(ErrorKind::option, "temporal_size must be at most the exemplar's frame count (" +
                                           std::to_string(exemplar.frame_count()) + "), got " +
                                           std::to_string(options.temporal_size));
    if (coarse.frame_count() < 2) throw Error(ErrorKind::input, "coarse: it has one frame; a motion needs two or more");
}

// Per sample: its element's type, through `map` (coarse type -> exemplar type).
std::vector<int> sample_types(const Exemplar& data, const std::vector<int>& map) {
    std::vector<int> types(data.samples.size());
    for (size_t s = 0; s < types.size(); ++s) types[s] = map[data.elements[data.samples[s].element].type];
    return types;
}

std::vector<int> identity_map(size_t n) {
    std::vector<int> map(n);
    for (size_t i = 0; i < n; ++i) map[i] = static_cast<int>(i);
    return map;
}

// The exemplar's details in its own coarse motion's local frames (`frames`).
DetailField exemplar_details(const MotionSplit& split, const TopologyGrid& grid, const std::vector<LocalFrame>& frames) {
    const Animation& c = split.coarse;
    DetailField in(grid, c.frame_count(), sample_types(c.structure, identity_map(c.structure.types.size())));
    for (size_t k = 0; k < in.detail.size(); ++k) in.detail[k] = frames[k].to_local(split.detail.positions[k]);
    return in;
}

std::vector<int> element_types(const Exemplar& data, const std::vector<int>& map) {
    std::vector<int> types;
    for (const Element& e : data.elements) types.push_back(map[e.type]);
    return types;
}

// How much longer the exemplar's elements are than their coarse paths (detail makes a
// noodle wiggle, so it is longer than its smoothed path), per type: the output's rest
// lengths are its coarse lengths times this.
std::vector<double> stretch_by_type(const Animation& exemplar, const MotionSplit& split, const TopologyGrid& grid) {
    const size_t types = exemplar.structure.types.size();
    const std::vector<int> of_element = element_types(exemplar.structure, identity_map(types));
    std::vector<double> actual(types, 0.0), smooth(types, 0.0), stretch(types, 1.0);
    for (int f = 0; f < exemplar.frame_count(); ++f) {
        const size_t first = static_cast<size_t>(f) * exemplar.sample_count();
        const auto edges = element_edges(grid, of_element, &split.coarse.positions[first], stretch);
        for (size_t e = 0; e < edges.size(); ++e)
            for (const Edge& edge : edges[e]) {
                smooth[of_element[e]] += edge.rest;
                actual[of_element[e]] += norm(exemplar.positions[first + edge.b] - exemplar.positions[first + edge.a]);
            }
    }
    for (size_t t = 0; t < types; ++t)
        if (smooth[t] > 0.0) stretch[t] = actual[t] / smooth[t];
    return stretch;
}

// Output positions: coarse plus detail turned into world coordinates.
std::vector<Vec3> compose(const Animation& coarse, const std::vector<LocalFrame>& frames, const DetailField& out) {
    std::vector<Vec3> p(coarse.positions.size());
    for (size_t k = 0; k < p.size(); ++k) p[k] = coarse.positions[k] + frames[k].to_world(out.detail[k]);
    return p;
}

void decompose_into(const Animation& coarse, const std::vector<LocalFrame>& frames, const std::vector<Vec3>& p,
                    DetailField& out) {
    for (size_t k = 0; k < p.size(); ++k) out.detail[k] = frames[k].to_local(p[k] - coarse.positions[k]);
}

// Rest lengths, contacts between elements (element_contacts.hpp) and the sides of sheets and
// threads (sheet_sides.hpp, thread_sides.hpp), alternated so that all hold together (each pass of one disturbs the
// others a little): lengths last, so that threads and sheets end at their rest lengths.
struct Constraints {
    const std::vector<std::vector<Edge>>& edges;
    const std::vector<Vec3>& coarse;
    std::vector<int> element_of;
    std::vector<std::array<int, 3>> sheet_triangles;  // 3D sheets only
    std::vector<std::array<int, 2>> thread_segments;  // 3D threads only
    int frames = 0, samples = 0, dimension = 2, threads = 0;
    double contact = 0.0;

    void apply(std::vector<Vec3>& p, LengthReport& lengths, ContactReport& contacts, ContactReport& sides) const {
        for (int pass = 0; pass < constraint_passes; ++pass) {
            lengths = keep_lengths(p, frames, samples, edges, length_tolerance, length_sweeps, threads);
            contacts = keep_apart(p, coarse, element_of, frames, samples, dimension, contact, contact_tolerance,
                                  contact_sweeps, threads);
            sides = keep_sides(p, coarse, sheet_triangles, element_of, frames, samples, contact, contact_tolerance,
                               contact_sweeps, threads);
            sides += keep_thread_sides(p, coarse, thread_segments, element_of, frames, samples, contact,
                                       contact_tolerance, contact_sweeps, threads);
            // The last lengths pass left the contacts and sides within tolerance: nothing more to alternate.
            const double tolerance = contact_tolerance * contact;
            if (contacts.first_gap <= tolerance && sides.first_gap <= tolerance) break;
        }
        lengths = keep_lengths(p, frames, samples, edges, length_tolerance, length_sweeps, threads);
    }
};

std::vector<int> element_of_samples(const Exemplar& data) {
    std::vector<int> of(data.samples.size());
    for (size_t s = 0; s < of.size(); ++s) of[s] = data.samples[s].element;
    return of;
}

// The exemplar's typical detail size, the unit of the cost of an unpaired entry.
double unpaired_cost(const DetailField& in) {
    double sum = 0.0;
    for (const Vec3& d : in.detail) sum += squared_norm(d);
    const double mean = in.detail.empty() ? 0.0 : sum / in.detail.size();
    return std::max(4.0 * mean, 1e-12);
}

std::vector<std::vector<GridOffset>> offsets_by_type(const Exemplar& data, const DynamicOptions& o) {
    std::vector<std::vector<GridOffset>> out;
    for (size_t t = 0; t < data.types.size(); ++t)
        out.push_back(grid_offsets(effective_topology(data, static_cast<int>(t)), o.topology_size / 2,
                                   (o.temporal_size - 1) / 2, o.shape, o.sigma_p, o.sigma_t));
    return out;
}

}  // namespace

AnimatedArrangement synthesize_on_coarse(const Animation& given, const Animation& coarse,
                                         const DynamicOptions& options, const Progress& progress) {
    // A still (one frame: a traced photo of branches, Figure 12) gets its detail motion by
    // graph synthesis first (graph_shapes.hpp), as frame-by-frame synthesis does for particles.
    std::optional<Animation> enriched;
    std::vector<std::string> graph_notes;
    const Animation& exemplar = exemplar_with_motion(given, options, enriched, graph_notes);
    check_inputs(exemplar, coarse, options);
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    const std::vector<int> type_map = coarse_types_in_exemplar(exemplar, coarse);
    LowPassOptions split_options;
    split_options.topology_radius = options.split_samples;
    split_options.temporal_radius = options.split_frames;
    split_options.threads = options.threads;
    const MotionSplit split = decompose_motion(exemplar, split_options);
    const TopologyGrid in_grid(exemplar.structure, "exemplar"), out_grid(coarse.structure, "coarse");
    const std::vector<LocalFrame> in_frames = local_frames(split.coarse, in_grid);
    const DetailField in = exemplar_details(split, in_grid, in_frames);
    DetailField out(out_grid, coarse.frame_count(), sample_types(coarse.structure, type_map));
    const std::vector<LocalFrame> frames = local_frames(coarse, out_grid);
    // The neighbours of other elements (the Hungarian part), within the exemplar's reach.
    const int dimension = coarse.structure.dimension;
    const std::vector<int> in_elements = element_of_samples(exemplar.structure);
    const double reach = options.cross_weight > 0.0
                             ? cross_radius(split.coarse.positions, in_elements, exemplar.frame_count(), dimension)
                             : 0.0;
    const CrossNeighbours in_cross(split.coarse.positions, in_frames, in_elements, exemplar.frame_count(), reach,
                                   dimension, options.threads);
    const CrossNeighbours out_cross(coarse.positions, frames, element_of_samples(coarse.structure),
                                    coarse.frame_count(), reach, dimension, options.threads);
    const CrossTerm cross{&out_cross, &in_cross, &frames, &in_frames, reach > 0.0 ? options.cross_weight : 0.0};
    const std::vector<std::vector<GridOffset>> offsets = offsets_by_type(exemplar.structure, options);
    const auto edges = element_edges(out_grid, element_types(coarse.structure, type_map), coarse.positions.data(),
                                     stretch_by_type(exemplar, split, in_grid));

    DetailMatches matches(out.frames * out.samples, options.matches), next = matches;
    copy_patches(in, out, matches, options.temporal_size, options.seed, options.threads);
    DetailSearch search{&offsets, &cross, unpaired_cost(in), options.search == SearchMode::exhaustive,
                        options.random_candidates, options.seed, 0};
    AnimatedArrangement result;
    result.stats.method = "dynamic";
    result.stats.seed = options.seed;
    result.stats.threads = core::resolve_threads(options.threads);
    result.stats.init_seconds = elapsed();
    const Constraints constraints{edges,
                                  coarse.positions,
                                  element_of_samples(coarse.structure),
                                  dimension == 3 ? sheet_triangles(out_grid) : std::vector<std::array<int, 3>>{},
                                  dimension == 3 ? thread_segments(out_grid) : std::vector<std::array<int, 2>>{},
                                  out.frames,
                                  out.samples,
                                  coarse.structure.dimension,
                                  options.threads,
                                  exemplar_contact_distance(exemplar, contact_quantile)};
    LengthReport lengths;
    ContactReport contacts, sides;
    std::vector<Vec3> positions = compose(coarse, frames, out);
    for (int round = 0; round < options.iterations; ++round) {
        const double round_start = elapsed();
        search.round = round;
        const double energy = search_details(in, out, search, matches, next, options.threads);
        std::swap(matches, next);
        out.detail = assign_details(in, out, matches, offsets, options.threads, &cross);
        positions = compose(coarse, frames, out);
        constraints.apply(positions, lengths, contacts, sides);
        decompose_into(coarse, frames, positions, out);
        result.stats.energy.push_back(energy);
        result.stats.iteration_seconds.push_back(elapsed() - round_start);
        if (progress && !progress(ProgressEvent{"iteration", round, options.iterations, energy, elapsed(),
                                                double(round + 1) / options.iterations}))
            throw Cancelled();
    }
    if (options.iterations == 0) constraints.apply(positions, lengths, contacts, sides);
    result.structure = coarse.structure;
    result.times = coarse.times;
    result.positions = std::move(positions);
    result.stats.solver_bound_hits = lengths.bound_hits + contacts.bound_hits + sides.bound_hits;
    if (lengths.bound_hits > 0)
        result.stats.notes.push_back(std::to_string(lengths.bound_hits) + " element-frames stopped at the bound of " +
                                     std::to_string(length_sweeps) + " length sweeps (worst strain " +
                                     std::to_string(lengths.worst_strain) + ")");
    if (contacts.bound_hits > 0)
        result.stats.notes.push_back(std::to_string(contacts.bound_hits) + " frames stopped at the bound of " +
                                     std::to_string(contact_sweeps) + " contact sweeps (largest gap left " +
                                     std::to_string(contacts.worst_gap) + ")");
    if (sides.bound_hits > 0)
        result.stats.notes.push_back(std::to_string(sides.bound_hits) + " frames stopped at the bound of " +
                                     std::to_string(contact_sweeps) + " sweeps keeping sheets and threads off each other (largest " +
                                     "shortfall left " + std::to_string(sides.worst_gap) + ")");
    result.stats.notes.insert(result.stats.notes.begin(), graph_notes.begin(), graph_notes.end());
    result.stats.final_energy = result.stats.energy.empty() ? 0.0 : result.stats.energy.back();
    result.stats.total_seconds = elapsed();
    if (progress) progress(ProgressEvent{"done", options.iterations - 1, options.iterations, result.stats.final_energy,
                                         elapsed(), 1.0});
    return result;
}

}  // namespace tessera
