// Assignment step (section 4.3): positions by least squares over all predicted
// offsets (Eq. 3, 4) plus a boundary term, attributes by voting (Eq. 5), then each
// rigid element is snapped to the best-fitting rigid copy of the input element it
// voted for.
#pragma once

#include "core/rigid_fit.hpp"
#include "det/model.hpp"

namespace tessera::det {

struct AssignReport {
    int cg_iterations = 0;     // largest count over the coordinates
    bool cg_converged = true;  // false: the iteration bound was hit (reported, not fatal)
};

AssignReport assign_step(OutputState& state, const InputIndex& index, const Domain& domain, const Params& params,
                         int threads);

// The position part alone (Eq. 4 as a sparse positive-definite solve).
// With a domain, samples outside it are pulled back by the boundary term.
AssignReport assign_positions(OutputState& state, const Params& params, int threads,
                              const Domain* domain = nullptr);

// Translates elements that still leave the domain back inside, as a whole (run once
// at the end of synthesis so the result lies in the domain). Returns how many still
// have a sample outside after the bounded rounds (an element longer than a thin domain).
int keep_inside_domain(Arrangement& out, const Domain& domain, int dimension);

// Best rigid motion (Kabsch), shared with element geometry: core/rigid_fit.hpp.
using core::best_rigid_fit;

// Re-derives each element's pose (position = centroid; orientation of rigid
// multi-sample elements from their fit to the source element's layout).
void update_poses(OutputState& state, const InputIndex& index, int dimension);

}  // namespace tessera::det
