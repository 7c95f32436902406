// brush/laplacian_field.hpp — a full direction field interpolated from partial strokes by
// Laplacian (membrane) interpolation on a grid: the two-phase baseline of the paper's
// Figure 5c, and the first guess from which fill() places its elements before the
// element field is optimized on the elements themselves (section 4).
#pragma once

#include <vector>

#include "tessera/brush.hpp"
#include "tessera/field.hpp"

namespace tessera::brush {

class Surface;  // brush/surface.hpp

// Minimises sum_nodes a(n) |u(n) - O(n)|^2 + sum_edges |u(n) - u(m)|^2 over the nodes of a
// grid of `cell` over the canvas bounds, a(n) = exp(-d^2 / sigma^2) with d the distance to
// the nearest stroke point (Eq. 5's falloff) and O its direction; solved by sparse Cholesky,
// vectors normalised. No strokes: the empty field (the exemplar's frame everywhere).
// On a surface (`surface` not null) only the nodes within reach of it take part (those of
// the cells a surface point lies in; the membrane then spreads the strokes along the band,
// not through the solid), and the field is given as a mesh-vertex field of tangent
// directions (brush/surface.hpp, surface_field).
OrientationField interpolate_strokes(const Domain& canvas, const std::vector<Stroke>& strokes, double cell,
                                     double sigma, const Surface* surface = nullptr);

}  // namespace tessera::brush
