// geometry/deform.cpp — the mesh of a deformable element (spaghetti, bags) follows its
// samples smoothly. Each sample gets the rigid motion that best fits its Gaussian-
// weighted neighbourhood of samples (reference -> output: rotation and weighted-centroid
// translation), and a vertex moves with the blend of those motions, weighted by a
// Gaussian of its distance to the reference samples (linear blend skinning).
//
// Fitting the motions with the same Gaussian that blends them matters: the chord error
// of extrapolating one sample's motion along a bent curve cancels, to first order,
// against the inward shift of the neighbourhood centroids, so a tube bent onto an arc
// keeps its radius (tests/geometry/test_deform.cpp) instead of drifting outward. Small
// per-sample corrections then make the blend pass through the samples themselves,
// which the one-sided neighbourhoods at an element's ends would otherwise miss.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/rigid_fit.hpp"
#include "geometry/geometry_internal.hpp"

namespace tessera::geometry {

TriangleMesh deform_mesh(const TriangleMesh& mesh, const std::vector<Vec3>& reference, const Vec3* samples,
                         double scale, double falloff, int dimension, const Quat& orientation) {
    const int n = static_cast<int>(reference.size());
    std::vector<Vec3> local(n);
    for (int i = 0; i < n; ++i) local[i] = reference[i] * scale;
    double spacing = 0.0;
    for (int i = 0; i + 1 < n; ++i) spacing += norm(local[i + 1] - local[i]);
    if (n > 1) spacing /= (n - 1);

    // The whole element's best fit: the start of the frame chain, and the motion of
    // every vertex when the samples cannot tell a bend (one sample, or all coinciding).
    Quat global;
    Vec3 global_t;
    core::best_rigid_fit(local.data(), samples, n, dimension, global, global_t, nullptr, &orientation);
    TriangleMesh out;
    out.triangles = mesh.triangles;
    out.vertices.reserve(mesh.vertices.size());
    const double width = falloff * spacing;
    if (n < 2 || !(width > 0.0)) {
        for (const Vec3& v : mesh.vertices) out.vertices.push_back(global.rotate(v * scale) + global_t);
        return out;
    }
    const double inv_two_w2 = 1.0 / (2.0 * width * width);

    // Gaussian weights between the reference samples: they weight the fits and the blend
    // at the samples alike.
    std::vector<double> kernel(static_cast<size_t>(n) * n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) kernel[i * n + j] = std::exp(-squared_norm(local[j] - local[i]) * inv_two_w2);

    // Per-sample motions; each fit's free twist (straight reference) follows the previous frame.
    std::vector<Quat> rotation(n);
    std::vector<Vec3> shift(n);
    Quat hint = global;
    for (int i = 0; i < n; ++i) {
        core::best_rigid_fit(local.data(), samples, n, dimension, rotation[i], shift[i], &kernel[i * n], &hint);
        hint = rotation[i];
    }

    // At the ends of an element the neighbourhoods are one-sided and the first-order
    // cancellation fails (the end of a bent tube lands off the end sample by about 5% of
    // the spacing). Corrections, one translation per motion, make the blend pass through
    // the samples: each round adds the remaining miss at every sample to its motion. The
    // blend matrix is row-stochastic with a positive spectrum, so the misses only shrink
    // (and fast, for the smooth misses bending leaves).
    std::vector<Vec3> uncorrected(n), correction(n), miss(n);
    std::vector<double> row_total(n, 0.0);
    for (int k = 0; k < n; ++k) {
        for (int j = 0; j < n; ++j) {
            uncorrected[k] += (rotation[j].rotate(local[k]) + shift[j]) * kernel[k * n + j];
            row_total[k] += kernel[k * n + j];
        }
        uncorrected[k] = uncorrected[k] / row_total[k];
    }
    constexpr int rounds = 16;
    for (int round = 0; round < rounds; ++round) {
        double worst = 0.0;
        for (int k = 0; k < n; ++k) {
            Vec3 moved;
            for (int j = 0; j < n; ++j) moved += correction[j] * kernel[k * n + j];
            miss[k] = samples[k] - uncorrected[k] - moved / row_total[k];
            worst = std::max(worst, norm(miss[k]));
        }
        if (worst <= 1e-12 * spacing) break;
        for (int k = 0; k < n; ++k) correction[k] += miss[k];
    }

    // Every vertex: the blend of the corrected motions by its distances to the samples.
    std::vector<double> d2(n);
    const auto blend = [&](const Vec3& v) {
        double nearest = std::numeric_limits<double>::infinity();
        for (int i = 0; i < n; ++i) nearest = std::min(nearest, d2[i] = squared_norm(v - local[i]));
        // Relative to the nearest sample, so that far vertices still get weights (no 0/0).
        Vec3 sum;
        double total = 0.0;
        for (int i = 0; i < n; ++i) {
            const double w = std::exp(-(d2[i] - nearest) * inv_two_w2);
            sum += (rotation[i].rotate(v) + shift[i] + correction[i]) * w;
            total += w;
        }
        return sum / total;
    };
    for (const Vec3& vertex : mesh.vertices) out.vertices.push_back(blend(vertex * scale));
    return out;
}

}  // namespace tessera::geometry
