// The least-squares position assignment (Eq. 4) and the rigid fit.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.hpp"
#include "det/assign.hpp"

using namespace tessera;
using namespace tessera::det;

TEST(DetAssign, LeastSquaresRecoversAnArrangementFromExactPredictions) {
    // Truth: a jittered grid. Start: the truth plus large noise. Predictions: the
    // true offsets between every pair closer than 2.5. One solve must recover the
    // truth up to a common translation.
    const core::KeyedRng rng(3, core::Purpose::test);
    OutputState state;
    Arrangement& a = state.arrangement;
    std::vector<Vec3> truth;
    for (int j = 0; j < 12; ++j)
        for (int i = 0; i < 12; ++i) {
            const std::uint64_t c = 4 * (j * 12 + i);
            truth.push_back({i + 0.2 * rng.uniform(c), j + 0.2 * rng.uniform(c + 1), 0});
            a.add_element(0, {truth.back() + Vec3{rng.uniform(c + 2) - 0.5, rng.uniform(c + 3) - 0.5, 0}});
        }
    a.types.push_back(ElementType{});
    const int n = static_cast<int>(truth.size());
    state.pairs.resize(n);
    for (int c = 0; c < n; ++c)
        for (int o = 0; o < n; ++o)
            if (o != c && norm(truth[o] - truth[c]) < 2.5) state.pairs[c].push_back(Pair{o, 0, truth[o] - truth[c]});
    Params params;
    params.dimension = 2;
    params.anchor_weight = 1e-9;  // no damping: the solve alone must be exact
    params.cg_tolerance = 1e-12;
    const AssignReport report = assign_positions(state, params, 2);
    EXPECT_TRUE(report.cg_converged);
    Vec3 shift;
    for (int i = 0; i < n; ++i) shift += a.samples[i].p - truth[i];
    shift = shift / n;
    double worst = 0.0;
    for (int i = 0; i < n; ++i) worst = std::max(worst, norm(a.samples[i].p - truth[i] - shift));
    EXPECT_LT(worst, 1e-5);
}

TEST(DetAssign, RigidFitRecoversRotationAndTranslation3D) {
    const Quat q = Quat{0.9, 0.1, -0.3, 0.2};
    const double len = std::sqrt(0.81 + 0.01 + 0.09 + 0.04);
    const Quat r{q.w / len, q.x / len, q.y / len, q.z / len};
    const Vec3 t{1, -2, 3};
    std::vector<Vec3> a = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 0, 3}, {1, 1, 1}};
    std::vector<Vec3> b;
    for (const auto& p : a) b.push_back(r.rotate(p) + t);
    Quat fit;
    Vec3 shift;
    best_rigid_fit(a.data(), b.data(), 5, 3, fit, shift);
    for (size_t k = 0; k < a.size(); ++k) EXPECT_LT(norm(fit.rotate(a[k]) + shift - b[k]), 1e-9);
}

TEST(DetAssign, RigidFitIn2DIsARotationAboutZ) {
    const Quat r = Quat::from_angle_z(2.0);
    std::vector<Vec3> a = {{0, 0, 0}, {1, 0, 0}, {2, 0.5, 0}};
    std::vector<Vec3> b;
    for (const auto& p : a) b.push_back(r.rotate(p) + Vec3{5, 5, 0});
    Quat fit;
    Vec3 shift;
    best_rigid_fit(a.data(), b.data(), 3, 2, fit, shift);
    EXPECT_NEAR(fit.angle_z(), 2.0, 1e-12);
    EXPECT_NEAR(shift.z, 0.0, 1e-12);
}
