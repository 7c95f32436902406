// apps/tessera/interrupt_scope.hpp — Ctrl-C during a long command: the first SIGINT asks
// the library to stop (through the progress callback), so that nothing half-written is left.
#pragma once

namespace tessera_cli {

// Catches SIGINT from its construction (loading an input or voxelizing a mesh domain can
// take a while) until it is destroyed; the first progress call after an interrupt then
// cancels the run. Restores the default on every way out. A second Ctrl-C kills the process
// the usual way, but only when it comes at least 0.2 s after the first: `timeout -s INT` and
// scripts that signal both a child and its process group deliver one interrupt twice within
// microseconds, and that must still end cleanly.
struct InterruptScope {
    InterruptScope();
    ~InterruptScope();
    InterruptScope(const InterruptScope&) = delete;
    InterruptScope& operator=(const InterruptScope&) = delete;
};

// True once SIGINT arrived inside an InterruptScope.
bool interrupt_requested();

}  // namespace tessera_cli
