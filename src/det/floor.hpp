// Constrained selection at the floor (section 5, "Constrained selection"): to keep
// elements from floating, output elements on the floor may only copy input floor
// elements (and the others only non-floor ones), and the assignment keeps the
// elevation of floor elements fixed.
//
// An element is a floor element when its type is marked floor, or when
// DetOptions::floor_distance > 0 and its lowest sample (along gravity) lies within
// that distance of the domain's boundary below it: p + floor_distance * g is
// outside the domain. The test uses only Domain::inside, so it works for boxes,
// bowls and any other shape.
#pragma once

#include <vector>

#include "tessera/det.hpp"
#include "tessera/exemplar.hpp"

namespace tessera::det {

// The axis (0, 1, 2) and sign (-1 or +1) of gravity; Error(option) unless axis-aligned.
struct Gravity {
    int axis = 1;
    double sign = -1.0;
    Vec3 vector() const {
        Vec3 g;
        g[axis] = sign;
        return g;
    }
};
Gravity resolve_gravity(const Vec3& gravity, int dimension);

// The boundary sides of constrained selection beyond the floor (DetOptions::boundary_sides).
struct BoundarySides {
    std::vector<DetOptions::BoundarySide> sides;
    double distance = 0.0;
};

// Per element of `data`, its boundary class in `domain`: bit 0 (value 1) = a floor element
// (its elevation is held), bit 1 + s = it touches chosen side s. Elements of different
// classes never copy one another (constrained selection); 0 = an interior element.
std::vector<char> floor_elements(const Exemplar& data, const Domain& domain, const Gravity& gravity,
                                 double floor_distance, const BoundarySides& boundary = {});
inline constexpr char floor_bit = 1;

// Elevation of an element: its lowest sample's coordinate along gravity's axis
// (lowest in the direction gravity points).
double element_elevation(const Exemplar& data, const Element& e, const Gravity& gravity);
// That lowest sample's position.
Vec3 lowest_sample(const Exemplar& data, const Element& e, const Gravity& gravity);

// How far below p (along gravity) the domain ends, found to 1e-6 of `reach` by stepping and
// bisection; infinity when it does not end within `reach` (no floor near), 0 outside.
double height_above_floor(const Domain& domain, const Vec3& p, const Gravity& gravity, double reach);

}  // namespace tessera::det
