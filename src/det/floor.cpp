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

double element_elevation(const Exemplar& data, const Element& e, const Gravity& gravity) {
    // The sample farthest along gravity is the lowest; its coordinate is the elevation.
    double lowest = data.samples[e.first_sample].p[gravity.axis];
    for (int s = 1; s < e.sample_count; ++s) {
        const double v = data.samples[e.first_sample + s].p[gravity.axis];
        if (v * gravity.sign > lowest * gravity.sign) lowest = v;
    }
    return lowest;
}

std::vector<char> floor_elements(const Exemplar& data, const Domain& domain, const Gravity& gravity,
                                 double floor_distance) {
    std::vector<char> floor(data.elements.size(), 0);
    const Vec3 step = gravity.vector() * floor_distance;
    for (size_t i = 0; i < data.elements.size(); ++i) {
        const Element& e = data.elements[i];
        if (data.types[e.type].floor) {
            floor[i] = 1;
            continue;
        }
        if (floor_distance <= 0.0) continue;
        for (int s = 0; s < e.sample_count && !floor[i]; ++s)
            floor[i] = !domain.inside(data.samples[e.first_sample + s].p + step);
    }
    return floor;
}

}  // namespace tessera::det
