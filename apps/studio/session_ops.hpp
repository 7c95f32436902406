// apps/studio/session_ops.hpp — what the routes do to a session (docs/studio.md): make one
// from a canvas and options, add palette entries, apply operations (short ones at once,
// long ones as job work on a copy of the canvas, swapped in when the work ends, so that
// readers never wait for a job and a cancel or failure leaves the canvas as it was), and
// write the session as a session file or the arrangement in an output format.
#pragma once

#include <filesystem>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "apps/studio/api_json.hpp"
#include "apps/studio/jobs.hpp"
#include "apps/studio/sessions.hpp"
#include "tessera/exemplar.hpp"

namespace tessera_studio {

// A new session over the canvas `canvas_text` (canvas_spec.hpp) with `options` (an object
// of brush options, or null); 400 naming the canvas or "options.NAME" when refused.
std::shared_ptr<Session> make_session(const std::string& id, const std::string& canvas_text,
                                      const Json& options, const std::filesystem::path& root);

// Adds `exemplar` to the palette under entry.name; 409 while a job runs, 400 when the
// library refuses it (a name already used, another dimension).
void add_palette_entry(Session& session, PaletteEntry entry, const tessera::Exemplar& exemplar);

// An operation with its palette names resolved against the session's palette.
struct ResolvedOp {
    OpRequest request;
    std::vector<int> exemplars;
};
// 400 naming a palette name the session does not have.
ResolvedOp resolve_op(const Session& session, OpRequest request);

// Applies `request` now, in the caller's thread; returns {"report", "changes"} (the elements
// it appended, canvas_changes.hpp, or null when it changed more). 409 while a job runs.
// `group`: the client's group of the operation, one undo step (session_history.hpp).
Json apply_now(Session& session, const OpRequest& request, std::optional<std::int64_t> group = std::nullopt);
// Whether `request` runs in the request thread (apply_now) rather than as a job: direction
// and erase always, paint when it makes few elements (paint_estimate.hpp); fill and optimize
// never.
bool runs_in_request(Session& session, const OpRequest& request);

// Marks the session busy with job `job_id` and returns the work that applies `ops` in order
// on a copy of the canvas and commits it (canvas and ops) at the end, as one undo step of
// `group` unless `undoable` is false (the replay of a loaded session file); 409 while
// another job runs. release_job() undoes the mark when the job could not be started.
struct StepOf {
    std::optional<std::int64_t> group;
    bool undoable = true;
};
JobRunner::Work prepare_job(const std::shared_ptr<Session>& session, std::vector<OpRequest> ops,
                            const std::string& job_id, StepOf step = {});
void release_job(Session& session, const std::string& job_id);

// GET /api/sessions/ID: the canvas, palette, options, ops count, running job, and the
// arrangement (tessera JSON) with the sample directions and palette entries.
Json session_view(Session& session);
// GET /api/sessions/ID/file: {"format": "tessera-brush", "version": 1, "canvas", "palette",
// "options", "ops"}.
Json session_file(Session& session);

// A parsed session file, checked except for its canvas and palette files.
struct SessionFileContent {
    std::string canvas;
    Json options;
    std::vector<PaletteEntry> palette;
    Json ops;  // checked against the canvas's dimension once the canvas is made
};
SessionFileContent parse_session_file(const Json& doc);

// The arrangement written by tessera::save in `format` (json, csv, ply, usda, gltf, glb,
// obj, png, svg): the bytes and their content type. 400 for another format.
struct ExportedFile {
    std::string body, content_type, filename;
};
ExportedFile export_arrangement(Session& session, const std::string& format,
                                const std::filesystem::path& scratch);

}  // namespace tessera_studio
