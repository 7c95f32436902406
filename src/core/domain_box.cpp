// Domain: the box shape. Later shapes (polygon, mask, mesh, shell) extend Kind.
#include "tessera/domain.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "tessera/error.hpp"

namespace tessera {

Domain Domain::box(const Vec3& lo, const Vec3& hi, int dimension) {
    if (dimension != 2 && dimension != 3)
        throw Error(ErrorKind::domain, "domain dimension must be 2 or 3, got " + std::to_string(dimension));
    for (int k = 0; k < dimension; ++k) {
        if (!std::isfinite(lo[k]) || !std::isfinite(hi[k]))
            throw Error(ErrorKind::domain, "domain bounds must be finite numbers");
        if (!(hi[k] > lo[k])) {
            std::ostringstream s;
            s << "domain extent along " << "xyz"[k] << " must be > 0 (got " << lo[k] << " to " << hi[k] << ")";
            throw Error(ErrorKind::domain, s.str());
        }
    }
    Domain d;
    d.kind_ = Kind::box;
    d.dimension_ = dimension;
    d.bounds_ = {lo, hi};
    if (dimension == 2) d.bounds_.lo.z = d.bounds_.hi.z = 0.0;
    return d;
}

double Domain::measure() const {
    double m = 1.0;
    for (int k = 0; k < dimension_; ++k) m *= bounds_.hi[k] - bounds_.lo[k];
    return m;
}

double Domain::translated_overlap(const Vec3& d) const {
    double m = 1.0;
    for (int k = 0; k < dimension_; ++k) m *= std::max(0.0, (bounds_.hi[k] - bounds_.lo[k]) - std::abs(d[k]));
    return m;
}

Vec3 Domain::closest_inside(const Vec3& p) const {
    Vec3 q = p;
    for (int k = 0; k < dimension_; ++k) q[k] = std::clamp(p[k], bounds_.lo[k], bounds_.hi[k]);
    return q;
}

double Domain::distance_to_boundary(const Vec3& p) const {
    double dist = INFINITY;
    for (int k = 0; k < dimension_; ++k)
        dist = std::min({dist, p[k] - bounds_.lo[k], bounds_.hi[k] - p[k]});
    return dist;
}

Domain Domain::scaled(double factor) const {
    if (!(factor > 0.0) || !std::isfinite(factor))
        throw Error(ErrorKind::option, "--scale must be a finite number > 0");
    Domain d = *this;
    d.bounds_.hi = bounds_.lo + (bounds_.hi - bounds_.lo) * factor;
    return d;
}

std::string Domain::describe() const {
    std::ostringstream s;
    s << "box ";
    for (int k = 0; k < dimension_; ++k) {
        if (k) s << "x";
        s << "[" << bounds_.lo[k] << "," << bounds_.hi[k] << "]";
    }
    return s.str();
}

}  // namespace tessera
