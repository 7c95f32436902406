// apps/studio/paint_estimate.hpp — how many elements a paint stroke will make, before it is
// made. The studio runs a paint in the request (its answer then carries the new elements,
// so a stroke drawn live shows them one round trip later) when it is small, and as a
// cancellable job when it is large; this estimate decides (docs/studio.md, "Live painting").
#pragma once

#include "tessera/brush.hpp"
#include "tessera/exemplar.hpp"

namespace tessera_studio {

// Elements per unit area (2D) or volume (3D) of an exemplar: its count over its domain's
// measure (0 when the domain has none).
double exemplar_density(const tessera::Exemplar& exemplar);

// The elements expected in the band `stroke` sweeps: its length times its width (2D) or
// cross-section (3D) times `density`. A width of 0 stands for `default_width_spacings`
// spacings of the exemplar, the spacing taken as density^(-1/dimension).
double expected_paint_elements(const tessera::Stroke& stroke, double density, int dimension,
                               double default_width_spacings);

// The largest paint the studio runs in the request thread (a paint of this size takes some
// tens of milliseconds in the library; B9).
constexpr double max_inline_paint_elements = 400;

}  // namespace tessera_studio
