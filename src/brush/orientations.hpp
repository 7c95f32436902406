// brush/orientations.hpp — the element field: the orientations o(s) of the movable samples
// that minimise, by L-BFGS (LBFGSpp), the field alignment to the strokes (Eq. 5), the field
// continuity between nearby samples (Eq. 6) and the rigidity of each element (Eq. 7): the
// orientation terms of section 4. The distribution term (Eq. 1) acts through the search and
// the position solve, which see every element in the frame of its o(s). (Drawing o(s) toward
// the rotation that fits each sample's matched neighbourhood best was tried: those per-sample
// fits are noisy, and they undid the field's continuity.)
//
// Each o(s) is a unit vector u = v / |v| of free variables v (2 in 2D, 3 in 3D), and
// d(o, o') = |u - u'|^2 = 2 - 2 cos(angle). A rigid element has one variable for all of
// its samples, so its samples' orientations are identical exactly (w_r = infinity);
// a deformable element has one per sample, joined by Eq. 7 along its graph with w_rigidity.
#pragma once

#include <vector>

#include "brush/distribution.hpp"

namespace tessera::brush {

struct OrientationResult {
    double energy = 0.0;   // the objective at the end, per movable sample
    bool bound_hit = false;  // BrushOptions::lbfgs_iterations stopped it
};

OrientationResult solve_orientations(BrushCanvas::Impl& state, const std::vector<char>& movable);

// The terms of the element field at the current orientations, summed over all samples
// (alignment, continuity, rigidity), each with its weight 1.
struct FieldEnergies {
    double alignment = 0, continuity = 0, rigidity = 0;
};
FieldEnergies field_energies(const BrushCanvas::Impl& state);

}  // namespace tessera::brush
