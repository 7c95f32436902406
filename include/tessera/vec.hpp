// tessera/vec.hpp — the small value types every part of tessera shares:
// a 3-vector (2D data keeps z = 0) and a unit quaternion stored (w, x, y, z).
// They are plain structs so that hot loops stay allocation-free and inlinable,
// and so that the Python module can hand them to numpy without conversion.
#pragma once

#include <cmath>

namespace tessera {

struct Vec3 {
    double x = 0.0, y = 0.0, z = 0.0;

    constexpr Vec3() = default;
    constexpr Vec3(double x_, double y_, double z_ = 0.0) : x(x_), y(y_), z(z_) {}

    constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

    constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
    constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
    constexpr Vec3 operator-() const { return {-x, -y, -z}; }
    constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
    constexpr Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }
    constexpr Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
    constexpr Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
    constexpr Vec3& operator*=(double s) { x *= s; y *= s; z *= s; return *this; }
    constexpr bool operator==(const Vec3& o) const = default;
};

constexpr Vec3 operator*(double s, const Vec3& v) { return v * s; }
constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
constexpr double squared_norm(const Vec3& v) { return dot(v, v); }
inline double norm(const Vec3& v) { return std::sqrt(dot(v, v)); }
inline bool is_finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Unit quaternion, stored (w, x, y, z) as DESIGN.md fixes; writers reorder for their formats.
struct Quat {
    double w = 1.0, x = 0.0, y = 0.0, z = 0.0;
    constexpr bool operator==(const Quat& o) const = default;

    // Rotation by `angle` radians about the +z axis (the 2D case).
    static Quat from_angle_z(double angle) {
        return {std::cos(0.5 * angle), 0.0, 0.0, std::sin(0.5 * angle)};
    }
    // Angle about +z of a rotation that is (close to) a pure z rotation.
    double angle_z() const { return 2.0 * std::atan2(z, w); }

    Vec3 rotate(const Vec3& v) const {
        // v' = v + 2 u x (u x v + w v), with u = (x, y, z)
        const Vec3 u{x, y, z};
        const Vec3 t = cross(u, v) * 2.0;
        return v + t * w + cross(u, t);
    }
    Quat conjugate() const { return {w, -x, -y, -z}; }
    Quat operator*(const Quat& q) const {
        return {w * q.w - x * q.x - y * q.y - z * q.z, w * q.x + x * q.w + y * q.z - z * q.y,
                w * q.y - x * q.z + y * q.w + z * q.x, w * q.z + x * q.y - y * q.x + z * q.w};
    }
};

}  // namespace tessera
