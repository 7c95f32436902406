// Filling enclosed holes behind the horizon (grow/vacancies.hpp).
#include "grow/vacancies.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/parallel.hpp"
#include "grow/ball_lattice.hpp"
#include "grow/generate.hpp"
#include "grow/repair.hpp"

namespace tessera::grow {

namespace {

// A neighbour within this cosine of a direction covers it.
constexpr double kCover = 0.5;
// A hole is enclosed when every direction is covered by an element within this many spacings
// of its rim: the open side of the horizon is empty much further, while three or four
// elements around a hole can leave a gap wider than the cover's 120 degrees.
constexpr double kEnclosureReach = 2.5;
// Pattern-search levels that centre a probed hole (steps from a quarter spacing, halved).
constexpr int kCentreLevels = 4;
// An element goes into a hole whose rim is at least this share of its hard cores away; the
// crowding repair then pushes its neighbours out to the hard cores (a hole a little smaller
// than an element is still a hole a viewer sees).
constexpr double kSqueeze = 0.8;
// A type already over its share fills only holes this many times deeper than the exemplar's
// largest (a smaller one is left for later rounds' larger elements, not filled with more
// of the small ones).
constexpr double kOverShareDepth = 1.1;


// The covered pass's probe lattice, in exemplar holes, and the most probes it makes (a
// region that would need more is left to the rounds' own search).
constexpr double kCoveredProbeStep = 0.5;
constexpr double kMaxCoveredProbes = 1 << 24;
constexpr int kCoveredRowsPerThread = 16;

// Rounds of search and insertion per call: the later ones probe around the elements just
// inserted, for the rest of a hole larger than one element.
constexpr int kPasses = 3;

// An enclosed hole found by the search: its centre and depth (rim-to-rim clearance).
struct Hole {
    Vec3 c;
    double depth = 0.0;
};

// The search, read-only on the state so that it runs in parallel: the holes next to one
// element, each centred and tested for enclosure.
class HoleFinder {
public:
    HoleFinder(const Grower::Impl& g, const Domain* region, bool enclosed_only = true)
        : g_(g),
          region_(region),
          enclosed_only_(enclosed_only),
          dirs_(probe_directions(g.metric.dimension)),
          spacing_(g.metric.params.spacing),
          hole_(enclosed_only ? g.hole_radius : kCoveredHoleDepth * g.hole_radius) {
        for (const Element& e : g.exemplar.elements) max_rim_ = std::max(max_rim_, e.radius);
    }

    double hole() const { return hole_; }
    // How close to a neighbour of type b an element of type a put in a hole may come: the
    // rounds squeeze it to kSqueeze of the hard core (the crowding repair then pushes the
    // neighbours out); a covered region's holes are deep enough to keep the distance under
    // which the repair would move the pair, and there the neighbours are often locked
    // (earlier tiles of a world: a 3D world of spheres crowded).
    double closest(int a, int b) const {
        return enclosed_only_ ? kSqueeze * g_.hard_core(a, b) : std::max(g_.hard_core(a, b), g_.repair_bound(a, b));
    }
    // How deep the search looks: while growth goes on, a place emptier than 3 spacings is the
    // open frontier, not a hole. In a covered region there is no frontier, and the search
    // reaches the depth from which the fill of what growth did not reach takes over
    // (uncovered_distance: twice the exemplar's hole and a spacing): a random pattern's holes
    // run past 3 spacings (the Japanese pines' largest is 2.7 of their mean nearest
    // distance), and one 1.4x the exemplar's was taken for the frontier and left.
    double cap() const {
        return enclosed_only_ ? 3.0 * spacing_ : std::max(3.0 * spacing_, 2.0 * hole_ + 2.0 * spacing_);
    }

    // Buffers of one worker.
    struct Buffers {
        std::vector<int> near, probe;
    };

    // The enclosed holes deeper than the exemplar's in the directions element i has no
    // neighbour, appended to `out` in the order of the directions.
    void holes_around(int i, Buffers& b, std::vector<Hole>& out) const {
        const Vec3 at = g_.out[i].p;
        g_.grid.query(
            at, 1.5 * spacing_, [&](int j) { return g_.out[j].p; }, b.near);
        for (const Vec3& d : dirs_) {
            if (covered(at, d, 1.5 * spacing_, b.near)) continue;
            Hole h;
            if (centred_hole(at + d * (rim(i) + hole_ + 0.25 * spacing_), b, h)) out.push_back(h);
        }
    }

    // Rim-to-rim distance from c to the nearest element, at most cap.
    double clearance(const Vec3& c, double cap) const {
        double best = cap;
        g_.grid.for_each_within(
            c, cap + max_rim_, [&](int j) { return g_.out[j].p; },
            [&](int j) { best = std::min(best, norm(g_.out[j].p - c) - rim(j)); });
        return best;
    }

    double max_rim() const { return max_rim_; }

    // The hole found by a pattern search from c (as holes_around's from its probes).
    bool hole_at(const Vec3& c, Buffers& b, Hole& out) const { return centred_hole(c, b, out); }

private:
    double rim(int i) const {
        return g_.out[i].kept >= 0 ? g_.existing.elements[g_.out[i].kept].radius
                                   : g_.exemplar.elements[g_.out[i].source].radius;
    }

    // A neighbour of `at` (among `near`) within `reach` lies within kCover of direction d.
    bool covered(const Vec3& at, const Vec3& d, double reach, const std::vector<int>& near) const {
        for (const int j : near) {
            const Vec3 v = g_.out[j].p - at;
            const double l = norm(v);
            if (l > 1e-12 && l <= reach && dot(v, d) >= kCover * l) return true;
        }
        return false;
    }

    // Pattern search from c to the deepest point nearby in the region; true when that hole is
    // deeper than the exemplar's and enclosed in every direction (by elements or the region's
    // outside).
    bool centred_hole(Vec3 c, Buffers& b, Hole& out) const {
        if (g_.metric.dimension == 2) c.z = 0.0;
        double depth = clearance(c, cap());
        for (int level = 0, step = 0; level < kCentreLevels; ++level) {
            const double h = 0.25 * spacing_ / (1 << level);
            for (bool moved = true; moved && step < 8 * kCentreLevels; ++step) {
                moved = false;
                for (int k = 0; k < 2 * g_.metric.dimension; ++k) {
                    Vec3 q = c;
                    q[k / 2] += (k % 2 ? -h : h);
                    // In a covered region the search stays in it: a hole against its edge
                    // opens toward the outside, where no element is, and would be followed out.
                    // (While growth goes on, such places are the region's own frontier.)
                    if (!enclosed_only_ && region_ && !region_->inside(q)) continue;
                    const double dq = clearance(q, cap());
                    if (dq > depth) c = q, depth = dq, moved = true;
                }
            }
        }
        if (!(depth > hole_) || !(depth < cap()) || (region_ && !region_->inside(c))) return false;
        out.c = c;
        out.depth = depth;
        // A covered region's hole need not be enclosed, unless the region is a world's
        // tile: there a hole open toward a face the next tiles have not grown yet is theirs
        // to fill (filled here, a 3D world of spheres crowded its seams).
        if (!enclosed_only_ && !(region_ && g_.open_region)) return true;
        const double reach = depth + kEnclosureReach * spacing_;
        g_.grid.query(
            c, reach, [&](int j) { return g_.out[j].p; }, b.probe);
        for (const Vec3& d : dirs_) {
            if (covered(c, d, reach, b.probe)) continue;
            // While growing, the region's outside encloses too; in a covered tile only the
            // directions out of it need an element (those into it are covered ground).
            const bool outside = region_ && !region_->inside(c + d * (depth + spacing_));
            if (enclosed_only_ ? !outside : outside) return false;
        }
        return true;
    }

    const Grower::Impl& g_;
    const Domain* region_;
    bool enclosed_only_ = true;
    std::vector<Vec3> dirs_;
    double spacing_ = 1.0, hole_ = 0.0, max_rim_ = 0.0;
};

// The insertion, serial: each hole found, still deeper than the exemplar's once the earlier
// insertions are in, gets an element.
class HoleFiller {
public:
    HoleFiller(Grower::Impl& g, const HoleFinder& finder)
        : g_(g), finder_(finder), balance_(g), types_(g.exemplar.types.size()) {}

    // Returns whether an element went into the hole.
    bool fill(const Hole& hole) {
        const double depth = finder_.clearance(hole.c, finder_.cap());
        return depth > finder_.hole() && insert(hole.c, depth);
    }

    const std::vector<int>& inserted() const { return inserted_; }

    // The inserted elements and their unlocked neighbours, sorted (what the repair moves).
    std::vector<int> movable() const {
        std::vector<int> m = inserted_, near;
        for (const int v : inserted_) {
            g_.grid.query(
                g_.out[v].p, g_.reach, [&](int j) { return g_.out[j].p; }, near);
            for (const int j : near)
                if (!g_.out[j].locked) m.push_back(j);
        }
        std::sort(m.begin(), m.end());
        m.erase(std::unique(m.begin(), m.end()), m.end());
        return m;
    }

private:
    // The type most short of its share whose hard cores hold at c, copied from the input
    // element of that type nearest the nearest neighbour's match.
    bool insert(const Vec3& c, double depth) {
        g_.grid.query(
            c, std::max(g_.reach, depth + finder_.max_rim() + 1e-9), [&](int j) { return g_.out[j].p; },
            probe_);
        if (probe_.empty() || !g_.crowd_allows(c)) return false;
        int nearest = probe_[0];
        for (const int j : probe_)
            if (norm(g_.out[j].p - c) < norm(g_.out[nearest].p - c)) nearest = j;
        for (size_t t = 0; t < types_.size(); ++t) types_[t] = static_cast<int>(t);  // ties in type order
        std::stable_sort(types_.begin(), types_.end(),
                         [&](int a, int b) { return balance_.deficit(a) > balance_.deficit(b); });
        for (const int t : types_) {
            if (types_.size() > 1 && balance_.deficit(t) < -1e-9 &&
                !(depth > kOverShareDepth * finder_.hole()))
                continue;
            bool fits = true;
            for (const int j : probe_)
                if (norm(g_.out[j].p - c) < finder_.closest(t, g_.out[j].type)) fits = false;
            if (!fits) continue;
            const OutElement& from = g_.out[nearest];
            const Vec3 near_input = from.match >= 0
                                        ? g_.input.centroid[from.match]
                                        : (from.source >= 0 ? g_.input.centroid[from.source] : Vec3{});
            const int source = g_.input.nearest_in_pool(t, near_input, 1e300);
            if (source < 0) continue;
            inserted_.push_back(g_.add_filling(t, source, c));
            balance_.add(t);
            return true;
        }
        return false;
    }

    Grower::Impl& g_;
    const HoleFinder& finder_;
    TypeBalance balance_;  // counted once per call, kept up to date by insert()
    std::vector<int> types_;
    std::vector<int> inserted_, probe_;
};

// The holes around elements `around`, found in parallel, listed in their order.
std::vector<Hole> find_holes(const Grower::Impl& g, const HoleFinder& finder,
                             const std::vector<int>& around) {
    const int n = static_cast<int>(around.size());
    std::vector<std::vector<Hole>> per(n);
    core::parallel_for(
        n, g.threads,
        [&](int begin, int end, int thread) {
            HoleFinder::Buffers b;
            for (int k = begin; k < end; ++k) {
                g.interrupt.check(thread);
                finder.holes_around(around[k], b, per[k]);
            }
        },
        kElementsPerThread);
    std::vector<Hole> all;
    for (const std::vector<Hole>& h : per) all.insert(all.end(), h.begin(), h.end());
    return all;
}

}  // namespace

namespace {

int fill_holes(Grower::Impl& g, std::vector<int> around, const Domain* region, bool enclosed_only) {
    if (!g.fills_holes || around.empty()) return 0;
    const HoleFinder finder(g, region, enclosed_only);
    HoleFiller filler(g, finder);
    for (int pass = 0; pass < kPasses && !around.empty(); ++pass) {
        const size_t before = filler.inserted().size();
        for (const Hole& h : find_holes(g, finder, around)) filler.fill(h);
        around.assign(filler.inserted().begin() + before, filler.inserted().end());
    }
    const int added = static_cast<int>(filler.inserted().size());
    if (added > 0) repair_round(g, filler.movable(), region);
    return added;
}

}  // namespace

int fill_enclosed_holes(Grower::Impl& g, int first, int end, const Domain* region) {
    std::vector<int> around;
    for (int i = first; i < end; ++i) around.push_back(i);
    return fill_holes(g, std::move(around), region, true);
}

int fill_enclosed_holes_around(Grower::Impl& g, const std::vector<int>& around, const Domain* region) {
    return fill_holes(g, around, region, true);
}

namespace {

// The covered pass's lattice over the region: `step` apart, `n` points along each axis.
struct ProbeLattice {
    Box box;
    double step = 0.0;
    int n[3] = {1, 1, 1};
    Vec3 point(int x, int y, int z, int dim) const {
        Vec3 c = box.lo + Vec3{(x + 0.5) * step, (y + 0.5) * step, (z + 0.5) * step};
        if (dim == 2) c.z = box.lo.z;
        return c;
    }
};

// The holes found from the lattice points at least `empty` from every element's rim, row by
// row in parallel (read-only), listed in lattice order.
std::vector<Hole> find_lattice_holes(const Grower::Impl& g, const HoleFinder& finder, const Domain& region,
                                     const ProbeLattice& lattice, double empty) {
    const int dim = g.metric.dimension, rows = lattice.n[1] * lattice.n[2];
    std::vector<std::vector<Hole>> per(rows);
    core::parallel_for(
        rows, g.threads,
        [&](int begin, int end, int thread) {
            HoleFinder::Buffers buffers;
            for (int row = begin; row < end; ++row) {
                g.interrupt.check(thread);
                for (int x = 0; x < lattice.n[0]; ++x) {
                    const Vec3 c = lattice.point(x, row % lattice.n[1], row / lattice.n[1], dim);
                    Hole h;
                    if (region.inside(c) && !(finder.clearance(c, empty) < empty) && finder.hole_at(c, buffers, h))
                        per[row].push_back(h);
                }
            }
        },
        kCoveredRowsPerThread);
    std::vector<Hole> all;
    for (const std::vector<Hole>& h : per) all.insert(all.end(), h.begin(), h.end());
    return all;
}

}  // namespace

int fill_covered_holes(Grower::Impl& g, int first, int end, const Domain& region) {
    if (!g.fills_holes || first >= end || !(g.hole_radius > 0.0)) return 0;
    // Probing from every element, as the rounds do, cost a world's tiles 30% more. A lattice
    // of step s holds a point within s sqrt(d) / 2 of every hole's centre, so a hole deeper
    // than the threshold has a lattice point at least the threshold minus that from every
    // element's rim; such points (rare) start the search.
    const HoleFinder finder(g, &region, false);
    HoleFiller filler(g, finder);
    const int dim = g.metric.dimension;
    ProbeLattice lattice;
    lattice.box = region.bounds();
    lattice.step = kCoveredProbeStep * g.hole_radius;
    for (int k = 0; k < dim; ++k)
        lattice.n[k] = std::max(1, static_cast<int>(std::ceil((lattice.box.hi[k] - lattice.box.lo[k]) / lattice.step)));
    if (static_cast<double>(lattice.n[0]) * lattice.n[1] * lattice.n[2] > kMaxCoveredProbes) return 0;
    const double empty = finder.hole() - 0.5 * lattice.step * std::sqrt(static_cast<double>(dim));
    for (int pass = 0; pass < kPasses; ++pass) {
        const size_t before = filler.inserted().size();
        for (const Hole& h : find_lattice_holes(g, finder, region, lattice, empty)) filler.fill(h);
        if (filler.inserted().size() == before) break;
    }
    const int added = static_cast<int>(filler.inserted().size());
    if (added > 0) repair_round(g, filler.movable(), &region);
    return added;
}

}  // namespace tessera::grow
