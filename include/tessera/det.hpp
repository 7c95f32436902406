// tessera/det.hpp — discrete element textures: neighbourhood-matching synthesis.
//
// Implements Ma, Wei and Tong, "Discrete Element Textures" (SIGGRAPH 2011),
// sections 3 and 4: the sample neighbourhood metric (Eq. 1), patch-copy
// initialization (4.1), search by exhaustive scan or k-coherence (4.2),
// least-squares position assignment (Eq. 3, 4) and attribute voting (Eq. 5),
// with the domain occupancy term of Eq. 6 for the output boundary.
#pragma once

#include <cstdint>
#include <vector>

#include "tessera/domain.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/field.hpp"
#include "tessera/physics.hpp"
#include "tessera/progress.hpp"

namespace tessera {

enum class Matching { greedy, hungarian };
enum class SearchMode { kcoherence, exhaustive };

struct DetOptions {
    // Neighbourhood radius in the exemplar's units; 0 = automatic: the exemplar's
    // mean nearest-neighbour distance between elements times 2 in 2D (about two
    // rings) or 1.5 in 3D (the first shell).
    double radius = 0.0;
    // Iterations of search + assign (the paper uses 10).
    int iterations = 10;
    // Weight of the attribute term alpha|q_o - q_i|^2 of Eq. 1, in squared length
    // units; negative = automatic: (mean nearest-neighbour distance)^2, so that a
    // type mismatch costs as much as a neighbour displaced by one spacing.
    double alpha = -1.0;
    // Weight lambda of the domain occupancy term of Eq. 6, squared length units;
    // negative = automatic: (mean nearest-neighbour distance)^2.
    double lambda = -1.0;
    // Pairing of neighbourhood samples in Eq. 1: the paper's greedy heuristic or
    // the exact minimum-cost (Hungarian) assignment.
    Matching matching = Matching::greedy;
    // Search: k-coherence (paper, 4.2) or exhaustive scan over every input sample.
    SearchMode search = SearchMode::kcoherence;
    // Size k of each input sample's similarity set for k-coherence search.
    int k = 4;
    // Side of the square/cubic patches copied at initialization; 0 = automatic:
    // min(2 x radius, half the exemplar's smallest extent).
    double patch_size = 0.0;
    // Random candidate patches tried per output cell at initialization; the one that
    // agrees best with the elements already placed is copied (quilting-style seams).
    int patch_candidates = 16;
    // Sweeps of the pair correlation relaxation after the iterations, for exemplars of
    // single-sample elements (det/pair_relaxation.hpp, docs/det.md): small moves that bring
    // the output's pair correlation closer to the exemplar's where seams and the averaging
    // of Eq. 4 left it. 0 = off.
    int relax_sweeps = 4;
    // Worker threads for search and assignment; 0 = all hardware threads.
    // Results are byte-identical for every value.
    int threads = 0;
    // Seed of every random draw (counter-based: results do not depend on threads).
    std::uint64_t seed = 1;
    // Local orientation field of the output (Eq. 7); none = the global frame.
    OrientationField field;
    // Gravity, along one axis; zero = automatic: -y in 2D, -z in 3D.
    Vec3 gravity;
    // Constrained selection at the floor: elements whose lowest sample lies within
    // this distance of the domain boundary below them (along gravity), and elements
    // of types marked floor, are floor elements; output floor elements copy only
    // input floor elements and keep their elevation. 0 = only types marked floor.
    double floor_distance = 0.0;
    // Constrained selection at other chosen boundaries (walls, a ceiling): elements whose
    // samples lie within boundary_distance of the domain's boundary on one of these sides
    // (each side an axis 0..2 and a direction -1 or +1: {0, -1} is the -x side) only copy
    // input elements touching the same sides, and the others only elements touching none.
    // Unlike floor elements their coordinates are not held. Empty or 0 = off.
    struct BoundarySide {
        int axis = 0;
        int sign = -1;
    };
    std::vector<BoundarySide> boundary_sides;
    double boundary_distance = 0.0;
    // Interleaved physics (section 5): after every search/assign iteration, a few
    // rigid-body steps (Bullet) resolve interpenetration and let elements settle.
    // physics_options.gravity zero = 9.81 m/s^2 along `gravity` (or its default).
    bool physics = false;
    PhysicsOptions physics_options;
};

// Synthesizes an arrangement of elements like `exemplar` filling `domain`.
// Preconditions: exemplar.validate() passes; domain.dimension() == exemplar.dimension.
// Throws Error(option) for invalid options, Error(domain) for a domain that cannot
// hold one element, Cancelled if `progress` returns false.
Arrangement synthesize_det(const Exemplar& exemplar, const Domain& domain,
                           const DetOptions& options = {}, const Progress& progress = {});

// The automatic neighbourhood radius used when DetOptions::radius == 0.
double default_radius(const Exemplar& exemplar);
// Its factor on the mean nearest-neighbour distance for a dimension (2 or 3).
double default_radius_factor(int dimension);

// Mean distance from each element (its centroid) to the nearest other element.
double mean_nearest_neighbor_distance(const Exemplar& exemplar);

}  // namespace tessera
