// python/src/tile_arrays.hpp — a world's tile (tessera/world.hpp) as a dict of numpy arrays,
// the compact form Python passes between processes and machines. It holds exactly what
// tile_to_json writes, so tile_from_compact(compact_tile(t)) is the tile a reader of t's file
// gets, bit for bit:
//   dimension         2 or 3
//   box_min, box_max  float64 (d,): the tile's box, its domain
//   types             list of dicts (name, rigid, floor, mesh, color, reference: R x d float64,
//                     depends_on: None or a list of names), as Exemplar.types
//   attribute_names   list of str
//   sample_counts     int32 (E,): samples of each element, whose runs follow each other
//   classes int32 (E,), radii float64 (E,), orientations float64 (E, 4) (w, x, y, z),
//   scales float64 (E,), ids uint64 (E,), locked bool (E,), attributes float64 (E, A)
//   positions float64 (S, d), times float64 (S,)
// Element centres are not stored: a reader computes them from the samples, as a file's does.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

#include "tessera/exemplar.hpp"

namespace tessera_python {

// The compact form of a tile (any arrangement whose domain is a box; OptionError otherwise).
pybind11::dict compact_tile(const tessera::Exemplar& tile);

// The tile back from its compact form. `what` names it in errors ("tile", "neighbour 0,1"):
// OptionError for a missing or unknown key and an array of the wrong shape or kind,
// InputError / DomainError for data that break the model's invariants.
tessera::Arrangement tile_from_compact(const pybind11::handle& compact, const std::string& what);

}  // namespace tessera_python
