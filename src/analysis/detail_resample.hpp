// The details of one element carried onto another element's samples for recombination
// (tessera/motion_analysis.hpp, recombine_motion; Dynamic Element Textures, section 5).
#pragma once

#include "analysis/low_pass.hpp"

namespace tessera::analysis {

// The detail offsets of element `from` of `detail` at detail frame `frame`, one per sample
// of an element laid out as `to`, written to out[0 .. to.rows x to.columns - 1]. Grids
// (threads, sheets) are resampled linearly along their rows and columns, end to end, so
// that a thread of 12 samples takes the waves of one of 40; particle elements take sample k
// from the detail's sample k mod its sample count (their samples have no order to follow).
void resampled_offsets(const Animation& detail, int from, const Layout& from_layout, int frame,
                       const Layout& to, Vec3* out);

}  // namespace tessera::analysis
