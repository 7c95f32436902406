// Patch-copy initialization (section 4.1): the output domain is cut into cells
// of the patch size; each cell receives a copy of the whole elements whose
// centroids lie in a same-sized window of the exemplar. Of several random
// windows, the one that agrees best with the elements already placed around the
// cell is taken (image-quilting-style seams; the paper's "preferring input
// patches with similar boundary conditions"), which keeps structured patterns
// aligned across seams.
#pragma once

#include "det/model.hpp"

namespace tessera::det {

struct InitResult {
    Arrangement arrangement;           // output elements and samples, ids 0..n-1
    std::vector<int> source_sample;    // per output sample: the input sample it was copied from
    std::vector<int> source_element;   // per output element: the input element it was copied from
    double patch_size = 0.0;
    double structure_range = 0.0;      // the exemplar's correlation range, when the default patch used it
    int filled = 0;                    // elements added by fill_holes
    int thinned = 0;                   // elements removed by thin_crowds
};

InitResult initialize_patches(const Exemplar& exemplar, const InputIndex& index, const Domain& domain,
                              const Params& params, const DetOptions& options);

// Element positions (centroids), z = 0 in 2D: the points of the grids over elements.
std::vector<Vec3> element_centroids(const std::vector<Element>& elements, int dimension);

// Appends a copy of exemplar element `source` moved by p -> rotation p + shift
// (recording its source samples and element); returns the new element's index.
int append_copy(InitResult& init, const Exemplar& exemplar, int source, const Quat& rotation, const Vec3& shift,
                int dimension);

// Adds copies of exemplar elements at the emptiest places of the domain until the
// output holds the exemplar's density (or no gap wider than half a spacing is left).
// Returns how many were added.
int fill_holes(InitResult& init, const Exemplar& exemplar, const Domain& domain, const Params& params,
               std::uint64_t seed);

// Removes the most crowded elements (nearest neighbour closest relative to the exemplar's
// typical distance for that pair of types) of every type that holds more than its
// exemplar density asks for, until the counts are met (src/det/thin_crowds.cpp).
// Returns how many were removed; renumbers ids 0..n-1.
int thin_crowds(InitResult& init, const Exemplar& exemplar, const Domain& domain, const Params& params);

}  // namespace tessera::det
