// A cancel that reaches into long loops. The progress callback may only be called from the
// caller's thread, between steps; a step on a large output (one search over 100,000
// elements) takes seconds. Loops call check(thread) now and then: on the caller's thread
// (thread 0 of core::parallel_for) it calls `poll` about every 50 ms (the method re-sends its
// last progress event, which may throw Cancelled); once a poll has thrown, every thread's
// next check throws Cancelled too, so the parallel loop ends within a chunk of work.
// Private to the library.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>

#include "tessera/error.hpp"

namespace tessera::core {

class Interrupt {
public:
    Interrupt() = default;
    explicit Interrupt(std::function<void()> poll) : poll_(std::move(poll)) {}
    // A copy polls the same function and starts not stopped; an owner that is copied with
    // it gives the copy a poll of its own (set_poll), since a poll usually reaches its owner.
    Interrupt(const Interrupt& other) : poll_(other.poll_) {}
    Interrupt& operator=(const Interrupt&) = delete;
    void set_poll(std::function<void()> poll) { poll_ = std::move(poll); }

    void check(int thread) const {
        if (stopped_.load(std::memory_order_relaxed)) throw Cancelled();
        if (thread != 0 || !poll_) return;
        const auto now = std::chrono::steady_clock::now();
        if (now - last_ < kInterval) return;
        last_ = now;
        try {
            poll_();
        } catch (...) {
            stopped_.store(true, std::memory_order_relaxed);
            throw;
        }
    }
    // A new step: the stop of a finished one is forgotten (it was thrown to the caller).
    void rearm() const {
        stopped_.store(false, std::memory_order_relaxed);
        last_ = std::chrono::steady_clock::now();
    }

private:
    static constexpr std::chrono::milliseconds kInterval{50};
    std::function<void()> poll_;
    mutable std::atomic<bool> stopped_{false};
    mutable std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// Checks `interrupt` if there is one.
inline void check(const Interrupt* interrupt, int thread) {
    if (interrupt) interrupt->check(thread);
}

}  // namespace tessera::core
