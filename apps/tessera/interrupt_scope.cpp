// apps/tessera/interrupt_scope.cpp — SIGINT handling of long commands (interrupt_scope.hpp).
#include "interrupt_scope.hpp"

#include <csignal>
#include <time.h>

namespace tessera_cli {

namespace {

volatile std::sig_atomic_t interrupted = 0;
volatile std::sig_atomic_t first_interrupt_ms = 0;

// clock_gettime is async-signal-safe; std::chrono is not guaranteed to be.
long monotonic_ms() {
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);
    return static_cast<long>(now.tv_sec % 1000000) * 1000 + now.tv_nsec / 1000000;
}

extern "C" void on_interrupt(int) {
    const long now = monotonic_ms();
    if (interrupted == 0) {
        interrupted = 1;
        first_interrupt_ms = static_cast<std::sig_atomic_t>(now);
        return;
    }
    if (now - first_interrupt_ms < 200) return;  // the same interrupt delivered twice
    std::signal(SIGINT, SIG_DFL);
    std::raise(SIGINT);
}

}  // namespace

InterruptScope::InterruptScope() {
    interrupted = 0;
    std::signal(SIGINT, on_interrupt);
}

InterruptScope::~InterruptScope() { std::signal(SIGINT, SIG_DFL); }

bool interrupt_requested() { return interrupted != 0; }

}  // namespace tessera_cli
