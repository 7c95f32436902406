// geometry/rigid_pose.cpp — the pose of a rigid element's mesh: the type's reference
// layout fitted onto the element's samples (Kabsch). Rigid elements are exact copies
// of input elements, so the fit is exact up to rounding and fit_error says so.
#include <algorithm>
#include <cmath>

#include "core/rigid_fit.hpp"
#include "geometry/geometry_internal.hpp"

namespace tessera::geometry {

namespace {

double rms_error(const std::vector<Vec3>& local, const Vec3* samples, const Quat& r, const Vec3& t) {
    double sum = 0.0;
    for (size_t k = 0; k < local.size(); ++k) sum += squared_norm(r.rotate(local[k]) + t - samples[k]);
    return std::sqrt(sum / static_cast<double>(local.size()));
}

}  // namespace

Pose fit_rigid_pose(const std::vector<Vec3>& reference, const Vec3* samples, const Element& element,
                    int dimension) {
    const int n = static_cast<int>(reference.size());
    Pose pose;
    pose.scale = element.scale;
    std::vector<Vec3> local(reference.size());
    Vec3 local_centroid, centroid;
    double extent = 0.0;
    for (int k = 0; k < n; ++k) {
        local[k] = reference[k] * element.scale;
        local_centroid += local[k];
        centroid += samples[k];
    }
    local_centroid = local_centroid / n;
    centroid = centroid / n;
    for (int k = 0; k < n; ++k) extent = std::max(extent, norm(local[k] - local_centroid));

    // The element's own orientation, placed by the centroids...
    const Quat own = element.orientation;
    const Vec3 own_t = centroid - own.rotate(local_centroid);
    const double own_error = rms_error(local, samples, own, own_t);
    // ...against the best fit; the twist a line of samples leaves free comes from `own`.
    Quat fit;
    Vec3 fit_t;
    core::best_rigid_fit(local.data(), samples, n, dimension, fit, fit_t, nullptr, &own);
    const double fit_error = rms_error(local, samples, fit, fit_t);
    // Keep the element's pose when it is as good up to rounding: consistent data then
    // get their own pose back bit for bit.
    if (own_error <= fit_error + 1e-9 * extent) {
        pose.orientation = own;
        pose.position = own_t;
        pose.fit_error = own_error;
    } else {
        pose.orientation = fit;
        pose.position = fit_t;
        pose.fit_error = fit_error;
    }
    return pose;
}

}  // namespace tessera::geometry
