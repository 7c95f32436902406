// apps/studio/sessions.hpp — the sessions of a studio server (docs/studio.md, "Sessions").
// A session is one canvas a client paints: its canvas text, the tessera::BrushCanvas, the
// palette entries as they were given (a path under the root or an inline exemplar), the
// operations applied, the states undo and redo go back to (session_history.hpp), and the
// job running on it if any. Each session is guarded by its own
// mutex and the registry by another, so clients working on different sessions never wait
// for each other; a job works on a copy of the canvas and swaps it in when it ends.
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "apps/studio/api_json.hpp"
#include "tessera/brush.hpp"

namespace tessera_studio {

// Ids of sessions and jobs: a prefix, a counter (unique in the server) and a random part
// (so that ids of an earlier server run are not guessed by a stale tab).
class IdMaker {
public:
    explicit IdMaker(char prefix);
    std::string next();

private:
    std::mutex mutex_;
    const char prefix_;
    std::uint64_t counter_ = 0;
    std::mt19937_64 random_;
};

struct PaletteEntry {
    std::string name;
    Json source;  // "relative/path.json" under the root, or the inline exemplar object
    double density = 0.0;  // its exemplar's elements per unit area or volume (paint_estimate.hpp)
    // The exemplar as added: a canvas that undo restores from before the entry was added
    // gets it again.
    std::shared_ptr<const tessera::Exemplar> exemplar;
};

// What undo and redo go back to: the canvas and the operations as they were, and how many
// palette entries the session had then.
struct SessionState {
    tessera::BrushCanvas canvas;
    Json ops;
    size_t palette = 0;
};

// Everything below `mutex` is guarded by it.
struct Session {
    Session(std::string id, std::string canvas_text, int dimension, tessera::BrushCanvas canvas);

    const std::string id;
    std::mutex mutex;
    const std::string canvas_text;
    const int dimension;
    tessera::BrushCanvas canvas;
    std::vector<PaletteEntry> palette;
    Json ops = Json::array();  // the operations applied, as a session file stores them
    std::string job;           // the running job's id, "" when none runs
    // Undo steps (the state before each step, the last one last) and redo steps; the
    // client's group of the last operation applied (its gesture: a stroke sent as several
    // paint operations is one step).
    std::deque<SessionState> undo, redo;
    std::optional<std::int64_t> last_group;
};

// 409 naming the job while one runs on the session (call with its mutex held).
void check_idle(const Session& session);

class SessionRegistry {
public:
    explicit SessionRegistry(size_t max_sessions);

    // Registers `session`; 503 (ApiError) when max_sessions are open.
    void add(std::shared_ptr<Session> session);
    // nullptr when there is no such session.
    std::shared_ptr<Session> find(const std::string& id) const;
    // The session removed, or nullptr.
    std::shared_ptr<Session> remove(const std::string& id);
    std::vector<std::string> ids() const;
    // An id for a new session.
    std::string next_id() { return ids_.next(); }

private:
    mutable std::mutex mutex_;
    std::map<std::string, std::shared_ptr<Session>> sessions_;
    const size_t max_sessions_;
    IdMaker ids_{'s'};
};

// The session's id or 404 naming it.
std::shared_ptr<Session> find_session(const SessionRegistry& registry, const std::string& id);

}  // namespace tessera_studio
