// Benchmark B7: worlds of deterministic tiles (tessera/world.hpp) made in one process, from
// 4 x 4 to 64 x 64 tiles, and what their per-tile cost says about 10^8 elements on 100 machines.
#pragma once

#include <string>

namespace tessera_bench {
// Prints a Markdown table (tiles asked and made, elements, tiles / s, elements / s, time per
// tile against the smallest world's) and the estimate. The 2-worker Dask figures come from
// python/benchmarks/world_dask.py, run by scripts/bench.
void run_world_scenarios(const std::string& examples, bool quick, int threads);
}  // namespace tessera_bench
