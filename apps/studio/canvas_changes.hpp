// apps/studio/canvas_changes.hpp — what an operation added to a canvas, to send instead of
// the whole arrangement. A paint stroke drawn live is sent as many small paint operations;
// reading the whole session back after each would grow with the canvas, so the answer of an
// operation that only appended elements carries just those (docs/studio.md, "Live
// painting"). When anything already there changed, there is no change set and the client
// reads the session.
#pragma once

#include <vector>

#include "apps/studio/api_json.hpp"
#include "tessera/brush.hpp"

namespace tessera_studio {

// The canvas as it was before an operation: counts, sample positions and directions.
struct CanvasMark {
    size_t elements = 0;
    std::vector<tessera::Vec3> positions, directions;
};
CanvasMark mark_canvas(const tessera::BrushCanvas& canvas);

// {"first_element", "first_sample", "arrangement" (tessera JSON of the new elements, with
// all the canvas's types, so type indices match the session's), "directions" and
// "exemplars" of the new samples}, or null when the operation did more than append.
Json appended_since(const tessera::BrushCanvas& canvas, const CanvasMark& before);

}  // namespace tessera_studio
