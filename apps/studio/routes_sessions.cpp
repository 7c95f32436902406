// apps/studio/routes_sessions.cpp — sessions: create, load from a session file, read,
// delete, palette entries, operations, the session file and exports.
#include <httplib.h>
#include <unistd.h>

#include "apps/studio/palette.hpp"
#include "apps/studio/server_context.hpp"
#include "apps/studio/session_history.hpp"
#include "apps/studio/session_ops.hpp"
#include "apps/studio/static_files.hpp"

namespace tessera_studio {
namespace {

constexpr size_t max_name_length = 100;

void create_session(ServerContext& ctx, const RouteRequest& r, httplib::Response& res) {
    const Json body = parse_body(r.body);
    check_keys(body, {"canvas", "options"});
    const std::string canvas = require_string(body, "canvas");
    auto session =
        make_session(ctx.sessions.next_id(), canvas, body.value("options", Json()), ctx.config.root);
    ctx.sessions.add(session);
    send_json(res, 201, {{"id", session->id}, {"dimension", session->dimension}});
}

// The session file of a load request: the body itself, or {"path": P} naming one under the
// root, whose palette paths are relative to its folder (as `tessera brush` reads them);
// those become relative to the root.
SessionFileContent session_file_of(const ServerContext& ctx, const std::string& body) {
    Json doc = parse_body(body);
    if (doc.contains("format") || !doc.contains("path")) return parse_session_file(doc);
    check_keys(doc, {"path"});
    const std::string relative = require_string(doc, "path");
    const ResolvedPath file = resolve_under(ctx.config.root, relative, {".json"});
    if (file.status != 200) throw ApiError(file.status, "path: " + relative + ": " + file.reason);
    const auto text = read_whole_file(file.path);
    if (!text) throw ApiError(404, "path: " + relative + ": cannot be read");
    SessionFileContent content;
    try {
        content = parse_session_file(parse_body(*text));
    } catch (const ApiError& e) {
        throw ApiError(e.status(), relative + ": " + e.what());
    }
    const std::filesystem::path folder = std::filesystem::path(relative).parent_path();
    for (PaletteEntry& entry : content.palette)
        if (entry.source.is_string())
            entry.source = (folder / entry.source.get<std::string>()).lexically_normal().generic_string();
    return content;
}

// A session file's palette and ops on a new session; its ops are replayed as a job.
void load_session(ServerContext& ctx, const RouteRequest& r, httplib::Response& res) {
    const SessionFileContent content = session_file_of(ctx, r.body);
    auto session = make_session(ctx.sessions.next_id(), content.canvas, content.options, ctx.config.root);
    for (const PaletteEntry& entry : content.palette) {
        const auto exemplar = load_palette_exemplar(entry.source, "palette." + entry.name, ctx.config.root);
        add_palette_entry(*session, entry, exemplar);
    }
    std::vector<OpRequest> ops;
    for (size_t k = 0; k < content.ops.size(); ++k)
        ops.push_back(parse_op(content.ops[k], session->dimension, "ops[" + std::to_string(k) + "]"));
    ctx.sessions.add(session);
    Json job;
    if (!ops.empty()) {
        try {
            // Its ops are where the session starts, not a step to undo.
            job = start_ops_job(ctx, session, std::move(ops), StepOf{std::nullopt, false});
        } catch (...) {
            ctx.sessions.remove(session->id);  // nothing half-loaded stays
            throw;
        }
    }
    send_json(res, 201, {{"id", session->id}, {"dimension", session->dimension}, {"job", job}});
}

void delete_session(ServerContext& ctx, const RouteRequest& r, httplib::Response& res) {
    const auto session = ctx.sessions.remove(r.params[0]);
    if (!session) throw ApiError(404, "no session '" + r.params[0] + "'");
    std::string job;
    {
        std::lock_guard lock(session->mutex);
        job = session->job;
    }
    if (const auto running = job.empty() ? nullptr : ctx.jobs.find(job)) running->cancel();
    send_json(res, 200, {{"deleted", session->id}});
}

void add_palette(ServerContext& ctx, const RouteRequest& r, httplib::Response& res) {
    const auto session = find_session(ctx.sessions, r.params[0]);
    const Json body = parse_body(r.body);
    check_keys(body, {"name", "path", "exemplar"});
    const std::string name = require_string(body, "name");
    if (name.empty() || name.size() > max_name_length) bad_request("name: 1 to 100 characters");
    if (body.contains("path") == body.contains("exemplar")) bad_request("give one of path or exemplar");
    const std::string key = body.contains("path") ? "path" : "exemplar";
    const tessera::Exemplar exemplar = load_palette_exemplar(body[key], key, ctx.config.root);
    add_palette_entry(*session, {name, body[key], 0.0, nullptr}, exemplar);
    send_json(res, 201,
              {{"name", name}, {"dimension", exemplar.dimension}, {"elements", exemplar.elements.size()}});
}

// The op's undo group ("group": an integer >= 0 the client picks per gesture), taken out of
// the body: the op itself is what a session file stores.
std::optional<std::int64_t> take_group(Json& body) {
    const auto it = body.is_object() ? body.find("group") : body.end();
    if (it == body.end()) return std::nullopt;
    if (!it->is_number_integer() || it->get<std::int64_t>() < 0)
        bad_request("group: expected an integer >= 0, got " + it->dump());
    const std::int64_t group = it->get<std::int64_t>();
    body.erase(it);
    return group;
}

void run_op(ServerContext& ctx, const RouteRequest& r, httplib::Response& res) {
    const auto session = find_session(ctx.sessions, r.params[0]);
    Json body = parse_body(r.body);
    const std::optional<std::int64_t> group = take_group(body);
    OpRequest op = parse_op(body, session->dimension);
    if (runs_in_request(*session, op)) {
        send_json(res, 200, apply_now(*session, op, group));
        return;
    }
    std::vector<OpRequest> ops;
    ops.push_back(std::move(op));
    send_json(res, 202, {{"job", start_ops_job(ctx, session, std::move(ops), StepOf{group, true})}});
}

void export_session(ServerContext& ctx, const RouteRequest& r, httplib::Response& res) {
    const auto session = find_session(ctx.sessions, r.params[0]);
    const Json body = parse_body(r.body);
    check_keys(body, {"format"});
    const std::string format = require_string(body, "format");
    const auto scratch =
        std::filesystem::temp_directory_path() /
        ("tessera-studio-" + std::to_string(::getpid()) + "-" + std::to_string(++ctx.exports));
    const ExportedFile file = export_arrangement(*session, format, scratch);
    res.status = 200;
    res.set_header("Content-Disposition", "attachment; filename=\"" + session->id + "." + format + "\"");
    res.set_content(file.body, file.content_type.c_str());
}

}  // namespace

std::string start_ops_job(ServerContext& ctx, const std::shared_ptr<Session>& session,
                          std::vector<OpRequest> ops, StepOf step) {
    const std::string id = ctx.job_ids.next();
    JobRunner::Work work = prepare_job(session, std::move(ops), id, step);  // 409 when busy
    if (!ctx.jobs.start(id, session->id, std::move(work))) {
        release_job(*session, id);
        throw ApiError(503,
                       std::to_string(ctx.config.max_jobs) + " jobs are running; try again when one ends");
    }
    return id;
}

void add_session_routes(Router& router, ServerContext& ctx) {
    const std::string one = "/api/sessions/{}";
    router.add("GET", "/api/sessions", [&ctx](const RouteRequest&, httplib::Response& res) {
        send_json(res, 200, {{"sessions", ctx.sessions.ids()}});
    });
    router.add("POST", "/api/sessions",
               [&ctx](const RouteRequest& r, httplib::Response& res) { create_session(ctx, r, res); });
    router.add("POST", "/api/sessions/load",
               [&ctx](const RouteRequest& r, httplib::Response& res) { load_session(ctx, r, res); });
    router.add("GET", one, [&ctx](const RouteRequest& r, httplib::Response& res) {
        send_json(res, 200, session_view(*find_session(ctx.sessions, r.params[0])));
    });
    router.add("DELETE", one,
               [&ctx](const RouteRequest& r, httplib::Response& res) { delete_session(ctx, r, res); });
    router.add("POST", one + "/palette",
               [&ctx](const RouteRequest& r, httplib::Response& res) { add_palette(ctx, r, res); });
    router.add("POST", one + "/ops",
               [&ctx](const RouteRequest& r, httplib::Response& res) { run_op(ctx, r, res); });
    router.add("POST", one + "/undo", [&ctx](const RouteRequest& r, httplib::Response& res) {
        send_json(res, 200, undo_step(*find_session(ctx.sessions, r.params[0])));
    });
    router.add("POST", one + "/redo", [&ctx](const RouteRequest& r, httplib::Response& res) {
        send_json(res, 200, redo_step(*find_session(ctx.sessions, r.params[0])));
    });
    router.add("GET", one + "/file", [&ctx](const RouteRequest& r, httplib::Response& res) {
        const auto session = find_session(ctx.sessions, r.params[0]);
        res.set_header("Content-Disposition", "attachment; filename=\"" + session->id + ".brush.json\"");
        send_json(res, 200, session_file(*session));
    });
    router.add("POST", one + "/export",
               [&ctx](const RouteRequest& r, httplib::Response& res) { export_session(ctx, r, res); });
}

}  // namespace tessera_studio
