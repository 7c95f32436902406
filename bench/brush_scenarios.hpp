// Benchmark B9: brushing element fields (tessera/brush.hpp) in the library: the time of one
// paint call for a stroke of about 100 elements, and of "fill the rest" of a canvas of about
// 2,000 elements (growth along the strokes' field, then the solver), for single-sample dots
// and 5-sample rigid sticks. The browser's figures (pointer events to elements drawn) come
// from tests/web/stroke_latency.mjs.
#pragma once

#include <string>

namespace tessera_bench {

void run_brush_scenarios(const std::string& examples, int threads);

}  // namespace tessera_bench
