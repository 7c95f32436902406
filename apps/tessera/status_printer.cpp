// apps/tessera/status_printer.cpp — progress lines and slow-step notices (status_printer.hpp).
#include "status_printer.hpp"

#include <algorithm>
#include <cstdio>
#include <utility>

namespace tessera_cli {

StatusPrinter::StatusPrinter(std::string command, bool quiet, std::ostream& out)
    : StatusPrinter(std::move(command), quiet, out, Timing{}) {}

StatusPrinter::StatusPrinter(std::string command, bool quiet, std::ostream& out, Timing timing)
    : command_(std::move(command)), quiet_(quiet), out_(out), timing_(timing) {
    if (!quiet_) thread_ = std::thread([this] { run_thread(); });
}

StatusPrinter::~StatusPrinter() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
}

std::string StatusPrinter::format(const tessera::ProgressEvent& event, const std::string& iteration_unit) {
    char line[200];
    if (event.stage == "done") return "";
    if (event.stage == "iteration") {
        std::snprintf(line, sizeof line, "%s %d/%d  energy %.6g  elapsed %.2f s", iteration_unit.c_str(),
                      event.iteration + 1, event.iterations, event.energy, event.elapsed_s);
        return line;
    }
    if (event.stage == "round" && event.iteration >= 0) {  // growth: the rounds are not planned ahead
        std::snprintf(line, sizeof line, "round %d  energy %.4g  about %d%% done  elapsed %.2f s", event.iteration + 1,
                      event.energy, static_cast<int>(100.0 * event.fraction), event.elapsed_s);
        return line;
    }
    if (event.stage == "round") {  // growth's first event, before any round has run
        std::snprintf(line, sizeof line, "growing  elapsed %.2f s", event.elapsed_s);
        return line;
    }
    // Any other stage: its fraction done when the event has one (a 0-based step index).
    const std::string stage = event.stage.empty() ? "working" : event.stage;
    if (event.iterations > 0 && event.iteration >= 0) {
        const int done = std::min(event.iteration + 1, event.iterations);
        std::snprintf(line, sizeof line, "%s %d/%d (%d%%)  elapsed %.2f s", stage.c_str(), done, event.iterations,
                      static_cast<int>(100.0 * done / event.iterations), event.elapsed_s);
    } else {
        std::snprintf(line, sizeof line, "%s  elapsed %.2f s", stage.c_str(), event.elapsed_s);
    }
    return line;
}

tessera::Progress StatusPrinter::progress(std::function<bool()> keep_going, std::string iteration_unit) {
    return [this, keep_going = std::move(keep_going), unit = std::move(iteration_unit)](
               const tessera::ProgressEvent& event) {
        if (!quiet_) show(event, unit);
        return keep_going ? keep_going() : true;
    };
}

void StatusPrinter::show(const tessera::ProgressEvent& event, const std::string& unit) {
    const std::string line = format(event, unit);
    std::unique_lock<std::mutex> lock(mutex_);
    if (line.empty()) {  // "done": the held line, then the command's summary
        print_held_locked();
        return;
    }
    // The last line of a run of iterations (its final energy) is always shown: held, it is
    // printed before another stage's line replaces it (the one exception to the rate).
    if (held_ && held_iteration_ && event.stage != "iteration") print_held_locked();
    const auto now = Clock::now();
    if (!last_line_ || now - *last_line_ >= std::chrono::duration<double>(timing_.min_interval)) {
        held_.reset();
        print_locked(line);
        return;
    }
    held_ = line;
    held_iteration_ = event.stage == "iteration";
    lock.unlock();
    wake_.notify_all();
}

void StatusPrinter::print_locked(const std::string& line) {
    out_ << line << std::endl;
    last_line_ = Clock::now();
}

void StatusPrinter::print_held_locked() {
    if (!held_) return;
    print_locked(*held_);
    held_.reset();
}

void StatusPrinter::flush() {
    std::lock_guard<std::mutex> lock(mutex_);
    print_held_locked();
}

StatusPrinter::StepScope::StepScope(StatusPrinter& p, const std::string& what) : printer(p) {
    if (printer.quiet_) return;
    {
        std::lock_guard<std::mutex> lock(printer.mutex_);
        printer.step_ = what;
        printer.step_start_ = Clock::now();
        printer.step_announced_ = false;
    }
    printer.wake_.notify_all();
}

StatusPrinter::StepScope::~StepScope() {
    if (printer.quiet_) return;
    std::lock_guard<std::mutex> lock(printer.mutex_);
    printer.step_.reset();
}

void StatusPrinter::run_thread() {
    const auto seconds = [](double s) { return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s)); };
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stop_) {
        // Sleep until the held line may be printed or the step becomes slow, whichever is first.
        std::optional<Clock::time_point> due;
        if (held_) due = *last_line_ + seconds(timing_.min_interval);
        if (step_ && !step_announced_) {
            const auto slow = step_start_ + seconds(timing_.slow_step);
            due = due ? std::min(*due, slow) : slow;
        }
        if (due)
            wake_.wait_until(lock, *due);
        else
            wake_.wait(lock);
        if (stop_) break;
        const auto now = Clock::now();
        if (held_ && now >= *last_line_ + seconds(timing_.min_interval)) print_held_locked();
        if (step_ && !step_announced_ && now >= step_start_ + seconds(timing_.slow_step)) {
            print_locked(command_ + ": " + *step_ + " ...");
            step_announced_ = true;
        }
    }
}

}  // namespace tessera_cli
