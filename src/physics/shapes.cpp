// Element collision shapes and the segment-segment distance both physics passes use.
#include "physics/shapes.hpp"

#include <algorithm>
#include <cmath>

#include "tessera/det.hpp"
#include "tessera/physics.hpp"

namespace tessera {

double collision_radius(const Element& element, double spacing) {
    if (element.radius > 0) return element.radius;
    const double factor = element.sample_count > 1 ? 0.2 : 0.5;
    return std::max(factor * spacing, 1e-9);
}

namespace physics {

std::vector<ElementShape> element_shapes(const Exemplar& data) {
    const bool need_spacing = std::any_of(data.elements.begin(), data.elements.end(),
                                          [](const Element& e) { return e.radius <= 0; });
    const double spacing = need_spacing ? mean_nearest_neighbor_distance(data) : 0.0;
    std::vector<ElementShape> shapes(data.elements.size());
    for (std::size_t i = 0; i < data.elements.size(); ++i) {
        const Element& e = data.elements[i];
        ElementShape& s = shapes[i];
        s.first = e.first_sample;
        s.count = e.sample_count;
        s.radius = collision_radius(e, spacing);
        Vec3 sum, lo = data.samples[s.first].p, hi = lo;
        for (int k = 0; k < s.count; ++k) {
            const Vec3& p = data.samples[s.first + k].p;
            sum += p;
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], p[a]);
                hi[a] = std::max(hi[a], p[a]);
            }
        }
        s.centroid = sum / s.count;
        const Vec3 r{s.radius, s.radius, s.radius};
        s.lo = lo - r;
        s.hi = hi + r;
    }
    return shapes;
}

// Ericson, Real-Time Collision Detection, 5.1.9 (ClosestPtSegmentSegment).
double closest_points_segments(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1, Vec3& on_p,
                               Vec3& on_q) {
    const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
    const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
    constexpr double eps = 1e-24;
    double s = 0, t = 0;
    if (a <= eps && e <= eps) {
        // both points
    } else if (a <= eps) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = dot(d1, r);
        if (e <= eps) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = dot(d1, d2), denom = a * e - b * b;
            s = denom > eps ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0) {
                t = 0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (t > 1) {
                t = 1;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    on_p = p0 + d1 * s;
    on_q = q0 + d2 * t;
    return squared_norm(on_p - on_q);
}

Vec3 gravity_direction(const Vec3& gravity, int dimension) {
    Vec3 g = gravity;
    if (dimension == 2) g.z = 0;
    const double n = norm(g);
    if (!(n > 1e-12) || !std::isfinite(n)) return dimension == 2 ? Vec3{0, -1, 0} : Vec3{0, 0, -1};
    return g / n;
}

}  // namespace physics
}  // namespace tessera
