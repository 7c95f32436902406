// tessera/domain.hpp — where elements live: the region an exemplar was observed
// in, and the region an output must fill. Methods see a domain only through
// inside(p), occupancy c(p) in [0, 1] (Eq. 6 of the Discrete Element Textures
// paper), its bounding box and its measure, so later shapes (polygons, image
// masks, mesh volumes, shells) plug in without touching the methods.
#pragma once

#include <string>

#include "tessera/vec.hpp"

namespace tessera {

struct Box {
    Vec3 lo, hi;
    Vec3 size() const { return hi - lo; }
    Vec3 center() const { return (lo + hi) * 0.5; }
};

class Domain {
public:
    enum class Kind { box };

    // An axis-aligned box. dimension 2 ignores z (lo.z = hi.z = 0 is allowed).
    // Throws Error(domain) if any extent used by `dimension` is not > 0 or not finite.
    static Domain box(const Vec3& lo, const Vec3& hi, int dimension);

    Kind kind() const { return kind_; }
    int dimension() const { return dimension_; }
    const Box& bounds() const { return bounds_; }

    // Inline: Eq. 6 asks it for every neighbour of every candidate of the search.
    bool inside(const Vec3& p) const {
        return p.x >= bounds_.lo.x && p.x <= bounds_.hi.x && p.y >= bounds_.lo.y && p.y <= bounds_.hi.y &&
               (dimension_ == 2 || (p.z >= bounds_.lo.z && p.z <= bounds_.hi.z));
    }
    // Occupancy c(p) of Eq. 6: 1 inside, 0 outside (boxes are sharp).
    double occupancy(const Vec3& p) const { return inside(p) ? 1.0 : 0.0; }
    // Area (2D) or volume (3D).
    double measure() const;
    // |W ∩ (W + d)|: the measure of the domain intersected with its translate by d,
    // used by the translation edge correction of pair correlation estimates.
    double translated_overlap(const Vec3& d) const;
    // The point of the domain nearest to p (p itself when inside).
    Vec3 closest_inside(const Vec3& p) const;
    // Distance from p to the domain boundary (positive inside).
    double distance_to_boundary(const Vec3& p) const;
    // The same shape scaled by `factor` about its lower corner.
    Domain scaled(double factor) const;
    // Human-readable description, e.g. "box [0,10]x[0,10]".
    std::string describe() const;

private:
    Kind kind_ = Kind::box;
    int dimension_ = 2;
    Box bounds_;
};

}  // namespace tessera
