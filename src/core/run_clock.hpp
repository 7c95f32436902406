// What every synthesis method's driver does around its iterations: wall-clock seconds
// for the run statistics, and progress reports that turn a "stop" answer from the
// caller's callback into Cancelled. Private to the library.
#pragma once

#include <chrono>

#include "tessera/error.hpp"
#include "tessera/progress.hpp"

namespace tessera::core {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Calls the progress callback (if any); throws Cancelled when it returns false.
inline void report(const Progress& progress, const ProgressEvent& event) {
    if (progress && !progress(event)) throw Cancelled();
}

}  // namespace tessera::core
