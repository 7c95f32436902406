#include "core/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace tessera::core {

namespace {
std::atomic<int> widest{0};
}  // namespace

int widest_parallel_for() { return widest.load(); }
void reset_widest_parallel_for() { widest.store(0); }

int resolve_threads(int requested) {
    if (requested > 0) return requested;
    const unsigned hw = std::thread::hardware_concurrency();
    return hw == 0 ? 1 : static_cast<int>(hw);
}

void parallel_for(int n, int threads, const std::function<void(int, int, int)>& body, int grain) {
    if (n <= 0) return;
    threads = std::max(1, std::min(threads, n / std::max(1, grain)));
    for (int seen = widest.load(); threads > seen && !widest.compare_exchange_weak(seen, threads);) {
    }
    if (threads == 1) {
        body(0, n, 0);
        return;
    }
    // Many more chunks than threads balance uneven work; chunk t*k..: thread t takes
    // chunks t, t + threads, ... so the assignment of indices to threads is fixed.
    const int chunks = std::min(n, threads * 16);
    std::vector<std::exception_ptr> errors(threads);
    auto run = [&](int t) {
        try {
            for (int c = t; c < chunks; c += threads) {
                const int begin = static_cast<int>(static_cast<long long>(n) * c / chunks);
                const int end = static_cast<int>(static_cast<long long>(n) * (c + 1) / chunks);
                body(begin, end, t);
            }
        } catch (...) {
            errors[t] = std::current_exception();
        }
    };
    std::vector<std::thread> workers;
    workers.reserve(threads - 1);
    for (int t = 1; t < threads; ++t) workers.emplace_back(run, t);
    run(0);
    for (auto& w : workers) w.join();
    for (auto& e : errors)
        if (e) std::rethrow_exception(e);
}

}  // namespace tessera::core
