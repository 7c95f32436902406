// apps/tessera/status_printer.hpp — what a subcommand tells the user on stderr while it
// works: the library's progress events as lines, and the steps of its own (reading an
// input, writing an output) that take long.
//
// Every event is shown, whatever its stage (set-up stages such as "index" or "analysis"
// as "STAGE k/n (p%)" when the event carries its fraction done), but at most one line per
// `min_interval`: an event that comes sooner is held, and a background thread prints the
// latest held one once the interval has passed, so a fast run is not flooded and a stage
// that sends one event and then works for seconds is still on screen within the
// interval. A step of the command's own is announced ("synth: reading big.csv ...") when
// it has run for `slow_step` seconds. Nothing at all is printed when quiet.
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <ostream>
#include <string>
#include <thread>

#include "tessera/progress.hpp"

namespace tessera_cli {

class StatusPrinter {
public:
    struct Timing {
        double min_interval = 0.25;  // seconds between two progress lines (at most 4 per second)
        double slow_step = 1.0;      // seconds after which a step of the command's own is announced
    };

    // `command` prefixes the step notices ("synth"); `out` is normally std::cerr.
    StatusPrinter(std::string command, bool quiet, std::ostream& out, Timing timing);
    StatusPrinter(std::string command, bool quiet, std::ostream& out);
    ~StatusPrinter();
    StatusPrinter(const StatusPrinter&) = delete;
    StatusPrinter& operator=(const StatusPrinter&) = delete;

    // The callback to hand the library: shows the event (as above) and returns
    // keep_going(). "iteration" events read "UNIT k/n  energy E  elapsed T s" (UNIT =
    // `iteration_unit`, e.g. "sweep" for the PCF method); "done" events print nothing of
    // their own, they only flush the held line (the command's summary follows).
    tessera::Progress progress(std::function<bool()> keep_going, std::string iteration_unit = "iteration");

    // Runs `work` and returns its result; when it takes longer than Timing::slow_step, a
    // line "COMMAND: WHAT ..." says what is going on.
    template <class Work>
    auto step(const std::string& what, Work&& work) -> decltype(work()) {
        StepScope scope(*this, what);
        return work();
    }

    // Prints the held event, if any, so that the next line the command prints comes after it.
    void flush();

    // The line of one event ("" for "done"); public for the tests.
    static std::string format(const tessera::ProgressEvent& event, const std::string& iteration_unit);

private:
    using Clock = std::chrono::steady_clock;

    struct StepScope {
        StepScope(StatusPrinter& printer, const std::string& what);
        ~StepScope();
        StatusPrinter& printer;
    };

    void show(const tessera::ProgressEvent& event, const std::string& unit);
    void print_locked(const std::string& line);  // with the mutex held
    void print_held_locked();
    void run_thread();

    const std::string command_;
    const bool quiet_;
    std::ostream& out_;
    const Timing timing_;

    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
    std::optional<Clock::time_point> last_line_;
    std::optional<std::string> held_;  // the latest event not printed yet, as its line
    bool held_iteration_ = false;      // that event is an iteration (or a sweep)
    std::optional<std::string> step_;  // the step of the command's own under way
    Clock::time_point step_start_;
    bool step_announced_ = false;
    std::thread thread_;  // started last, after everything it reads
};

}  // namespace tessera_cli
