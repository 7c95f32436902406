// A deterministic parallel-for: the range is cut into fixed contiguous chunks
// (independent of timing), each index writes only its own output slot, and the
// caller reduces slots in index order. Worker threads are started per call:
// calls are coarse (one per solver phase), so a pool would save little and would
// add shared state, which the library must not have.
#pragma once

#include <functional>

namespace tessera::core {

// Effective thread count for a requested value (0 = hardware concurrency).
int resolve_threads(int requested);

// Calls body(begin, end, thread_index) on disjoint chunks covering [0, n).
// thread_index < threads; each thread owns scratch indexed by it.
// Exceptions thrown by a body are rethrown in the caller (the first by chunk order).
// `grain`: the fewest indices worth a thread of their own (starting one costs tens of
// microseconds): fewer threads run when n / grain is smaller than `threads`.
void parallel_for(int n, int threads, const std::function<void(int begin, int end, int thread)>& body, int grain = 1);

// The most threads any parallel_for ran with since the last reset: a diagnostic that lets
// tests check that a method keeps to its `threads` option (the only state here, atomic).
int widest_parallel_for();
void reset_widest_parallel_for();

}  // namespace tessera::core
