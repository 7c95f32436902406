// Benchmark B8: dynamic synthesis, frame by frame (tessera::synthesize_dynamic).
#pragma once

#include <string>

namespace tessera_bench {
// Prints a Markdown table: 1,000 particles x 100 frames from examples/dynamic/, the time of
// the first frame (the static method and the input index) and the time per later frame.
void run_dynamic_scenarios(const std::string& examples, int threads);
}  // namespace tessera_bench
