// The state a Grower keeps (include/tessera/grow.hpp): the indexed exemplar and the output,
// one record per element with the input element it copies, in a dynamic grid.
#pragma once

#include <array>

#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/crowding_repair.hpp"
#include "core/dynamic_grid.hpp"
#include "core/interrupt.hpp"
#include "det/pair_relaxation.hpp"
#include "grow/crowd_ceiling.hpp"
#include "grow/input_elements.hpp"
#include "grow/pairing.hpp"
#include "tessera/grow.hpp"

namespace tessera {

namespace grow {

// One output element. Grown elements are a rigid copy of input element `source`, turned by
// `frame` (the field's frame where it was made); elements of an existing arrangement keep
// their own samples (`kept`, an index into Grower::Impl::existing).
struct OutElement {
    Vec3 p;  // centroid
    int type = 0;
    int source = -1;  // input element copied; -1 = an element of the existing arrangement
    int kept = -1;
    Quat frame;
    int match = -1;  // input element its neighbourhood matched best last time
    int born = 0;    // round that made it
    bool locked = false;  // never moved: an existing element, or one of the fill (`filled`)
    // Put by the fill of what growth did not reach (grow/uncovered.hpp): fixed for growth
    // like an existing element, but not locked in the caller's arrangement.
    bool filled = false;
    int tries = 0;  // as Candidate::tries, while it is being filtered
    int crowd = 0;  // other elements within Impl::crowd's radius (kept only while it is active)
    std::uint64_t id = 0;
};

// A proposed element (section IV).
struct Candidate {
    Vec3 p;
    int type = 0;
    int source = -1;  // input element e' whose attributes and layout it copies
    Quat frame;
    double fit = 0.0;   // mean energy (Eq. 3 per neighbour) of its proposer's match
    int proposer = -1;  // horizon element that proposed it
    int order = 0;      // its rank among the proposer's candidates
    int tries = 0;      // rounds it was proposed again after the energy filter dropped it
};

// Elements whose neighbourhood match is worth a thread of its own (a match takes tens of
// microseconds, as does starting a thread): core::parallel_for's grain in growth's loops.
constexpr int kElementsPerThread = 16;

// Buffers of one worker (no allocation in the inner loops once warm).
struct Scratch {
    std::vector<int> candidates, partner;
    std::vector<det::NeighborEntry> entries;
    det::MatchScratch match;
    PairScratch pair;
};

}  // namespace grow

struct Grower::Impl {
    Impl(const Exemplar& exemplar, const GrowOptions& options);

    Exemplar exemplar;
    GrowOptions options;
    grow::Metric metric;
    int threads = 1;
    grow::InputElements input;
    core::CrowdingBounds bounds;  // the exemplar's close-distance tails (centroids, samples)
    double reach = 0.0;           // the largest hard core: the overlap filter's query radius
    double extent = 0.0;          // the farthest sample from its element's centroid
    // Radius of the exemplar's largest empty disk or ball (det::exemplar_hole_radius): holes
    // behind the horizon deeper than it are filled (grow/vacancies.hpp), for exemplars of
    // single-sample elements only (`fills_holes`).
    double hole_radius = 0.0;
    bool fills_holes = false;
    // The exemplar's clumping (grow/thinning.cpp), measured on first use.
    std::optional<double> clumping;
    // The final pair-correlation relaxation of grow(region) (grow/relax.hpp): its sweeps
    // (GrowOptions::relax_sweeps, the automatic choice resolved), and the relaxation when
    // there are some (it applies to exemplars of single-sample elements).
    int relax_sweeps = 0;
    std::optional<det::PairRelaxation> relaxation;
    // Per type pair (row: a candidate's type, column: an existing element's): whether the
    // candidate must lie in its proposer's Voronoi cell (grow/generate.cpp, propose). Set for
    // single-sample exemplars where the pair's closest distance is well under its typical
    // one, so that the hard core alone does not keep patches copied at misaligned offsets
    // from both filling one place.
    std::vector<char> owned;
    // Multi-sample exemplars: a candidate that touches others takes another input element's
    // shape (generate.cpp, reshape) only where fewer elements than this lie within r of the
    // place and of each element near it: one more than the 85% quantile of the counts of the
    // exemplar's pool elements. Without it, rods in a 3D slab, which fit many orientations,
    // filled the gaps the exemplar leaves and grew at 1.64x.
    int reshape_ceiling = 0;
    // The count ceiling the overlap filter holds every element to (grow/crowd_ceiling.hpp);
    // add, move and drop_tail keep each element's `crowd` up to date while it is active.
    grow::CrowdCeiling crowd;
    bool any_owned = false;
    bool owned_by_proposer(int candidate_type, int other_type) const {
        return owned[candidate_type * exemplar.types.size() + other_type] != 0;
    }

    // A 3D box exemplar no thicker than two growth reaches (patch + r) along an axis, and
    // thicker along the other two, is a layer (a membrane, rods on a floor): its layers are
    // linked only through the few elements that span them (a lipid's patch never reaches
    // the other leaflet), and offsets copied element to element drift across it. Without a
    // field, a seed copies its whole thickness (`layer`, grower.cpp), and every element
    // growth places from then on lies at its input element's coordinate along those axes
    // plus `layer_origin` (set by the first seed; `layer_registered`).
    std::array<bool, 3> layer{false, false, false};
    // Depths further than this share of the spacing from every depth the exemplar holds an
    // element's type at are off the layer (the fill's elements, a reshape's shapes, an
    // existing arrangement's elements).
    static constexpr double kLayerTolerance = 0.25;
    bool layer_registered = false;
    Vec3 layer_origin;
    // Registers the layer on the elements already there (an existing arrangement): the depth
    // offset most of them share with exemplar elements of their type, when at least half
    // of them lie at it; else the layer stays unregistered.
    void register_layer_of_elements();
    // Along the registered layer axes, the place of input element `source`'s centroid.
    void register_on_layer(int source, Vec3& p) const {
        if (!layer_registered || source < 0) return;
        for (int k = 0; k < 3; ++k)
            if (layer[k]) p[k] = layer_origin[k] + input.centroid[source][k];
    }
    // A move from `from` to `to` kept on the registered layer: `to`'s layer-axis coordinates
    // put back to `from`'s (the solve, the repair and the nudge move elements within it).
    void keep_on_layer(const Vec3& from, Vec3& to) const {
        if (!layer_registered) return;
        for (int k = 0; k < 3; ++k)
            if (layer[k]) to[k] = from[k];
    }
    // Whether an element of `type` centred at p lies within kLayerTolerance spacings of a
    // depth the exemplar holds an element of the type at (always, when no layer is
    // registered).
    bool on_layer(int type, const Vec3& p) const;

    std::vector<grow::OutElement> out;
    // Elements of each type in `out`, kept by add, drop_tail, set_type and clear (the type
    // balance asks for it every round; counting would cost the whole output each time).
    std::vector<int> type_count;
    core::DynamicGrid grid;
    std::vector<int> horizon;
    // Candidates the energy filter dropped, proposed again next round: their neighbourhood
    // is fuller then, and a place left empty would stay a hole behind the horizon.
    std::vector<grow::Candidate> retry;
    Arrangement existing;  // samples of the elements kept from set_arrangement
    int round = 0;
    // First element of each round that added some (elements are stored in round order), and
    // the first of the recent rounds whose elements a candidate short of its type's share may
    // displace (generate.cpp, TypeBalance): they are all at the tail of `out`.
    std::vector<int> round_first;
    int recent_first = 0;
    int displaced = 0;  // elements removed so, in the current round
    int reshaped = 0;   // multi-sample candidates that took another input element's shape
    std::uint64_t next_id = 0;
    Box grown;  // union of the regions grown (the arrangement's domain)
    bool has_bounds = false;
    // The grow(region) call in progress treats the region as one cell of a partition
    // (RegionEdge::open, the tiles of a world): only element centres must lie in it, samples
    // may reach beyond, and candidates just outside are left to the neighbouring cell.
    bool open_region = false;
    // seed() placed the last patches and no round has run since: grow(region) keeps those of
    // their elements that fit the region (the others would be outside it).
    bool seed_pending = false;
    // Whether an element of input layout `source` in `frame` at p lies in the region as the
    // call in progress counts it: its centre (open region) or every sample (samples: scratch).
    bool fits_region(const Domain& region, int kept, int source, const Quat& frame, const Vec3& p,
                     std::vector<Vec3>& samples) const;

    Progress progress;
    ProgressEvent last_event;  // the last event sent, sent again by the interrupt's polls
    // Polled inside a round's long loops (core/interrupt.hpp): a cancel takes effect within
    // about 0.1 s, not only between rounds (a round of a large 3D growth takes most of a second).
    core::Interrupt interrupt{poll()};
    // The interrupt's poll: this Impl's progress, re-sent (a copied Impl gets its own).
    std::function<void()> poll() {
        return [this] {
            if (progress && !progress(last_event)) throw Cancelled();
        };
    }
    GrowReport last_report;  // of the last call, kept up to date round by round
    std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
    mutable Arrangement view;  // arrangement(), rebuilt when `dirty`
    mutable bool dirty = true;

    // Local frame of the field at p (identity without one).
    Quat frame_at(const Vec3& p) const;
    // Hard-core distance between the centroids of types a and b, with a floor so that
    // coincident candidates always merge (for multi-sample elements a low quantile of the
    // exemplar's distances, grow_state.cpp).
    double hard_core(int a, int b) const { return hard_cores[a * exemplar.types.size() + b]; }
    // Hard-core distance between samples of different elements of types a and b (0 when the
    // exemplar has no multi-sample elements).
    double sample_core(int a, int b) const { return sample_cores[a * exemplar.types.size() + b]; }
    // Both per type pair (row a, column b), computed once: they are asked in the inner loops.
    std::vector<double> hard_cores, sample_cores;
    // The centroid distance under which crowding repair moves a pair of types a and b (the
    // tail of the exemplar's nearest distances, core::CrowdingRepairOptions::tail), per type
    // pair, and the largest of them: the repair's skip test asks them for every part.
    std::vector<double> repair_bounds;
    double repair_reach = 0.0;
    double repair_bound(int a, int b) const { return repair_bounds[a * exemplar.types.size() + b]; }
    double compute_hard_core(int a, int b) const;
    // Appends an element (grid included); returns its index.
    int add(const grow::OutElement& e);
    // Appends a copy of input element `source` (of type `type`) put into a hole at p: in the
    // field's frame there, born this round, with a new id, not on the horizon; returns its index.
    int add_filling(int type, int source, const Vec3& p);
    // Adds `change` to the crowd of every element other than `self` within the ceiling's
    // radius of p; returns how many there are.
    int count_crowd(const Vec3& p, int self, int change);
    // Whether an element at p would have at least one neighbour fewer within the ceiling's
    // radius than the ceiling allows (always, while the ceiling is inactive). The hole
    // filling asks only this, not its neighbours' counts: those count the crowded places
    // around the hole too, and a hole left open is worse than a neighbour over the ceiling.
    bool crowd_allows(const Vec3& p) const;
    // Changes element i's type (the counts included).
    void set_type(int i, int type);
    // Removes every element (a fresh output over the same index).
    void clear();
    // Moves element i to p (grid included).
    void move(int i, const Vec3& p);
    // Removes the elements from index `first` on whose `keep` is 0 (they are the newest).
    void drop_tail(int first, const std::vector<char>& keep);
    // Removes the elements from index `base` on whose `removed` is 1 and renumbers what refers
    // to the elements after them: the horizon and the rounds' first indices.
    void remove_and_renumber(int base, const std::vector<char>& removed);
    // Sample positions of an element centred at p: the samples of existing element `kept`
    // (when >= 0), else input element `source`'s layout turned by `frame`.
    void sample_positions(int kept, int source, const Quat& frame, const Vec3& p,
                          std::vector<Vec3>& out) const;
};

}  // namespace tessera
