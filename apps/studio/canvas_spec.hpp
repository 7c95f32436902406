// apps/studio/canvas_spec.hpp — the canvas of a session from its text form, the output
// domain forms of `tessera synth --domain` (tessera/option_text.hpp) as a client sends them
// ("box:0,0,60,40", "polygon:0,0,60,0,30,40", "mesh:examples/blob.obj"). A canvas has no
// exemplar to take a dimension or a lower corner from: the dimension comes from the form
// (2 or 4 box numbers = 2D, 3 or 6 = 3D; polygon and mask 2D; mesh and shell 3D), a box
// size starts at the origin, and a mask needs its box (mask:FILE.png@xmin,ymin,xmax,ymax).
// A file the form names must lie under the project root (static_files.hpp).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "tessera/domain.hpp"

namespace tessera_studio {

struct Canvas {
    tessera::Domain domain;
    int dimension = 2;
    // The form as a session file keeps it: a box size as its corners ("box:60,40" ->
    // "box:0,0,60,40", which `tessera brush` reads the same whatever the palette), files
    // as the client named them (relative to the root).
    std::string text;
};

// 400 (ApiError) naming "canvas" for a malformed form or a domain the library refuses;
// 403/404 for a file outside the root or not there.
Canvas parse_canvas(const std::string& text, const std::filesystem::path& root);

}  // namespace tessera_studio
