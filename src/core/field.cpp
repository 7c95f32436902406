// Procedural orientation fields, the dispatch to file-based ones (field_grid.cpp,
// field_mesh.cpp) and the frame of a direction (Eq. 7).
#include "tessera/field.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/field_data.hpp"
#include "tessera/error.hpp"

namespace tessera {

namespace {

constexpr double degenerate = field_detail::degenerate_norm;

Vec3 unit_or_throw(const Vec3& v, const std::string& what) {
    const double n = norm(v);
    if (!is_finite(v) || !(n > degenerate)) throw Error(ErrorKind::option, what + " must be a finite, non-zero vector");
    return v / n;
}

}  // namespace

OrientationField OrientationField::constant(const Vec3& direction) {
    OrientationField f;
    f.kind_ = Kind::constant;
    f.vector_ = unit_or_throw(direction, "the field direction");
    return f;
}

OrientationField OrientationField::radial(const Vec3& center, const Vec3& axis) {
    if (!is_finite(center)) throw Error(ErrorKind::option, "the field centre must be finite");
    OrientationField f;
    f.kind_ = Kind::radial;
    f.vector_ = center;
    f.axis_ = unit_or_throw(axis, "the field axis");
    return f;
}

OrientationField OrientationField::vortex(const Vec3& center, const Vec3& axis) {
    OrientationField f = radial(center, axis);
    f.kind_ = Kind::vortex;
    return f;
}

OrientationField OrientationField::polyline(const std::vector<Vec3>& points) {
    if (points.size() < 2) throw Error(ErrorKind::option, "a polyline field needs at least 2 points");
    for (size_t k = 0; k < points.size(); ++k) {
        if (!is_finite(points[k])) throw Error(ErrorKind::option, "a polyline field's points must be finite");
        if (k > 0 && !(norm(points[k] - points[k - 1]) > degenerate))
            throw Error(ErrorKind::option, "a polyline field has a zero-length segment at point " + std::to_string(k));
    }
    OrientationField f;
    f.kind_ = Kind::polyline;
    f.points_ = std::make_shared<const std::vector<Vec3>>(points);
    return f;
}

OrientationField OrientationField::trefoil(const Vec3& center, double scale, int samples) {
    if (!(scale > 0.0) || !std::isfinite(scale)) throw Error(ErrorKind::option, "the trefoil's scale must be > 0");
    std::vector<Vec3> points;
    for (int k = 0; k <= std::max(samples, 12); ++k) {
        const double t = 2.0 * M_PI * k / std::max(samples, 12);
        points.push_back(center + Vec3{std::sin(t) + 2 * std::sin(2 * t), std::cos(t) - 2 * std::cos(2 * t),
                                       -std::sin(3 * t)} *
                                      scale);
    }
    return polyline(points);
}

OrientationField OrientationField::parse(const std::string& text, int dimension, const std::string& parameter) {
    const size_t colon = text.find(':');
    const std::string kind = text.substr(0, colon);
    if (kind == "grid" || kind == "mesh") {
        // The rest is a path, taken verbatim (it may hold commas or colons).
        const std::string path = colon == std::string::npos ? std::string() : text.substr(colon + 1);
        if (path.empty())
            throw Error(ErrorKind::option, parameter + ": expected " + kind + ":FILE" +
                                               (kind == "grid" ? ".json" : ".ply or " + kind + ":FILE.obj"));
        if (kind == "mesh" && dimension != 3)
            throw Error(ErrorKind::option, parameter + ": " + path + ": a mesh field is 3D but the exemplar is " +
                                               std::to_string(dimension) + "D");
        try {
            if (kind == "mesh") return mesh_file(path);
            OrientationField f = grid_file(path);
            if (f.data_dimension() != dimension)
                throw Error(ErrorKind::input, path + ": dimension: the field is " +
                                                  std::to_string(f.data_dimension()) + "D but the exemplar is " +
                                                  std::to_string(dimension) + "D");
            return f;
        } catch (const Error& e) {
            throw Error(e.kind(), parameter + ": " + e.what());
        }
    }
    std::vector<double> v;
    if (colon != std::string::npos) {
        std::stringstream in(text.substr(colon + 1));
        std::string field;
        while (std::getline(in, field, ',')) {
            char* end = nullptr;
            const double x = std::strtod(field.c_str(), &end);
            if (field.empty() || *end != '\0')
                throw Error(ErrorKind::option, parameter + ": '" + field + "' is not a number in '" + text + "'");
            v.push_back(x);
        }
    }
    try {
        if (kind == "polyline") {
            if (v.size() < 2u * dimension || v.size() % dimension != 0)
                throw Error(ErrorKind::option, "a polyline needs at least 2 points of " + std::to_string(dimension) +
                                                   " numbers each");
            std::vector<Vec3> points;
            for (size_t k = 0; k < v.size(); k += dimension)
                points.push_back({v[k], v[k + 1], dimension == 3 ? v[k + 2] : 0.0});
            return polyline(points);
        }
        if (kind == "trefoil") {
            if (dimension != 3 || v.size() != 4) throw Error(ErrorKind::option, "expected trefoil:cx,cy,cz,scale (3D)");
            return trefoil({v[0], v[1], v[2]}, v[3]);
        }
    } catch (const Error& e) {
        throw Error(ErrorKind::option, parameter + ": " + e.what());
    }
    if (v.size() != static_cast<size_t>(dimension))
        throw Error(ErrorKind::option, parameter + ": expected constant|radial|vortex:" +
                                           (dimension == 2 ? "x,y" : "x,y,z") + ", got '" + text + "'");
    const Vec3 p{v[0], v[1], dimension == 3 ? v[2] : 0.0};
    try {
        if (kind == "constant") return constant(p);
        if (kind == "radial") return radial(p);
        if (kind == "vortex") return vortex(p);
    } catch (const Error& e) {
        throw Error(ErrorKind::option, parameter + ": " + e.what());
    }
    throw Error(ErrorKind::option, parameter + ": unknown field '" + kind +
                                       "' (constant, radial, vortex, polyline, trefoil, grid or mesh)");
}

Vec3 OrientationField::direction(const Vec3& p) const {
    switch (kind_) {
        case Kind::none: return {1, 0, 0};
        case Kind::constant: return vector_;
        case Kind::radial:
        case Kind::vortex: {
            Vec3 r = p - vector_;
            r -= axis_ * dot(r, axis_);  // distance from the axis
            const double n = norm(r);
            if (!(n > degenerate)) return {};
            r = r / n;
            return kind_ == Kind::radial ? r : cross(axis_, r);
        }
        case Kind::polyline: {
            // Tangent of the nearest segment (a linear scan: fields are evaluated once per
            // sample per iteration and curves typed by users are short).
            double best = INFINITY;
            Vec3 tangent{1, 0, 0};
            const std::vector<Vec3>& points = *points_;
            for (size_t k = 0; k + 1 < points.size(); ++k) {
                const Vec3 a = points[k], ab = points[k + 1] - a;
                const double t = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
                const double d = squared_norm(a + ab * t - p);
                if (d < best) best = d, tangent = ab / norm(ab);
            }
            return tangent;
        }
        case Kind::grid: return field_detail::grid_direction(*grid_, p);
        case Kind::mesh: return field_detail::mesh_direction(*mesh_, p);
    }
    return {1, 0, 0};
}

namespace {

Quat quat_from_axes(const Vec3& x, const Vec3& y, const Vec3& z) {
    Eigen::Matrix3d m;
    m << x.x, y.x, z.x, x.y, y.y, z.y, x.z, y.z, z.z;
    Eigen::Quaterniond q(m);
    q.normalize();
    if (q.w() < 0) q.coeffs() *= -1.0;
    return Quat{q.w(), q.x(), q.y(), q.z()};
}

}  // namespace

Quat frame_from_direction(const Vec3& d, int dimension) {
    if (!(norm(d) > degenerate)) return Quat{};
    if (dimension == 2) return Quat::from_angle_z(std::atan2(d.y, d.x));
    // Local axes: x = d; y perpendicular to x and to +z (horizontal) where possible; z = x cross y.
    const Vec3 x = d / norm(d);
    Vec3 y = cross(Vec3{0, 0, 1}, x);
    if (norm(y) < 1e-9) y = cross(x, Vec3{1, 0, 0}).y < 0 ? Vec3{0, -1, 0} : Vec3{0, 1, 0};
    y = y / norm(y);
    const Vec3 z = cross(x, y);
    return quat_from_axes(x, y, z);
}

Quat frame_from_direction(const Vec3& d, const Vec3& normal) {
    if (!(norm(normal) > degenerate) || !is_finite(normal)) return frame_from_direction(d, 3);
    const Vec3 z = normal / norm(normal);
    Vec3 x = is_finite(d) ? d - z * dot(d, z) : Vec3{};
    if (!(norm(d) > degenerate) || !(norm(x) > 1e-9 * norm(d))) {
        // No usable direction: +x turned by the least rotation taking +z onto the normal
        // (Rodrigues: v' = v cos a + (k x v) sin a + k (k.v)(1 - cos a), k sin a = +z x n,
        // cos a = n.z). For n = +z that is the identity; for n = -z, a half turn about +x.
        const Vec3 ex{1, 0, 0};
        const Vec3 axis = cross(Vec3{0, 0, 1}, z);
        const double sin_a = norm(axis);
        x = ex;
        if (sin_a > 1e-12) {
            const Vec3 k = axis / sin_a;
            x = ex * z.z + cross(k, ex) * sin_a + k * (dot(k, ex) * (1 - z.z));
        }
    }
    x = x / norm(x);
    return quat_from_axes(x, cross(z, x), z);
}

Quat OrientationField::frame(const Vec3& p, int dimension) const {
    if (kind_ == Kind::none) return Quat{};
    if (kind_ == Kind::mesh) return field_detail::mesh_frame(*mesh_, p, dimension);
    return frame_from_direction(direction(p), dimension);
}

int OrientationField::data_dimension() const {
    if (kind_ == Kind::grid) return field_detail::grid_dimension(*grid_);
    if (kind_ == Kind::mesh) return 3;
    return 0;
}

std::string OrientationField::describe() const {
    std::ostringstream s;
    switch (kind_) {
        case Kind::none: return "none";
        case Kind::constant: s << "constant (" << vector_.x << "," << vector_.y << "," << vector_.z << ")"; break;
        case Kind::radial: s << "radial about (" << vector_.x << "," << vector_.y << "," << vector_.z << ")"; break;
        case Kind::vortex: s << "vortex about (" << vector_.x << "," << vector_.y << "," << vector_.z << ")"; break;
        case Kind::polyline: s << "polyline of " << points_->size() << " points"; break;
        case Kind::grid: return field_detail::grid_describe(*grid_);
        case Kind::mesh: return field_detail::mesh_describe(*mesh_);
    }
    return s.str();
}

}  // namespace tessera
