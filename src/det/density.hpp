// The exemplar's density where its elements are. An exemplar's count over its window is its
// density only when the elements fill the window: a hand-placed example or a lattice often
// has an empty margin inside its window, and matching that lower density forces the output
// to stretch or to leave vacancies. For a box window of a regular pattern, each side whose
// nearest element lies more than 0.75 spacings in is moved in to half a spacing before it.
// Other windows are eroded by one mean spacing, then by two, while the band taken off holds
// significantly fewer elements (3 standard deviations of a Poisson count) than the
// interior's density predicts; the density is then the interior's. Field data cut from a
// larger pattern have no such margin and keep count / measure.
#pragma once

#include <vector>

#include "tessera/exemplar.hpp"

namespace tessera::det {

// Elements per unit measure (area in 2D, volume in 3D), per type.
std::vector<double> exemplar_type_density(const Exemplar& exemplar, double spacing);

}  // namespace tessera::det
