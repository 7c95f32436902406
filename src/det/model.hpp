// Internal model of the discrete element texture solver: the parameters derived
// from the exemplar and options, the precomputed input index, and the output
// state the search and assignment steps work on. Not part of the public API.
#pragma once

#include <cstdint>
#include <vector>

#include "core/spatial_grid.hpp"
#include "det/floor.hpp"
#include "tessera/det.hpp"
#include "tessera/exemplar.hpp"

namespace tessera::det {

// Parameters of the metric (Eq. 1, 6) in the exemplar's units, resolved from DetOptions.
struct Params {
    int dimension = 2;
    double radius = 0.0;       // neighbourhood radius r
    double input_radius = 0.0; // extent of input neighbourhoods: r + cap (the paper's "infinite" n(s_i))
    double spacing = 0.0;      // mean nearest-neighbour distance between exemplar elements
    std::vector<double> type_density;  // per type: the exemplar's density where its elements are (det/density.hpp)
    double cap2 = 0.0;         // cost of an unmatched output neighbour; pairs costlier than this are not made
    double alpha = 0.0;        // weight of the attribute term of Eq. 1
    double lambda = 0.0;       // weight of the occupancy term of Eq. 6
    double intra_weight = 4.0; // weight of predictions between samples of one element in Eq. 4
    // Damping of Eq. 4 toward the current positions. It makes the system positive
    // definite (Eq. 4 alone fixes positions only up to a translation per connected
    // component) and bounds the conditioning, so each solve takes a bounded number
    // of conjugate-gradient iterations whatever the output size; the next
    // iterations remove its small bias.
    double anchor_weight = 0.01;
    // Relative residual at which the conjugate-gradient solve of Eq. 4 stops. The
    // solve is repeated every iteration, so a loose tolerance loses nothing.
    double cg_tolerance = 1e-6;
    // Weight of the pull of samples outside the domain back to its boundary.
    double wall_weight = 8.0;
    Matching matching = Matching::greedy;
    OrientationField field;    // local frames of the output (Eq. 7)
    Gravity gravity;           // down
    double floor_distance = 0.0;
    BoundarySides boundary;          // chosen sides beyond the floor (DetOptions::boundary_sides)
    bool floor_constraints = false;  // some exemplar element is a floor or boundary element
    double floor_weight = 1e4;       // holds floor elevations in Eq. 4
};

// Matching key of a sample: samples pair only with samples of the same key.
// Single-sample elements share key 0 (their type enters through alpha); each
// (type, sample id) of a multi-sample type has its own key, so shapes keep their topology.
std::vector<int> sample_keys(const Exemplar& data, std::vector<int>* type_key_base = nullptr);

// One sample of a neighbourhood, relative to the centre sample.
struct NeighborEntry {
    Vec3 offset;         // p(s') - p(s), in the centre's frame (Eq. 7 when frames exist)
    int sample = -1;     // index of s' in its arrangement
    int key = 0;         // matching key of s'
    int match_key = 0;   // pairing class: key * 2 + (s' in the centre's element); pairs need equal match keys,
                         // so samples of the centre's own element pair only with the candidate's own element
    int type = 0;        // element type of s'
    int element = -1;    // element of s'
    double radius = 0.0; // element radius of s'
};

// The exemplar, prepared for search: per-sample attributes, neighbourhoods
// within Params::input_radius (sorted by match key, then distance, so that the
// pairing scans only entries an output sample may pair with), a grid for
// nearest-compatible lookups, and similarity sets.
struct InputIndex {
    const Exemplar* exemplar = nullptr;
    std::vector<Vec3> positions;
    std::vector<int> key, type, element;
    std::vector<double> radius;
    std::vector<int> nb_start;            // CSR offsets into nb, size samples + 1
    std::vector<NeighborEntry> nb;
    std::vector<std::vector<int>> by_key; // samples of each key, index order
    core::SpatialGrid grid;
    // Per key: positions of that key's samples and a grid over them, for the
    // nearest-compatible lookups of k-coherence (one per neighbour per sample).
    std::vector<std::vector<Vec3>> key_positions;
    std::vector<core::SpatialGrid> key_grid;
    std::vector<int> sim_start, sim;      // k-coherence similarity sets (CSR)
    std::vector<char> floor;              // per sample: of a floor element

    int size() const { return static_cast<int>(positions.size()); }
    const NeighborEntry* neighbors(int i) const { return nb.data() + nb_start[i]; }
    int neighbor_count(int i) const { return nb_start[i + 1] - nb_start[i]; }
    // Nearest input sample of key `k` to p within `max_distance`, or -1.
    int nearest_with_key(const Vec3& p, int k, double max_distance) const;
};

// A pairing of one output neighbour with an input sample, recorded by the search
// for the assignment step: the prediction p(s'_o) - p(s_o) = predicted (Eq. 3).
struct Pair {
    int output = -1;   // output sample s'_o
    int input = -1;    // input sample s'_i paired with it
    Vec3 predicted;    // p(s'_i) - p(s_i), rotated into the output frame
    double weight = 1.0; // 1 for pairs within the cap; cap2 / cost beyond it (a robust
                         // weight: far pairs still push an extra sample toward a free
                         // position, but cannot drag well-placed samples far away)
};

// The output being synthesized.
struct OutputState {
    Arrangement arrangement;            // elements and samples (positions updated in place)
    std::vector<int> key;               // per output sample
    std::vector<int> match;             // best input sample per output sample (search result)
    std::vector<double> cost;           // its cost (Eq. 1 + lambda Eq. 6)
    std::vector<std::vector<Pair>> pairs; // per output sample: its neighbourhood's pairings
    std::vector<int> source_element;    // input element each output element copies attributes from
    std::vector<Quat> frame;            // per output sample: local frame of the field at it (Eq. 7)
    std::vector<char> floor;            // per output sample: of a floor element (constrained selection)
    // Per type: the element count the attribute vote must keep (the initialization's, which
    // holds the exemplar's density); empty = unconstrained.
    std::vector<int> type_target;
};

}  // namespace tessera::det
