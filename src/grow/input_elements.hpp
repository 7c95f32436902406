// The exemplar as growth sees it: one entry per element (its centroid stands for it, its
// sample layout is copied whole), each element's neighbourhood sorted by distance (so the
// metric's neighbourhood within r and the larger patch copied by generation are prefixes
// of one list), per-type pools of elements far enough from the exemplar's border to have
// whole neighbourhoods, and k-coherence similarity sets over them.
#pragma once

#include <vector>

#include "core/spatial_grid.hpp"
#include "det/matching.hpp"
#include "det/model.hpp"
#include "tessera/exemplar.hpp"

namespace tessera::grow {

// The metric's constants (Eq. 3 with the attribute term of DET's Eq. 1).
struct Metric {
    det::Params params;         // radius, spacing, cap2, alpha (det/model.hpp)
    double patch_radius = 0.0;  // extent of the patch generation copies
    double threshold2 = 0.0;    // c: squared distance under which a pair is an assignment
    int dimension = 2;
};

struct InputElements {
    std::vector<Vec3> centroid;
    std::vector<int> type;
    std::vector<det::NeighborEntry> nb;  // CSR: nb[nb_start[i] .. nb_start[i+1]), nearest first
    std::vector<int> nb_start;
    // The same neighbours as columns (index as in nb), for the pairing's inner loop
    // (grow/pairing.hpp): offset, type as a number, element radius.
    // When every input element has one type (one radius), an output entry of that type (that
    // radius) has no attribute term against any of them: the pairing skips it.
    struct Columns {
        std::vector<double> x, y, z, type, radius;
        bool one_type = false, one_radius = false;
        int the_type = 0;
        double the_radius = 0.0;
    } columns;
    std::vector<int> metric_count;  // entries within r + cap (what Eq. 3 pairs against)
    std::vector<int> patch_count;   // entries within the patch radius (what generation copies)
    std::vector<int> within_r;      // entries within r (the local histogram of section V.C)
    // Per type: the input elements a match may pick (those with whole patches when there
    // are enough of them), with a grid over their centroids.
    std::vector<std::vector<int>> pool;
    std::vector<std::vector<Vec3>> pool_position;
    std::vector<core::SpatialGrid> pool_grid;
    std::vector<int> sim_start, sim;  // k-coherence similarity sets (CSR), within the pools
    // Each element's samples relative to its centroid (CSR): its shape and heading.
    std::vector<Vec3> layout;
    std::vector<int> layout_start;

    int size() const { return static_cast<int>(centroid.size()); }
    const det::NeighborEntry* neighbors(int i) const { return nb.data() + nb_start[i]; }
    // The pool element of type t nearest to p within max_distance, or -1.
    int nearest_in_pool(int t, const Vec3& p, double max_distance) const;
    // Mean squared distance between the corresponding samples of two elements' layouts
    // (0 for single-sample elements, a < 0 or different sample counts): centroids alone
    // cannot tell a lipid of the upper leaflet from a flipped one of the lower, or two
    // headings of a stick, when their neighbourhoods within r look alike.
    double shape_distance(int a, int b) const;
};

// Builds the index; the similarity sets pair every two pool elements of one type on
// `threads` threads (a cost of the exemplar's size, paid once).
InputElements index_input_elements(const Exemplar& exemplar, const Metric& metric, int k, int threads);

// Centroid of an element's samples (2D: z = 0).
Vec3 element_centroid(const Exemplar& data, const Element& element);

}  // namespace tessera::grow
