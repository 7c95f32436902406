// An extra solver step of frame-by-frame synthesis (section 4.1, "Extra solver steps"):
// voids wider than any the exemplar holds are closed by moving the samples on their rim a
// little towards their centre, every frame.
//
// Why: the method neither adds nor removes elements, and nothing in the search or the
// assignment fills a void once it is there (a sample on its rim has its neighbours on one side
// and is held by them). A flow opens voids that the exemplar never had: past an obstacle the
// streamlines part at the front stagnation point and particles on either side of the dividing
// line are drawn apart, so a gap runs down the middle of the wake and, with wrap, round again
// (advection alone: largest empty circle 0.97 -> 1.6 over 72 frames). Pulling the rim in
// shrinks such a void and spreads its deficit over the samples round it, which the assignment
// evens out. Voids up to the exemplar's own largest are left alone, so a clustered or sparse
// exemplar's gaps are kept.
#pragma once

#include <vector>

#include "dynamic/output_frames.hpp"
#include "dynamic/probe_lattice.hpp"
#include "tessera/animation.hpp"
#include "tessera/domain.hpp"

namespace tessera::dynamic {

class VoidClosing {
public:
    // Measures the exemplar's largest empty circle (sphere in 3D): over up to 16 of its frames,
    // the largest disk inside its domain that holds no sample (its window's sides are where
    // it was cut out, not walls, so a disk must not cross them).
    VoidClosing(const Animation& exemplar, const Domain& domain, double spacing, const Periodic& periodic);

    // The exemplar's largest empty radius: voids up to it are left alone.
    double exemplar_void() const { return exemplar_void_; }
    // Moves each sample on the rim of a void wider than the exemplar's towards the void's
    // centre by at most a tenth of a spacing (less when the void is only a little too wide),
    // unless that brings it nearer to another than the exemplar's spacing, less its deviation.
    // Returns the number of samples moved.
    int apply(std::vector<Vec3>& positions);

private:
    struct Probe {
        double empty;   // the distance to the nearest sample (at most largest_reach spacings)
        int index;      // the probe's
    };

    double wall_distance(const Vec3& p) const;
    bool crowds(int i, const Vec3& move, const std::vector<Vec3>& positions) const;
    // How wide a void at p may be for the walls: its distance to them plus the allowance.
    double wall_bound(const Vec3& p) const;

    const Domain* domain_;
    Periodic periodic_;
    int dimension_ = 2;
    double spacing_ = 1.0, exemplar_void_ = 0.0;
    double closest_pair_ = 0.0;           // no move brings two samples nearer (the exemplar's mean
                                          // nearest-neighbour distance less its deviation)
    ProbeLattice probes_;                 // over the output domain
    std::vector<int> open_;               // probes no sample's disk of the exemplar's void covers
    PeriodicImages images_;               // the frame's samples (with their periodic images)
    core::SpatialGrid grid_;              // over images_.points
    std::vector<Probe> voids_;
    std::vector<char> claimed_;
    std::vector<Vec3> built_;             // the positions the grid was built over
};

}  // namespace tessera::dynamic
