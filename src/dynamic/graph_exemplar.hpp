// How the dynamic method uses graph synthesis (section 4.3, tessera/graph_motion.hpp):
// DynamicOptions::graph_frames' option row and the exemplar synthesize_dynamic works on.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "tessera/dynamic.hpp"
#include "tessera/option_table.hpp"

namespace tessera::dynamic {

// The row of graph_frames: -1 (automatic), 0 (off) or at least 2 frames; 1 is refused by the
// name the caller wrote (a range cannot say "but not 1").
OptionSpec<DynamicOptions> graph_frames_row();

// Throws Error(option) naming graph_frames when it is 1 (C++ callers fill the struct
// directly, past the row's setter).
void check_graph_frames(const DynamicOptions& options);

// The exemplar synthesis works on: `given` itself, or (graph_frames_for > 0 and more than
// its frames) it continued by graph synthesis (extend_by_graph) with the run's radius, seed
// and threads, kept in `storage`; a line for the run's notes says so.
const Animation& exemplar_with_motion(const Animation& given, const DynamicOptions& options,
                                      std::optional<Animation>& storage, std::vector<std::string>& notes);

}  // namespace tessera::dynamic
