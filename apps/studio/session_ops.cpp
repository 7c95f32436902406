// apps/studio/session_ops.cpp — operations on sessions (session_ops.hpp).
#include "apps/studio/session_ops.hpp"

#include <algorithm>

#include "apps/studio/canvas_changes.hpp"
#include "apps/studio/canvas_spec.hpp"
#include "apps/studio/paint_estimate.hpp"
#include "apps/studio/session_history.hpp"
#include "apps/studio/static_files.hpp"
#include "tessera/error.hpp"
#include "tessera/io.hpp"

namespace tessera_studio {
namespace fs = std::filesystem;

namespace {

// Runs library code, turning its refusals into 400s.
template <class Work>
auto library_call(Work&& work) -> decltype(work()) {
    try {
        return work();
    } catch (const tessera::Error& e) {
        if (e.kind() == tessera::ErrorKind::internal || e.kind() == tessera::ErrorKind::cancelled) throw;
        bad_request(e.what());
    }
}

tessera::BrushReport apply_op(tessera::BrushCanvas& canvas, const ResolvedOp& op) {
    const OpRequest& r = op.request;
    if (r.op == "paint") return canvas.paint(op.exemplars.front(), r.stroke);
    if (r.op == "direction") return canvas.direct(r.stroke);
    if (r.op == "erase") return canvas.erase(r.stroke);
    if (r.op == "fill") return canvas.fill(op.exemplars);
    return canvas.optimize(r.iterations);
}

// Applies `ops` in order to `canvas`, the progress of op k scaled into [k/n, (k+1)/n].
Json apply_all(tessera::BrushCanvas& canvas, const std::vector<ResolvedOp>& ops,
               const tessera::Progress& progress) {
    const double n = static_cast<double>(ops.size());
    tessera::BrushReport total;
    for (size_t k = 0; k < ops.size(); ++k) {
        const auto scaled = [&, k](const tessera::ProgressEvent& e) {
            tessera::ProgressEvent s = e;
            s.fraction = (static_cast<double>(k) + std::clamp(e.fraction, 0.0, 1.0)) / n;
            return progress(s);
        };
        tessera::ProgressEvent start;
        start.stage = ops[k].request.op;
        start.iteration = -1;
        start.fraction = static_cast<double>(k) / n;
        if (!progress(start)) throw tessera::Cancelled();
        canvas.set_progress(scaled);
        const tessera::BrushReport r = apply_op(canvas, ops[k]);
        total.added += r.added;
        total.removed += r.removed;
        total.iterations += r.iterations;
        total.lbfgs_bound_hits += r.lbfgs_bound_hits;
        total.energy = r.energy;
        total.seconds += r.seconds;
    }
    canvas.set_progress({});
    Json report = report_json(total);
    report["ops"] = ops.size();
    return report;
}

}  // namespace

std::shared_ptr<Session> make_session(const std::string& id, const std::string& canvas_text,
                                      const Json& options, const fs::path& root) {
    Canvas canvas = parse_canvas(canvas_text, root);
    tessera::BrushOptions brush_options;
    if (!options.is_null()) apply_brush_options(options, canvas.dimension, brush_options);
    return library_call([&] {
        return std::make_shared<Session>(id, canvas.text, canvas.dimension,
                                         tessera::BrushCanvas(canvas.domain, brush_options));
    });
}

void add_palette_entry(Session& session, PaletteEntry entry, const tessera::Exemplar& exemplar) {
    std::lock_guard lock(session.mutex);
    check_idle(session);
    library_call([&] { return session.canvas.add_exemplar(entry.name, exemplar); });
    entry.density = exemplar_density(exemplar);
    entry.exemplar = std::make_shared<const tessera::Exemplar>(exemplar);
    session.palette.push_back(std::move(entry));
}

ResolvedOp resolve_op(const Session& session, OpRequest request) {
    ResolvedOp op{std::move(request), {}};
    for (const std::string& name : op.request.palette) {
        const int index = session.canvas.find_exemplar(name);
        if (index < 0) bad_request("palette: no entry '" + name + "' in session " + session.id);
        op.exemplars.push_back(index);
    }
    // Recorded as run: a session file replays the same count whatever its options say.
    if (op.request.op == "optimize" && op.request.iterations < 0)
        op.request.iterations = session.canvas.options().iterations;
    return op;
}

Json apply_now(Session& session, const OpRequest& request, std::optional<std::int64_t> group) {
    std::lock_guard lock(session.mutex);
    check_idle(session);
    const ResolvedOp op = resolve_op(session, request);
    std::optional<SessionState> state = state_before(session, group);
    const CanvasMark before = mark_canvas(session.canvas);
    const tessera::BrushReport report = library_call([&] { return apply_op(session.canvas, op); });
    session.ops.push_back(op_json(op.request, session.dimension));
    commit_step(session, std::move(state), group);
    return {{"report", report_json(report)}, {"changes", appended_since(session.canvas, before)}};
}

bool runs_in_request(Session& session, const OpRequest& request) {
    if (request.op == "direction" || request.op == "erase") return true;
    if (request.op != "paint") return false;
    std::lock_guard lock(session.mutex);
    const auto entry = std::find_if(session.palette.begin(), session.palette.end(),
                                    [&](const PaletteEntry& e) { return e.name == request.palette.front(); });
    if (entry == session.palette.end()) return false;  // the job will say it is unknown
    return expected_paint_elements(request.stroke, entry->density, session.dimension,
                                   session.canvas.options().stroke_width) <= max_inline_paint_elements;
}

JobRunner::Work prepare_job(const std::shared_ptr<Session>& session, std::vector<OpRequest> requests,
                            const std::string& job_id, StepOf step) {
    std::lock_guard lock(session->mutex);
    check_idle(*session);
    std::vector<ResolvedOp> ops;
    for (OpRequest& r : requests) ops.push_back(resolve_op(*session, std::move(r)));
    auto copy = std::make_shared<tessera::BrushCanvas>(session->canvas);
    session->job = job_id;
    return [session, ops = std::move(ops), copy, job_id, step](const tessera::Progress& progress) {
        Json report;
        try {
            report = apply_all(*copy, ops, progress);
        } catch (...) {
            release_job(*session, job_id);  // the canvas stays as it was
            throw;
        }
        std::lock_guard lock(session->mutex);
        // The canvas the job started from is the step's state before (no copy to make).
        std::optional<SessionState> before;
        if (step.undoable && starts_step(*session, step.group))
            before = SessionState{std::move(session->canvas), session->ops, session->palette.size()};
        session->canvas = std::move(*copy);
        for (const ResolvedOp& op : ops) session->ops.push_back(op_json(op.request, session->dimension));
        if (step.undoable) commit_step(*session, std::move(before), step.group);
        session->job.clear();
        return report;
    };
}

void release_job(Session& session, const std::string& job_id) {
    std::lock_guard lock(session.mutex);
    if (session.job == job_id) session.job.clear();
}

Json session_view(Session& session) {
    std::lock_guard lock(session.mutex);
    const tessera::BrushCanvas& canvas = session.canvas;
    Json palette = Json::array();
    for (const PaletteEntry& e : session.palette)
        palette.push_back({{"name", e.name}, {"source", e.source.is_string() ? e.source : Json("inline")}});
    Json directions = Json::array();
    for (const tessera::Vec3& d : canvas.sample_directions()) directions.push_back({d.x, d.y, d.z});
    return {{"id", session.id},
            {"canvas", session.canvas_text},
            {"dimension", session.dimension},
            {"options", brush_options_json(canvas.options())},
            {"palette", std::move(palette)},
            {"ops", session.ops.size()},
            {"undo", session.undo.size()},
            {"redo", session.redo.size()},
            {"job", session.job.empty() ? Json() : Json(session.job)},
            {"arrangement", Json::parse(tessera::to_json(canvas.arrangement()))},
            {"directions", std::move(directions)},
            {"exemplars", canvas.sample_exemplars()}};
}

Json session_file(Session& session) {
    std::lock_guard lock(session.mutex);
    Json palette = Json::object();
    for (const PaletteEntry& e : session.palette) palette[e.name] = e.source;
    return {{"format", "tessera-brush"},
            {"version", 1},
            {"canvas", session.canvas_text},
            {"palette", std::move(palette)},
            {"options", brush_options_json(session.canvas.options())},
            {"ops", session.ops}};
}

SessionFileContent parse_session_file(const Json& doc) {
    check_keys(doc, {"format", "version", "canvas", "palette", "options", "ops"});
    if (require_string(doc, "format") != "tessera-brush")
        bad_request("format: expected \"tessera-brush\", got \"" + doc["format"].get<std::string>() + "\"");
    const Json& version = require(doc, "version");
    if (!version.is_number_integer() || version.get<long long>() != 1) bad_request("version: expected 1");
    SessionFileContent content;
    content.canvas = require_string(doc, "canvas");
    content.options = doc.contains("options") ? doc["options"] : Json();
    if (const auto it = doc.find("palette"); it != doc.end()) {
        if (!it->is_object()) bad_request("palette: expected an object {name: path or exemplar}");
        for (const auto& [name, source] : it->items()) content.palette.push_back({name, source, 0.0, nullptr});
    }
    content.ops = doc.contains("ops") ? doc["ops"] : Json::array();
    if (!content.ops.is_array()) bad_request("ops: expected an array");
    return content;
}

ExportedFile export_arrangement(Session& session, const std::string& format, const fs::path& scratch) {
    static const std::vector<std::string> formats = {"json", "csv", "ply", "usda", "gltf",
                                                     "glb",  "obj", "png", "svg"};
    if (std::find(formats.begin(), formats.end(), format) == formats.end())
        bad_request("format: expected json, csv, ply, usda, gltf, glb, obj, png or svg, got '" + format +
                    "'");
    tessera::Arrangement arrangement;
    {
        std::lock_guard lock(session.mutex);
        arrangement = session.canvas.arrangement();  // written outside the lock
    }
    // A folder of its own: a writer may leave side files (a glTF buffer) next to its output.
    std::error_code ignored;
    fs::create_directories(scratch, ignored);
    const fs::path file = scratch / ("arrangement." + format);
    struct Cleanup {
        fs::path dir;
        ~Cleanup() {
            std::error_code e;
            fs::remove_all(dir, e);
        }
    } cleanup{scratch};
    library_call([&] { tessera::save(arrangement, file.string()); });
    auto body = read_whole_file(file);
    if (!body)
        throw tessera::Error(tessera::ErrorKind::io, "cannot read back the exported " + format + " file");
    return {std::move(*body), content_type_for("." + format), file.filename().string()};
}

}  // namespace tessera_studio
