// The steps of PCF synthesis on the incremental state (synth_state.hpp): the error of
// a candidate (Eq. 11), initialisation (Algorithm 1), refinement (Eq. 4 to 6) and the
// validity check of section 6.4. Private to the library.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "pcf/synth_state.hpp"

namespace tessera::pcf {

// Per-thread buffers of candidate evaluations.
struct Scratch {
    std::vector<double> near_sum;  // R_k: the candidate's pairs, kernels weighted by its correction
    std::vector<double> near_ref;  // D_k: the same with the neighbours as references (within a class)
    CircleProfile profile;         // the candidate's boundary correction
    explicit Scratch(const State& s) : near_sum(s.bins), near_ref(s.bins) {}
};

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

// E of Eq. 11 for an element of class c with radius r at p against the placed elements:
// per active PCF (the class's own and its parent edges) the
// mean term plus the envelope term, the largest over the PCFs. `fill` is the share of
// the class placed so far: below 1 the lower envelope of the class's own PCF is left out
// (a partial class cannot reach it yet). Returns kInfinity as soon as E is known to
// exceed `limit`. scratch.profile is left holding the candidate's boundary correction.
double candidate_error(const State& s, int c, const Vec3& p, double r, double fill, double limit, Scratch& scratch);

// How far element i's individual PCFs leave the validity region: the envelope term of
// Eq. 11 over its class's PCFs, with every element placed.
double envelope_violation(const State& s, int i, Scratch& scratch);

struct InitSettings {
    std::uint64_t seed = 1;
    int threads = 1;
    double epsilon0 = 0.0, epsilon_step = 0.001;
    int max_fails = 1000;
    int grid_cells = 64;
    int round = 0;  // 0 = first placement, then the outlier round (keys the random numbers)
};

struct InitReport {
    int by_grid = 0;      // elements placed by grid search
    int by_fallback = 0;  // elements placed at a random point because no grid cell's point was inside
};

// Algorithm 1 for `elements` (unplaced, of class c, in placement order): dart throwing,
// then grid search once max_fails successive candidates were rejected. `tick` is called
// on the calling thread every few placements (it may throw Cancelled).
InitReport initialise(State& s, int c, const std::vector<int>& elements, const InitSettings& settings,
                      const std::function<void()>& tick);

struct SparseReport {
    int by_bound = 0;    // elements placed at the best of the bounded darts, breaking a rule
    double worst = 0.0;  // the largest violation (normalised axis) among them
};

// Places `elements` (unplaced, of the sparse class sc.cls) by the fallback of
// PcfSparseClass: keyed darts, the first that keeps every rule (a bounded number; then
// the one that broke them least). `tick` is called on the calling thread now and then.
SparseReport place_sparse(State& s, const PcfSparseClass& sc, const std::vector<int>& elements, std::uint64_t seed,
                          const std::function<void()>& tick);

struct RefineReport {
    int sweeps = 0;
    bool converged = false;
};

// The neighbourhood of a re-placed element of class c that a local refinement moves
// with it: two r_max beyond contact (the first rings of neighbours).
double local_reach(const State& s, int c);

// Refinement of `elements` (placed, of class c) by Eq. 4 to 6 against the class's PCFs,
// at most max_iterations sweeps; on_sweep(energy) after each one.
RefineReport refine(State& s, int c, const std::vector<int>& elements, int max_iterations, double convergence, double stall,
                    int threads, const std::function<void(double energy)>& on_sweep);

}  // namespace tessera::pcf
