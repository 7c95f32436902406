// Benchmark B6: on-demand growth (tessera::Grower) from 10,000 to 1,000,000 elements.
#pragma once

#include <string>

namespace tessera_bench {
// Prints a Markdown table: elements per second, time per element against the smallest
// size, and memory per element, for a 2D single-sample and a 3D 5-sample exemplar.
void run_grow_scenarios(const std::string& examples, bool quick, int threads);
}  // namespace tessera_bench
