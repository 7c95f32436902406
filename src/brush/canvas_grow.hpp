// brush/canvas_grow.hpp — elements added to a brush canvas by growth (tessera/grow.hpp):
// a palette entry grown in a region next to the canvas's elements of that entry, with an
// orientation field, and the new elements that do not conflict with the other entries'
// elements (Eq. 3's bound: no two samples closer than 0.8 of their summed weights) added.
#pragma once

#include <vector>

#include "brush/brush_state.hpp"
#include "tessera/field.hpp"

namespace tessera::brush {

// Grows entry `kappa` in `region` (seeded at `seed_at` when no element of the entry is within
// reach) with `field`, and appends the new elements to the canvas, each sample's o(s) the
// field's direction at its element's centre, tilted by up to `tilt` radians (a draw keyed by
// the element's place in the world, so the same place gets the same tilt). Returns
// {added, dropped in conflict}.
// `edge`: closed for a stroke's band (every sample inside), open for fill's parts of the
// canvas, which meet other entries' parts (centres inside; the conflict check settles the
// border, where a closed edge left a gap as wide as an element).
std::pair<int, int> grow_entry(BrushCanvas::Impl& state, int kappa, const Domain& region, const OrientationField& field,
                               const Vec3& seed_at, double tilt = 0.0, RegionEdge edge = RegionEdge::closed);

}  // namespace tessera::brush
