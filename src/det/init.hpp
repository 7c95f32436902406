// Patch-copy initialization (section 4.1): the output domain is cut into cells
// of the patch size; each cell receives a copy of the whole elements whose
// centroids lie in a same-sized window of the exemplar. Of several random
// windows, the one that agrees best with the elements already placed around the
// cell is taken (image-quilting-style seams; the paper's "preferring input
// patches with similar boundary conditions"), which keeps structured patterns
// aligned across seams.
#pragma once

#include <functional>

#include "core/crowding_repair.hpp"
#include "det/model.hpp"
#include "det/provenance.hpp"

namespace tessera::det {

struct InitResult {
    Arrangement arrangement;           // output elements and samples, ids 0..n-1
    std::vector<int> source_sample;    // per output sample: the input sample it was copied from
    std::vector<int> source_element;   // per output element: the input element it was copied from
    double patch_size = 0.0;
    double structure_range = 0.0;      // the exemplar's correlation range, when the default patch used it
    int filled = 0;                    // elements added by fill_vacancies
    int thinned = 0;                   // elements removed by thin_crowds
    Provenance provenance() { return {arrangement, source_sample, source_element}; }
};

// Called now and then with the cells done and the cell count (progress; it may throw
// Cancelled to stop the initialization).
using InitTick = std::function<void(int done, int total)>;

InitResult initialize_patches(const Exemplar& exemplar, const InputIndex& index, const Domain& domain,
                              const Params& params, const DetOptions& options, const InitTick& tick = {});

// Removes the most crowded elements (nearest neighbour closest relative to the exemplar's
// typical distance for that pair of types) of every type that holds more than its
// exemplar density asks for, until the counts are met (src/det/thin_crowds.cpp).
// Returns how many were removed; renumbers ids 0..n-1.
// With hole_radius > 0, an element whose removal would leave an empty ball larger than it
// stays. `crowded_below`: the crowding (1 = the exemplar's close distance) from which an
// element is no longer removed. Types are thinned down to (1 + allowance) times their count.
int thin_crowds(Provenance of, const Exemplar& exemplar, const Domain& domain, const Params& params,
                double hole_radius = 0.0, double crowded_below = 1.0, double allowance = 0.0);

// A hand-placed exemplar or a lattice may keep all its elements away from a side of its box
// window (an empty margin, more than a quarter spacing wide): output elements nearer that
// side of a box domain than a quarter of that margin are removed (they show a partial row along a wall
// the exemplar never has). Not with floor constraints or layered exemplars. Returns how many.
int drop_beyond_margin(Provenance of, const Exemplar& exemplar, const Domain& domain, const Params& params);

// Removes elements the crowding repair could not separate (core::crowded_pairs after it),
// of types above their count, the later of each pair first. Returns how many.
int remove_unresolved_crowding(Provenance of, const Domain& domain, const Params& params,
                               const core::CrowdingBounds& tails, const core::CrowdingRepairOptions& options);

}  // namespace tessera::det
