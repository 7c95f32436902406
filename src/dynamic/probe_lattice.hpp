// A regular lattice of probe points (cell centres) over a domain's bounding box, the ones
// inside the domain marked, onto which disks (balls in 3D) are stamped: the probes no disk
// covers are the places farther than the disks' radius from every centre. Stamping costs the
// disk's probes per centre, a few dozen, where a nearest-neighbour query per probe cost ten
// times as much (the void closing runs twice a frame).
#pragma once

#include <vector>

#include "tessera/domain.hpp"

namespace tessera::dynamic {

class ProbeLattice {
public:
    ProbeLattice() = default;
    // Probes about `step` apart (exactly extent / count along each axis, so that with
    // `periodic` the lattice repeats across the box's faces).
    ProbeLattice(const Domain& domain, double step, bool periodic);

    int size() const { return static_cast<int>(inside_.size()); }
    Vec3 point(int i) const;
    bool inside(int i) const { return inside_[i] != 0; }
    bool covered(int i) const { return covered_[i] != 0; }

    void clear_stamps() { covered_.assign(inside_.size(), 0); }
    // Covers every probe within `radius` of p (across the faces when periodic).
    void stamp(const Vec3& p, double radius);

private:
    int index_along(int axis, int i, bool& valid) const;

    Vec3 lo_;
    double step_[3] = {1, 1, 1};
    int count_[3] = {1, 1, 1};
    int dimension_ = 2;
    bool periodic_ = false;
    std::vector<char> inside_, covered_;
};

}  // namespace tessera::dynamic
