// brush/palette.hpp — a palette entry prepared once: the exemplar checked, its spacing, its
// samples' weights and element graphs, the input neighbourhoods of Eq. 1 and its grower.
#pragma once

#include <string>

#include "brush/brush_state.hpp"

namespace tessera::brush {

// Error(input) naming `name` for an exemplar that is invalid or of another dimension.
PaletteEntry prepare_entry(const std::string& name, const Exemplar& exemplar, int dimension,
                           const BrushOptions& options);
// Fills entry.neighbourhoods and by_type once the entry's output types are known.
void index_neighbourhoods(PaletteEntry& entry);

}  // namespace tessera::brush
