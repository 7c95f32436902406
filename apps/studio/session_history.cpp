// apps/studio/session_history.cpp — undo and redo of a session (session_history.hpp).
#include "apps/studio/session_history.hpp"

#include <string>
#include <utility>

namespace tessera_studio {
namespace {

// Puts the last state of `from` in place and the replaced one at the end of `to`.
void swap_in(Session& s, std::deque<SessionState>& from, std::deque<SessionState>& to) {
    SessionState back = std::move(from.back());
    from.pop_back();
    to.push_back(SessionState{std::move(s.canvas), std::move(s.ops), s.palette.size()});
    s.canvas = std::move(back.canvas);
    s.ops = std::move(back.ops);
    // Palette entries added since that state stay in the session: the canvas gets them back
    // in the same order, so the palette indices of the operations still hold.
    for (size_t k = back.palette; k < s.palette.size(); ++k)
        s.canvas.add_exemplar(s.palette[k].name, *s.palette[k].exemplar);
    s.last_group.reset();  // the next operation starts a step, whatever its group
}

Json counts(const Session& s) {
    return {{"ops", s.ops.size()}, {"undo", s.undo.size()}, {"redo", s.redo.size()}};
}

// Undo (`back`) or redo: the last state of one stack in place, the replaced one on the other.
Json take_step(Session& session, bool back) {
    std::lock_guard lock(session.mutex);
    check_idle(session);
    std::deque<SessionState>& from = back ? session.undo : session.redo;
    std::deque<SessionState>& to = back ? session.redo : session.undo;
    if (from.empty())
        throw ApiError(409, "session " + session.id + " has nothing to " + (back ? "undo" : "redo"));
    swap_in(session, from, to);
    return counts(session);
}

}  // namespace

bool starts_step(const Session& session, std::optional<std::int64_t> group) {
    return !group || session.last_group != group;
}

std::optional<SessionState> state_before(const Session& session, std::optional<std::int64_t> group) {
    if (!starts_step(session, group)) return std::nullopt;
    return SessionState{session.canvas, session.ops, session.palette.size()};
}

void commit_step(Session& session, std::optional<SessionState> before, std::optional<std::int64_t> group) {
    session.redo.clear();
    if (before) {
        session.undo.push_back(std::move(*before));
        if (session.undo.size() > max_undo_steps) session.undo.pop_front();
    }
    session.last_group = group;
}

Json undo_step(Session& session) { return take_step(session, true); }
Json redo_step(Session& session) { return take_step(session, false); }

}  // namespace tessera_studio
