// core/rigid_fit.hpp — best-fit rigid motion between two point lists (Kabsch), shared
// by synthesis (rigid elements stay exact copies of input elements) and by element
// geometry (posing a type's mesh on an element's samples, and the per-sample frames
// of deformable meshes).
#pragma once

#include "tessera/vec.hpp"

namespace tessera::core {

// Best rigid motion (rotation R, translation t) minimising sum w_k |R a_k + t - b_k|^2
// (Kabsch; no reflections; rotation about z only when dimension == 2). `weights`
// (n values >= 0, not all 0) default to 1.
//
// When the points do not fix the rotation (3D, all a_k or all b_k on one line, or all
// coinciding), a plain SVD returns an arbitrary twist about that line. With `hint`,
// the result is instead the rotation closest to *hint among the best fits (for points
// on a line: the line's direction is turned onto the target's by the smallest
// rotation after applying *hint), so frames stay continuous from one fit to the next.
void best_rigid_fit(const Vec3* a, const Vec3* b, int n, int dimension, Quat& rotation, Vec3& translation,
                    const double* weights = nullptr, const Quat* hint = nullptr);

// The smallest rotation turning direction `from` onto direction `to` (any lengths > 0);
// opposite directions turn by half a turn about an axis perpendicular to `from`.
Quat rotation_between(const Vec3& from, const Vec3& to);

}  // namespace tessera::core
