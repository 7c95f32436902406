// Crowding repair: no output holds more close pairs than its exemplar.
//
// A synthesis method reproduces an exemplar's typical spacing, but where its pieces meet
// (patch seams, a least-squares compromise, a random insertion) two elements can end up
// closer together than the exemplar ever shows them, or on top of each other. Such
// near-duplicates are the first thing a viewer notices and barely move the averages
// (the pair correlation) a method optimises.
//
// The exemplar tells how close elements may come: for each ordered pair of element types
// (a, b), the distribution of the distance from a sample of an a element to the nearest
// sample of another, b element (for single-sample elements: element to element; for
// noodles and sticks the samples see crossings that centroids miss). The repair holds the
// lower tail of the output's distribution to the exemplar's: ranking the output's samples
// of a elements by that distance, the k-th of n_a may be no closer than the
// exemplar's quantile at k / (n_a * slack), for the lowest `tail` share (and at least the
// exemplar's three closest distances). So a clustered
// exemplar keeps its legitimate close pairs, an exemplar with a few coincident pairs may
// keep that share of them (its quantiles are 0 there), and a hard-core pattern keeps its
// hard core; nothing beyond the tail is touched. Elements that break the bound are pushed
// apart from their nearest b (half each when the violation is mutual), whole elements
// move rigidly, locked ones never move, and no element is moved out of the domain. The
// rounds are bounded and the report says when the bound was hit.
#pragma once

#include <vector>

#include "core/interrupt.hpp"
#include "tessera/domain.hpp"
#include "tessera/exemplar.hpp"

namespace tessera::core {

// What the distances are measured between: element centroids (the statistic a viewer of
// point patterns judges), or samples of different elements (for multi-sample elements:
// two noodles that cross have distant centroids but touching samples).
enum class CrowdingLevel { centroids, samples };

// Per ordered type pair (a, b): the sorted distances from each point (centroid or sample)
// of an exemplar a element to the nearest point of another b element.
class NearestDistanceTails {
public:
    NearestDistanceTails() = default;
    NearestDistanceTails(const Exemplar& exemplar, CrowdingLevel level);

    CrowdingLevel level() const { return level_; }
    int types() const { return types_; }
    // Exemplar distances for (a, b), ascending (empty when b never neighbours a).
    const std::vector<double>& distances(int a, int b) const { return sorted_[a * types_ + b]; }
    // The u-quantile of distances(a, b): the smallest distance with a share u at or below it
    // (the inverse empirical distribution, R's type 1); 0 when empty.
    double quantile(int a, int b, double u) const;
    // The largest distance any repair bound can ask for: the `tail` quantile over all pairs.
    double reach(double tail) const;
    // The same for the pairs (a, *): as far as a point of type a has to look.
    double reach(int a, double tail) const;
    // The largest bound a repair holds a point of type a to against its nearest of type b (0
    // when b never neighbours a): a pair at least this far apart is never repaired.
    double tail_distance(int a, int b, double tail) const;
    // The smallest exemplar distance of (a, b) or (b, a), or 0 when neither is known:
    // closer than this two points of elements of these types never are.
    double hard_core(int a, int b) const;

private:
    CrowdingLevel level_ = CrowdingLevel::centroids;
    int types_ = 0;
    std::vector<std::vector<double>> sorted_;
};

// The bounds a repair holds: between centroids always, and between samples of different
// elements when the exemplar has multi-sample elements.
struct CrowdingBounds {
    explicit CrowdingBounds(const Exemplar& exemplar);
    NearestDistanceTails centroids;
    bool has_samples = false;
    NearestDistanceTails samples;
    // The closest approach of points of two types: between samples where they are known.
    double hard_core(int a, int b) const { return (has_samples ? samples : centroids).hard_core(a, b); }
    int types() const { return centroids.types(); }
};

struct CrowdingRepairOptions {
    double tail = 0.03;   // share of each type's elements (the closest) whose distance is bounded,
                          // and at least the share of the exemplar's three closest distances
    double slack = 1.25;  // the output may hold this many times the exemplar's share below any distance
    int rounds = 12;      // repair rounds at most
    int threads = 1;      // worker threads (0 = all); results are the same for any value
    // Elements whose level along `level_axis` must not change (floor elements that keep their
    // elevation): per element, non-zero = held; empty = none. Their moves keep to the plane.
    std::vector<char> held_level;
    Vec3 level_axis{0, 1, 0};
    const Interrupt* interrupt = nullptr;  // checked before every round (a cancel)
};

struct CrowdingRepairReport {
    int moved = 0;           // element moves made
    int rounds = 0;          // rounds run
    int remaining = 0;       // elements still closer than their bound after the last round
    bool bound_hit = false;  // stopped by `rounds` with violations left
};

// Repairs `data` (elements with their samples; types as in `tails`) in place (element
// positions are first recomputed from the samples), keeping
// every moved sample inside `domain`. Deterministic for any thread count.
CrowdingRepairReport repair_crowding(Exemplar& data, const Domain& domain, const CrowdingBounds& bounds,
                                     const CrowdingRepairOptions& options = {});

// An element closer to its nearest neighbour of some type than its rank allows, and that neighbour.
struct CrowdedPair {
    int element = -1, neighbour = -1;
};
// The element pairs repair_crowding would move now (each pair once per direction), without
// moving anything; in element order.
std::vector<CrowdedPair> crowded_pairs(const Exemplar& data, const CrowdingBounds& bounds,
                                       const CrowdingRepairOptions& options = {});

}  // namespace tessera::core
