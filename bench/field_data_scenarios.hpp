// Benchmark B5: both methods on every real dataset of the shared data.
#pragma once

#include <string>

namespace tessera_bench {
// Prints a Markdown table: for each dataset, the PCF error of det and pcf outputs of 4x
// the area (mean over seeds 1-3) against a uniform random pattern and a 2 x 2 tiling of
// the exemplar itself, and the time per run.
void run_field_data_scenarios(const std::string& shared, int threads);
}  // namespace tessera_bench
