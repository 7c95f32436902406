// core/domain_box.cpp — Domain's public methods: the box kind answered here
// directly (exact formulas), every other kind forwarded to its DomainShape in the
// shape's own coordinates (Domain::scaled keeps the shape and scales about the
// lower corner of its bounds, so a 128^3 mesh grid is never rebuilt by --scale).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/domain_shape.hpp"
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

Domain Domain::from_shape(std::shared_ptr<const DomainShape> shape, Kind kind) {
    Domain d;
    d.kind_ = kind;
    d.dimension_ = shape->dimension;
    d.bounds_ = shape->bounds;
    d.origin_ = shape->bounds.lo;
    d.shape_ = std::move(shape);
    return d;
}

bool Domain::shaped_inside(const Vec3& p) const { return shape_->inside(to_shape(p)); }

double Domain::shaped_occupancy(const Vec3& p) const { return shape_->occupancy(to_shape(p)); }

double Domain::measure() const {
    if (kind_ != Kind::box) return shape_->measure() * std::pow(scale_, dimension_);
    double m = 1.0;
    for (int k = 0; k < dimension_; ++k) m *= bounds_.hi[k] - bounds_.lo[k];
    return m;
}

void Domain::prepare_overlap(int threads) const {
    if (kind_ != Kind::box) shape_->prepare_overlap(threads);
}

double Domain::translated_overlap(const Vec3& d) const {
    if (kind_ != Kind::box) return shape_->translated_overlap(d * (1.0 / scale_)) * std::pow(scale_, dimension_);
    double m = 1.0;
    for (int k = 0; k < dimension_; ++k) m *= std::max(0.0, (bounds_.hi[k] - bounds_.lo[k]) - std::abs(d[k]));
    return m;
}

Vec3 Domain::closest_inside(const Vec3& p) const {
    if (kind_ != Kind::box) {
        if (inside(p)) return p;
        return to_world(shape_->closest_inside(to_shape(p)));
    }
    Vec3 q = p;
    for (int k = 0; k < dimension_; ++k) q[k] = std::clamp(p[k], bounds_.lo[k], bounds_.hi[k]);
    return q;
}

double Domain::distance_to_boundary(const Vec3& p) const {
    if (kind_ != Kind::box) return shape_->distance_to_boundary(to_shape(p)) * scale_;
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
    if (kind_ != Kind::box) d.scale_ = scale_ * factor;  // about origin_ = the unscaled lower corner
    return d;
}

std::string Domain::describe() const {
    std::ostringstream s;
    if (kind_ != Kind::box) {
        s << shape_->describe();
        if (scale_ != 1.0) s << " scaled by " << scale_;
        return s.str();
    }
    s << "box ";
    for (int k = 0; k < dimension_; ++k) {
        if (k) s << "x";
        s << "[" << bounds_.lo[k] << "," << bounds_.hi[k] << "]";
    }
    return s.str();
}

std::string Domain::notes() const { return shape_ ? shape_->notes : std::string(); }

DomainSource Domain::source() const {
    if (!shape_) return {};
    DomainSource s = shape_->source;
    s.scale = scale_;
    s.origin = origin_;
    return s;
}

}  // namespace tessera
