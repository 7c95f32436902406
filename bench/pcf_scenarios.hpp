// Benchmark B4: the PCF method on examples/pcf/ and the shared real datasets.
#pragma once

#include <string>

namespace tessera_bench {
// Prints a Markdown table: time and quality of each scenario (synthesis into 4x the area).
void run_pcf_scenarios(const std::string& examples, const std::string& shared, int threads);
}  // namespace tessera_bench
