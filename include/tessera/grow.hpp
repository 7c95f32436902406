// tessera/grow.hpp — on-demand growth (docs/grow.md): an arrangement grown outward along
// its horizon, next to elements that already exist and never move.
//
// A game, a world builder or a brush does not know the output domain in advance. A Grower
// holds an arrangement and adds elements just where they are needed. Each round:
//   1. generation: each horizon element h is matched to the input element e whose
//      neighbourhood fits best (Eq. 3, k-coherence candidates); the input neighbours e' of
//      e left without an output partner by the partial pair assignment (threshold c)
//      become candidates at p(h) + (p(e') - p(e)) with the attributes of e';
//   2. filters: candidates overlapping one another or an existing element are dropped
//      (the best-fitting proposer's candidate is kept), then candidates whose neighbourhood
//      energy exceeds t times the round's mean, and candidates outside the target region;
//      the chosen candidates are the new horizon (the patch choice, default), or a
//      single-player Monte-Carlo tree search chooses among them (Eq. 4-5, the paper's choice);
//   3. optimization: the weighted least-squares position solve of Eq. 6-7 over the horizon
//      and a band behind it (weights rising with the distance from the horizon, elements
//      beyond the lock distance fixed), then attributes reassigned by votes and
//      redistributed by local type histograms (section V).
// Elements copy the sample layout of their input element whole, so multi-sample shapes are
// kept exactly. Locked elements (Element::locked, and every element of an arrangement the
// grower starts from) are never moved, retyped or removed.
//
// Deterministic: the same exemplar, options and seed give the same arrangement whatever
// the thread count. Not thread-safe: one thread at a time per Grower.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tessera/domain.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/field.hpp"
#include "tessera/progress.hpp"

namespace tessera {

// What the edge of a grow(region) call's region means.
enum class RegionEdge {
    closed,  // a wall: every sample of every element lies inside; candidates just outside are
             // pulled onto the edge, so that it is not left with a gap (default)
    open,    // one cell of a partition (the tiles of a world, tessera/world.hpp): only element
             // centres lie inside, samples may reach beyond, and candidates outside are left
             // to the neighbouring cell
};

// How a round chooses among its candidates.
enum class GrowChoice {
    patch,  // every filtered candidate: the input patch that fits best is copied (default)
    mcts,   // single-player Monte-Carlo tree search over the candidates (the paper, section IV)
};

struct GrowOptions {
    // Neighbourhood radius r of the metric (Eq. 3); 0 = automatic, as DetOptions::radius.
    double radius = 0.0;
    GrowChoice choice = GrowChoice::patch;
    // Extent of the input patch copied at each horizon element, in units of r (patch
    // choice); the tree search proposes from the neighbourhood itself (1).
    double patch_extent = 1.5;
    // Threshold c of the partial pair assignment, as a fraction of the exemplar's mean
    // nearest-neighbour distance: a pair further apart than this is not an assignment.
    double threshold = 0.4;
    // t: candidates whose best neighbourhood energy exceeds t times the round's mean are dropped.
    double energy_factor = 1.5;
    // Elements further than this from the horizon (in units of r) are fixed in the solve.
    double lock_distance = 1.0;
    // Weight of the pull toward the current position at the lock distance (Eq. 7's w);
    // it rises linearly from 0 at the horizon.
    double band_weight = 4.0;
    // Least-squares solves per round: one search, then a pairing with its matches before each.
    int solves = 2;
    // Votes an element needs before its type is reassigned (section V.B).
    int votes = 2;
    // Size k of each input element's similarity set (k-coherence).
    int k = 6;
    // Weight of the attribute (type) term, squared length units; negative = automatic.
    double alpha = -1.0;
    // Tree search: play-outs per round, and the explore / exploit constants of Eq. 5.
    int playouts = 24;
    double explore = 0.5;
    double exploit = 1.0;
    // Bound on the rounds of one grow() call (reported when hit).
    int max_rounds = 10000;
    // grow(region): stop where the horizon proposes nothing, as the paper does, instead of
    // filling what it did not reach (places farther from every element than twice the
    // exemplar's largest hole plus its spacing) by neighbourhood synthesis next to it.
    bool stop_at_horizon = false;
    // grow(region): sweeps of the final pair-correlation relaxation of the call's elements,
    // as synthesize_det's (DetOptions::relax_sweeps); 0 = none; negative = automatic: 4 for
    // a soft pattern (closest pairs well under the typical distance: most field data), 0
    // where a hard core holds the pair correlation. Single-sample exemplars.
    int relax_sweeps = -1;
    // Local orientation field of the output (patches are rotated by it).
    OrientationField field;
    int threads = 0;  // 0 = all hardware threads; results are identical for every value
    std::uint64_t seed = 1;
};

// What one call did.
struct GrowReport {
    int rounds = 0;
    int added = 0;           // net: elements made (the seed patch included) less elements displaced
    int candidates = 0;      // proposed, before the filters
    int merged = 0;          // dropped as overlapping
    int high_energy = 0;     // dropped by the energy filter
    int outside = 0;         // dropped outside the target region
    int reassigned = 0;      // types changed by votes or redistribution
    int last_made = 0;       // elements the last round made (before displacements)
    int displaced = 0;       // recent elements a candidate of a type short of its share replaced
    int filled = 0;          // elements put into enclosed holes behind the horizon
    int uncovered = 0;       // grow(region): elements put where the horizon did not reach
    int rare = 0;            // grow(region): elements of a rare type put where growth left it short
    int thinned = 0;         // grow(region): removed where the region held more than its density asks
    int relaxed = 0;         // grow(region): moves the pair-correlation relaxation kept
    bool covered = false;    // grow(region): the region took no more elements
    bool bound_hit = false;  // the round bound (GrowOptions::max_rounds) stopped the call
    double energy = 0.0;     // mean neighbourhood energy of the last round's horizon (Eq. 4 / |H|)
    double seconds = 0.0;
};

class Grower {
public:
    // Validates the exemplar (Error(input)) and options (Error(option), naming the field)
    // and indexes the exemplar's elements.
    Grower(const Exemplar& exemplar, const GrowOptions& options = {});
    ~Grower();
    Grower(Grower&&) noexcept;
    Grower& operator=(Grower&&) noexcept;
    // A copy with its own arrangement and state: far cheaper than indexing the exemplar again
    // (a world copies one indexed Grower for every tile). Copying from a Grower that other
    // threads only copy from too is safe.
    Grower(const Grower& other);
    Grower& operator=(const Grower&) = delete;

    // Starts from a copy of an exemplar patch centred at `center` (its elements are the first
    // horizon). grow() does this at the region's centre when the arrangement is empty.
    void seed(const Vec3& center);
    // Starts from a patch at each centre, each drawn as seed() draws one; an element of a later
    // patch that would come closer to an element already there than their hard core is left
    // out. All are the first horizon. (A world's first tiles start so: one patch would make
    // every tile that draws the same seed element the same tile.)
    void seed(const std::vector<Vec3>& centres);
    // Starts from `existing`, whose types are matched to the exemplar's by name
    // (Error(input) for an unknown type or a different sample count). Its elements become
    // locked and are the first horizon.
    void set_arrangement(const Arrangement& existing);

    // Grows until `region` takes no more elements: candidates outside it are discarded.
    // Error(domain) for an empty region, Error(input) when the arrangement is not empty and
    // no element lies within reach of the region.
    GrowReport grow(const Domain& region, RegionEdge edge = RegionEdge::closed);
    // Grows by about n elements (Error(option) for n <= 0), outward from the arrangement.
    GrowReport grow(int n);
    // One round, unbounded (no region).
    GrowReport step();

    // Progress events at the start, after each round and at the end; the last one is also
    // re-sent about every 50 ms inside a round (tessera/progress.hpp). A callback returning
    // false cancels: the call throws Cancelled within about 0.1 s, and the arrangement stays
    // valid, with every round finished before (a round cancelled during its optimization
    // keeps its elements as far as they were optimized; one cancelled earlier is undone).
    void set_progress(Progress progress);
    // The report of the last grow call or step, also of one that was cancelled (up to its
    // last finished round).
    const GrowReport& last_report() const;

    const Arrangement& arrangement() const;
    // Indices of the current horizon's elements.
    const std::vector<int>& horizon() const;
    double radius() const;

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

}  // namespace tessera
