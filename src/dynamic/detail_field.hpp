// All-frame synthesis of detail motion on a coarse motion (Dynamic Element Textures,
// section 4.1 with temporal-non-causal neighbourhoods, Figures 10 and 13): every sample of
// every frame holds a detail vector, the offset of the sample from its coarse position in
// the coarse motion's local frame (local_frames.hpp). The exemplar's details come from its
// decomposition (section 5, motion_analysis.hpp); the output's are synthesized by search
// and assignment over grid neighbourhoods (topology_grid.hpp) of the detail vectors.
#pragma once

#include <cstdint>
#include <vector>

#include "dynamic/topology_grid.hpp"

namespace tessera::dynamic {

// The detail vectors of one animation (the exemplar or the output), frame-major.
struct DetailField {
    DetailField(TopologyGrid grid_, int frames_, std::vector<int> type_)
        : grid(std::move(grid_)), frames(frames_), samples(grid.sample_count()), type(std::move(type_)),
          detail(static_cast<size_t>(frames) * samples) {}

    TopologyGrid grid;
    int frames = 0, samples = 0;
    std::vector<int> type;      // per sample: the exemplar's type index
    std::vector<Vec3> detail;   // detail[f * samples + s], local coordinates

    const Vec3& at(int f, int s) const { return detail[static_cast<size_t>(f) * samples + s]; }
    Vec3& at(int f, int s) { return detail[static_cast<size_t>(f) * samples + s]; }
    bool valid(int f, int s) const { return s >= 0 && f >= 0 && f < frames; }
};

// The N best input matches of every output sample-frame, as input ids g * samples + j, and
// for each match the input sample paired with each of the sample-frame's cross entries
// (cross_neighbours.hpp; -1 = unpaired; kept only when the cross term is on).
struct DetailMatches {
    static constexpr int kCross = 6;  // CrossNeighbours::kMax
    DetailMatches(int count, int n_) : n(n_), id(static_cast<size_t>(count) * n_, -1), cost(id.size(), 0.0) {}
    int n;
    std::vector<int> id;
    std::vector<double> cost;
    std::vector<int> partner;
    int* partners(int k, int q) { return partner.data() + (static_cast<size_t>(k) * n + q) * kCross; }
    const int* partners(int k, int q) const { return partner.data() + (static_cast<size_t>(k) * n + q) * kCross; }
    int* of(int k) { return id.data() + static_cast<size_t>(k) * n; }
    const int* of(int k) const { return id.data() + static_cast<size_t>(k) * n; }
    double* cost_of(int k) { return cost.data() + static_cast<size_t>(k) * n; }
    const double* cost_of(int k) const { return cost.data() + static_cast<size_t>(k) * n; }
};

struct CrossTerm;

struct DetailSearch {
    const std::vector<std::vector<GridOffset>>* offsets = nullptr;  // by exemplar type
    const CrossTerm* cross = nullptr;  // the neighbours of other elements, when on
    double cap2 = 1.0;          // cost of an entry present on one side only (a thread's end)
    bool exhaustive = false;
    int random_candidates = 2;
    std::uint64_t seed = 1;
    int round = 0;
};

// Eq. 4 and Eq. 9 on grid neighbourhoods: the Gaussian-weighted squared differences of
// relative detail vectors, the centre's absolute detail first; stops early past `cutoff`.
double detail_distance(const DetailField& out, int f, int s, const DetailField& in, int g, int j,
                       const std::vector<GridOffset>& offsets, double cap2, double cutoff);

// The search step: each output sample-frame's N best input sample-frames (k-coherence:
// its matches, its neighbours' matches shifted back by their grid and frame offsets, and
// keyed random draws; or every input sample-frame of its type). Reads `previous`, writes
// `next`; returns the mean best distance.
double search_details(const DetailField& in, const DetailField& out, const DetailSearch& settings,
                      const DetailMatches& previous, DetailMatches& next, int threads);

// The assignment step (Eq. 6-7 with Eq. 11-12): each detail becomes the weighted mean of
// the predictions of every matched neighbourhood that covers it, the neighbourhood centres
// held fixed (Jacobi); reads `out`, returns the new details.
// With `cross`, each matched neighbourhood also predicts the details of its paired cross
// entries: the neighbour's detail is the centre's plus the input pair's relative detail.
std::vector<Vec3> assign_details(const DetailField& in, const DetailField& out, const DetailMatches& matches,
                                 const std::vector<std::vector<GridOffset>>& offsets, int threads,
                                 const CrossTerm* cross = nullptr);

}  // namespace tessera::dynamic
