// apps/studio/session_history.hpp — undo and redo of a session, kept by the server
// (docs/studio.md, "Undo and redo"). Before the first operation of a step commits, the
// session's state (canvas, operations, palette count) is kept; undo puts it back and keeps
// the state it replaced for redo. A step is one group of operations: a client names the
// group of each operation (a gesture: a stroke sent as several paint operations while it is
// drawn); an operation without one is a step of its own. Going back costs a swap, not a
// replay of the session.
#pragma once

#include <cstdint>
#include <optional>

#include "apps/studio/sessions.hpp"

namespace tessera_studio {

// Steps kept per session; the oldest is dropped beyond it (each holds a copy of the canvas).
constexpr size_t max_undo_steps = 64;

// Whether an operation of `group` starts a step (it has no group, or another than the
// operation before it); call with the mutex held, as the two below.
bool starts_step(const Session& session, std::optional<std::int64_t> group);

// A copy of the session's state to keep for undo when an operation of `group` starts a
// step, else nothing.
std::optional<SessionState> state_before(const Session& session, std::optional<std::int64_t> group);

// Records an operation of `group` committed, `before` (when it started a step) as the
// state its undo goes back to; redo steps are dropped.
void commit_step(Session& session, std::optional<SessionState> before, std::optional<std::int64_t> group);

// POST /api/sessions/ID/undo and /redo: the step taken back (or again); 409 while a job
// runs or when there is no step. Answers {"ops", "undo", "redo"}: the operations applied and
// the steps left each way.
Json undo_step(Session& session);
Json redo_step(Session& session);

}  // namespace tessera_studio
