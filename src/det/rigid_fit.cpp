// Kabsch best-fit rotation, used to keep rigid elements exact copies of input elements.
#include <Eigen/Dense>
#include <cmath>

#include "det/assign.hpp"

namespace tessera::det {

void best_rigid_fit(const Vec3* a, const Vec3* b, int n, int dimension, Quat& rotation, Vec3& translation) {
    Vec3 ca, cb;
    for (int k = 0; k < n; ++k) ca += a[k], cb += b[k];
    ca = ca / n;
    cb = cb / n;
    if (dimension == 2) {
        // Closed form in 2D: angle = atan2(sum cross, sum dot) of centred pairs.
        double sdot = 0.0, scross = 0.0;
        for (int k = 0; k < n; ++k) {
            const Vec3 u = a[k] - ca, v = b[k] - cb;
            sdot += u.x * v.x + u.y * v.y;
            scross += u.x * v.y - u.y * v.x;
        }
        rotation = (sdot == 0.0 && scross == 0.0) ? Quat{} : Quat::from_angle_z(std::atan2(scross, sdot));
    } else {
        Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
        for (int k = 0; k < n; ++k) {
            const Vec3 u = a[k] - ca, v = b[k] - cb;
            h += Eigen::Vector3d(u.x, u.y, u.z) * Eigen::Vector3d(v.x, v.y, v.z).transpose();
        }
        Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
        Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
        if ((svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0) d(2, 2) = -1.0;
        const Eigen::Matrix3d r = svd.matrixV() * d * svd.matrixU().transpose();
        Eigen::Quaterniond q(r);
        q.normalize();
        if (q.w() < 0) q.coeffs() *= -1.0;
        rotation = Quat{q.w(), q.x(), q.y(), q.z()};
    }
    translation = cb - rotation.rotate(ca);
}

}  // namespace tessera::det
