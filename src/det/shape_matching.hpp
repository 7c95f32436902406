// Deformable elements keep their shape (section 3: "deformable" elements bend, they do not
// fall apart). The least-squares assignment (Eq. 4) moves every sample by its own
// predictions, and in a dense tangle the predictions of neighbouring elements pull the
// samples of one noodle different ways: left alone, noodles zigzag (95th-percentile bend
// about 100 degrees where the exemplar's is 16) and stretch. After each assignment every
// deformable element is projected towards its source element's shape by shape matching
// with overlapping clusters (Mueller et al. 2005, "Meshless deformations based on shape
// matching"): each sample's cluster is the samples of the source element within two
// spacings of it; the source cluster is fitted rigidly (Kabsch) onto the current one, and
// each sample moves to the mean of the goals its clusters give it. The local shape (sample
// spacing, bend between segments) becomes the source's, the global bend stays free.
#pragma once

#include "det/model.hpp"

namespace tessera::det {

// Projects the deformable elements (types not rigid, 3 or more samples, not locked) of the
// output towards their source elements' shapes, `rounds` times.
void match_deformable_shapes(OutputState& state, const Exemplar& exemplar, int dimension, int threads,
                             int rounds = 3);

}  // namespace tessera::det
