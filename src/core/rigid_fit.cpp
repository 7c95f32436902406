// Kabsch best-fit rotation: keeps rigid elements exact copies of input elements
// (det) and poses element meshes on their samples (geometry). Weights and the hint
// serve the deformable meshes: per-sample frames are fits of Gaussian-weighted
// neighbourhoods, and a straight reference polyline leaves each fit's twist free.
#include "core/rigid_fit.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace tessera::core {

Quat rotation_between(const Vec3& from, const Vec3& to) {
    const Vec3 a = from / norm(from), b = to / norm(to);
    const double c = dot(a, b);
    if (c < -1.0 + 1e-12) {
        // Half a turn about the axis perpendicular to `a` that is best conditioned.
        int least = 0;
        for (int k = 1; k < 3; ++k)
            if (std::abs(a[k]) < std::abs(a[least])) least = k;
        Vec3 other;
        other[least] = 1.0;
        Vec3 axis = cross(a, other);
        axis = axis / norm(axis);
        return {0.0, axis.x, axis.y, axis.z};
    }
    // q = (1 + c, a x b) normalised is the half-angle form of the rotation a -> b.
    const Vec3 v = cross(a, b);
    Quat q{1.0 + c, v.x, v.y, v.z};
    const double len = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    return {q.w / len, q.x / len, q.y / len, q.z / len};
}

void best_rigid_fit(const Vec3* a, const Vec3* b, int n, int dimension, Quat& rotation, Vec3& translation,
                    const double* weights, const Quat* hint) {
    Vec3 ca, cb;
    double total = 0.0;
    for (int k = 0; k < n; ++k) {
        const double w = weights ? weights[k] : 1.0;
        ca += a[k] * w, cb += b[k] * w, total += w;
    }
    ca = ca / total;
    cb = cb / total;
    const Quat fallback = hint ? *hint : Quat{};
    if (dimension == 2) {
        // Closed form in 2D: angle = atan2(sum cross, sum dot) of centred pairs.
        double sdot = 0.0, scross = 0.0;
        for (int k = 0; k < n; ++k) {
            const double w = weights ? weights[k] : 1.0;
            const Vec3 u = a[k] - ca, v = b[k] - cb;
            sdot += w * (u.x * v.x + u.y * v.y);
            scross += w * (u.x * v.y - u.y * v.x);
        }
        rotation = (sdot == 0.0 && scross == 0.0) ? fallback : Quat::from_angle_z(std::atan2(scross, sdot));
    } else {
        Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
        for (int k = 0; k < n; ++k) {
            const double w = weights ? weights[k] : 1.0;
            const Vec3 u = a[k] - ca, v = b[k] - cb;
            h += w * Eigen::Vector3d(u.x, u.y, u.z) * Eigen::Vector3d(v.x, v.y, v.z).transpose();
        }
        Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
        const Eigen::Vector3d s = svd.singularValues();
        if (hint && s(1) <= 1e-10 * s(0)) {
            // Rank <= 1: only the direction U0 -> V0 is fixed (or nothing, if s0 = 0).
            if (s(0) <= 0.0) {
                rotation = *hint;
            } else {
                const Eigen::Vector3d u0 = svd.matrixU().col(0), v0 = svd.matrixV().col(0);
                rotation = rotation_between(hint->rotate({u0.x(), u0.y(), u0.z()}), {v0.x(), v0.y(), v0.z()}) * *hint;
            }
        } else {
            Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
            if ((svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0) d(2, 2) = -1.0;
            const Eigen::Matrix3d r = svd.matrixV() * d * svd.matrixU().transpose();
            Eigen::Quaterniond q(r);
            q.normalize();
            if (q.w() < 0) q.coeffs() *= -1.0;
            rotation = Quat{q.w(), q.x(), q.y(), q.z()};
        }
    }
    translation = cb - rotation.rotate(ca);
}

}  // namespace tessera::core
