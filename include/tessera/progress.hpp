// tessera/progress.hpp — how long runs report progress and accept cancellation.
// The library never prints; it calls this (from the calling thread only): at the start and
// end of each step, and during a long step (the neighbourhood method's initialization and
// search, a growth round) about every 50 ms, re-sending the step's last event with a new elapsed_s, so that
// a cancel takes effect within about 0.1 s. Returning false cancels: the method throws
// Cancelled. A repeated event carries no news; count steps by (stage, iteration).
#pragma once

#include <functional>
#include <string>

namespace tessera {

struct ProgressEvent {
    std::string stage;       // det: "init", "patches", "fill", "iteration", "relax", "repair", "settle"
                             // (with physics), "done"; pcf: "analysis", "init", "iteration", "repair", "done"
    int iteration = 0;       // 0-based step of the stage (iteration, sweep); -1 for a stage's start
    int iterations = 0;      // total steps of the stage (iterations, sweeps) planned
    double energy = 0.0;     // current energy (Eq. 2), 0 when not known yet
    double elapsed_s = 0.0;  // seconds since the method started
    double fraction = 0.0;   // share of the whole call done, 0 to 1 (1 with "done"); an
                             // estimate from the planned steps (a PCF class may stop early)
};

using Progress = std::function<bool(const ProgressEvent&)>;

}  // namespace tessera
