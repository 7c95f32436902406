#include "det/floor.hpp"

#include <cmath>

#include "tessera/error.hpp"

namespace tessera::det {

Gravity resolve_gravity(const Vec3& gravity, int dimension) {
    Gravity g;
    int nonzero = 0;
    for (int k = 0; k < 3; ++k) {
        if (!std::isfinite(gravity[k])) throw Error(ErrorKind::option, "--gravity must be finite");
        if (gravity[k] != 0.0) {
            ++nonzero;
            g.axis = k;
            g.sign = gravity[k] > 0.0 ? 1.0 : -1.0;
        }
    }
    if (nonzero != 1 || g.axis >= dimension)
        throw Error(ErrorKind::option, std::string("--gravity must point along one axis of the ") +
                                           (dimension == 2 ? "2D (x, y)" : "3D (x, y, z)") + " data, e.g. " +
                                           (dimension == 2 ? "-y" : "-z"));
    return g;
}

Vec3 lowest_sample(const Exemplar& data, const Element& e, const Gravity& gravity) {
    // The sample farthest along gravity is the lowest.
    Vec3 lowest = data.samples[e.first_sample].p;
    for (int s = 1; s < e.sample_count; ++s) {
        const Vec3& p = data.samples[e.first_sample + s].p;
        if (p[gravity.axis] * gravity.sign > lowest[gravity.axis] * gravity.sign) lowest = p;
    }
    return lowest;
}

double element_elevation(const Exemplar& data, const Element& e, const Gravity& gravity) {
    return lowest_sample(data, e, gravity)[gravity.axis];
}

double height_above_floor(const Domain& domain, const Vec3& p, const Gravity& gravity, double reach) {
    if (!domain.inside(p)) return 0.0;
    constexpr int kSteps = 64, kBisections = 20;
    const Vec3 down = gravity.vector();
    const double step = reach / kSteps;
    for (int k = 1; k <= kSteps; ++k) {
        if (domain.inside(p + down * (k * step))) continue;
        double in = (k - 1) * step, out = k * step;  // the boundary lies between
        for (int b = 0; b < kBisections; ++b) {
            const double mid = 0.5 * (in + out);
            (domain.inside(p + down * mid) ? in : out) = mid;
        }
        return 0.5 * (in + out);
    }
    return INFINITY;
}

std::vector<char> floor_elements(const Exemplar& data, const Domain& domain, const Gravity& gravity,
                                 double floor_distance, const BoundarySides& boundary) {
    std::vector<char> code(data.elements.size(), 0);
    const Vec3 step = gravity.vector() * floor_distance;
    for (size_t i = 0; i < data.elements.size(); ++i) {
        const Element& e = data.elements[i];
        bool floor = data.types[e.type].floor;
        for (int s = 0; s < e.sample_count && !floor && floor_distance > 0.0; ++s)
            floor = !domain.inside(data.samples[e.first_sample + s].p + step);
        char c = floor ? floor_bit : 0;
        if (boundary.distance > 0.0) {
            for (size_t side = 0; side < boundary.sides.size(); ++side) {
                Vec3 probe;
                probe[boundary.sides[side].axis] = boundary.sides[side].sign * boundary.distance;
                bool touches = false;
                for (int s = 0; s < e.sample_count && !touches; ++s)
                    touches = !domain.inside(data.samples[e.first_sample + s].p + probe);
                if (touches) c = static_cast<char>(c | (2 << side));
            }
        }
        code[i] = c;
    }
    return code;
}

}  // namespace tessera::det
