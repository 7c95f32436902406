// Brush session files (tessera/brush.hpp, docs/brush.md "Session files"): reading and
// replaying them. A session file is what the studio saves and `tessera brush` replays.
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <optional>

#include "tessera/brush.hpp"
#include "tessera/det.hpp"
#include "tessera/error.hpp"
#include "tessera/io.hpp"
#include "tessera/option_table.hpp"
#include "tessera/option_text.hpp"

namespace tessera {

namespace {

// Ordered: the palette's entries are the canvas's in the file's order (kappa, the order of
// the arrangement's types), as the studio writes and reads them; a sorted object replayed a
// studio session whose entries were not added in alphabetical order to another arrangement.
using Json = nlohmann::ordered_json;

struct Reader {
    std::string source;
    int dimension = 2;

    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw Error(ErrorKind::input, source + ": " + where + ": " + what);
    }
    const Json& require(const Json& o, const std::string& key, const std::string& where) const {
        if (!o.contains(key)) fail(where, "missing \"" + key + "\"");
        return o[key];
    }
    Vec3 point(const Json& p, const std::string& where) const {
        if (!p.is_array() || static_cast<int>(p.size()) != dimension)
            fail(where, "must be a point of " + std::to_string(dimension) + " numbers, got " + p.dump());
        Vec3 v;
        for (int a = 0; a < dimension; ++a) {
            if (!p[a].is_number()) fail(where, "must be a point of numbers, got " + p.dump());
            v[a] = p[a].get<double>();
        }
        return v;
    }
    Stroke stroke(const Json& op, const std::string& where) const {
        Stroke s;
        const Json& points = require(op, "stroke", where);
        if (!points.is_array()) fail(where + ".stroke", "must be an array of points");
        for (size_t k = 0; k < points.size(); ++k) s.points.push_back(point(points[k], where + ".stroke[" + std::to_string(k) + "]"));
        if (op.contains("width")) {
            if (!op["width"].is_number() || !(op["width"].get<double>() >= 0.0))
                fail(where + ".width", "must be a number >= 0, got " + op["width"].dump());
            s.width = op["width"].get<double>();
        }
        return s;
    }
    int entry(const BrushSession& session, const Json& name, const std::string& where) const {
        if (!name.is_string()) fail(where, "must name a palette entry, got " + name.dump());
        for (size_t i = 0; i < session.palette_names.size(); ++i)
            if (session.palette_names[i] == name.get<std::string>()) return static_cast<int>(i);
        fail(where, "no palette entry named '" + name.get<std::string>() + "'");
    }
};

OptionValue option_value(const Json& v, const Reader& r, const std::string& where) {
    if (v.is_boolean()) return v.get<bool>();
    // nlohmann reads every non-negative integer as unsigned; only a seed above int64's range
    // needs to stay one (tessera/option_table.hpp, OptionValue).
    if (v.is_number_unsigned() && v.get<std::uint64_t>() > static_cast<std::uint64_t>(INT64_MAX))
        return v.get<std::uint64_t>();
    if (v.is_number_integer()) return v.get<std::int64_t>();
    if (v.is_number()) return v.get<double>();
    if (v.is_string()) return v.get<std::string>();
    r.fail(where, "must be a number, a flag or text, got " + v.dump());
}

void read_options(const Json& doc, const Reader& r, BrushOptions& options) {
    if (!doc.contains("options")) return;
    const Json& o = doc["options"];
    if (!o.is_object()) r.fail("options", "must be an object");
    for (const auto& [name, value] : o.items()) {
        const auto* spec = find_option(brush_option_table(), name);
        if (!spec) r.fail("options." + name, "is not an option of brushing (docs/brush.md)");
        set_option(*spec, options, option_value(value, r, "options." + name), OptionContext{"options." + name, r.dimension});
    }
}

void read_palette(const Json& doc, const Reader& r, const std::string& base_dir, BrushSession& session) {
    const Json& palette = r.require(doc, "palette", "session");
    if (!palette.is_object() || palette.empty()) r.fail("palette", "must be an object of name: exemplar file");
    for (const auto& [name, value] : palette.items()) {
        Exemplar ex;
        if (value.is_string()) {
            const std::filesystem::path p = value.get<std::string>();
            ex = load((p.is_absolute() ? p : std::filesystem::path(base_dir) / p).string());
        } else if (value.is_object()) {
            ex = parse_json(value.dump(), r.source + ": palette." + name);
        } else {
            r.fail("palette." + name, "must be an exemplar file's path or an exemplar object");
        }
        session.palette_names.push_back(name);
        session.palette.push_back(std::move(ex));
    }
}

BrushSession::Op read_op(const Json& op, const Reader& r, const BrushSession& session, const std::string& where) {
    if (!op.is_object()) r.fail(where, "must be an object");
    BrushSession::Op out;
    const Json& kind = r.require(op, "op", where);
    out.kind = kind.is_string() ? kind.get<std::string>() : "";
    if (out.kind == "paint") {
        out.exemplars.push_back(r.entry(session, r.require(op, "palette", where), where + ".palette"));
        out.stroke = r.stroke(op, where);
    } else if (out.kind == "direction" || out.kind == "erase") {
        out.stroke = r.stroke(op, where);
    } else if (out.kind == "fill") {
        if (op.contains("palette")) {
            const Json& names = op["palette"];
            if (names.is_array())
                for (size_t k = 0; k < names.size(); ++k)
                    out.exemplars.push_back(r.entry(session, names[k], where + ".palette[" + std::to_string(k) + "]"));
            else
                out.exemplars.push_back(r.entry(session, names, where + ".palette"));
        }
    } else if (out.kind == "optimize") {
        const Json& n = r.require(op, "iterations", where);
        if (!n.is_number_integer() || n.get<int>() < 0) r.fail(where + ".iterations", "must be an integer >= 0");
        out.iterations = n.get<int>();
    } else {
        r.fail(where + ".op", "must be paint, direction, erase, fill or optimize, got " + kind.dump());
    }
    return out;
}

// "surface:FILE[,thickness[,resolution]]": FILE, then the trailing comma-separated numbers
// (a file name may hold commas), as the --domain forms mesh: and shell: are split.
struct SurfaceForm {
    std::string file;
    std::vector<double> numbers;
};

std::optional<SurfaceForm> surface_form(const std::string& canvas, const std::string& source) {
    const std::string prefix = "surface:";
    if (canvas.rfind(prefix, 0) != 0) return std::nullopt;
    SurfaceForm form{canvas.substr(prefix.size()), {}};
    for (size_t comma = form.file.rfind(','); comma != std::string::npos && form.numbers.size() < 2;
         comma = form.file.rfind(',')) {
        const std::string field = form.file.substr(comma + 1);
        char* end = nullptr;
        const double x = std::strtod(field.c_str(), &end);
        if (field.empty() || end != field.c_str() + field.size()) break;
        form.numbers.insert(form.numbers.begin(), x);
        form.file.resize(comma);
    }
    if (form.file.empty() || (!form.numbers.empty() && !(form.numbers[0] > 0.0)) ||
        (form.numbers.size() == 2 && form.numbers[1] != std::floor(form.numbers[1])))
        throw Error(ErrorKind::input, source + ": canvas: expected surface:FILE[,thickness[,resolution]] with "
                                               "thickness > 0, got '" + canvas + "'");
    return form;
}

// The band of a surface canvas when the session gives none: the largest palette spacing, so
// that every entry's layer and its neighbourhoods' curvature fit in it.
double default_thickness(const BrushSession& session) {
    double t = 0.0;
    for (const Exemplar& e : session.palette)
        if (e.elements.size() > 1) {
            Exemplar positioned = e;
            positioned.update_positions();
            t = std::max(t, mean_nearest_neighbor_distance(positioned));
        }
    return t > 0.0 ? t : 1.0;
}

Domain canvas_domain(const BrushSession& session) {
    const auto form = surface_form(session.canvas, "canvas");
    if (!form) return parse_output_domain(session.canvas, session.palette.front(), 1.0, "canvas");
    if (session.dimension != 3) throw Error(ErrorKind::input, "canvas: a surface canvas needs 3D palette entries");
    const std::filesystem::path p = form->file;
    const std::string file = (p.is_absolute() ? p : std::filesystem::path(session.base_dir) / p).string();
    const double thickness = form->numbers.empty() ? default_thickness(session) : form->numbers[0];
    const int resolution = form->numbers.size() == 2 ? static_cast<int>(form->numbers[1]) : 128;
    return Domain::shell(file, thickness, resolution);
}

}  // namespace

BrushSession parse_brush_session(const std::string& text, const std::string& source, const std::string& base_dir) {
    Json doc;
    try {
        doc = Json::parse(text);
    } catch (const Json::parse_error& e) {
        throw Error(ErrorKind::input, source + ": not valid JSON (" + std::string(e.what()) + ")");
    }
    Reader r{source, 2};
    if (!doc.is_object() || doc.value("format", "") != "tessera-brush")
        r.fail("format", "a session file has \"format\": \"tessera-brush\"");
    BrushSession session;
    read_palette(doc, r, base_dir, session);
    session.dimension = r.dimension = session.palette.front().dimension;
    for (size_t i = 1; i < session.palette.size(); ++i)
        if (session.palette[i].dimension != session.dimension)
            r.fail("palette." + session.palette_names[i], "mixes 2D and 3D exemplars");
    const Json& canvas = r.require(doc, "canvas", "session");
    if (!canvas.is_string()) r.fail("canvas", "must be a domain as --domain writes it (\"box:0,0,60,40\")");
    session.canvas = canvas.get<std::string>();
    session.base_dir = base_dir;
    surface_form(session.canvas, source);  // its syntax checked here, its file read at replay
    read_options(doc, r, session.options);
    const Json& ops = r.require(doc, "ops", "session");
    if (!ops.is_array()) r.fail("ops", "must be an array of operations");
    for (size_t i = 0; i < ops.size(); ++i) session.ops.push_back(read_op(ops[i], r, session, "ops[" + std::to_string(i) + "]"));
    return session;
}

BrushSession read_brush_session(const std::string& path) {
    const std::string base = std::filesystem::path(path).parent_path().string();
    return parse_brush_session(read_file(path), path, base.empty() ? "." : base);
}

BrushCanvas replay_brush_session(const BrushSession& session, const Progress& progress) {
    const Domain domain = canvas_domain(session);
    BrushCanvas canvas(domain, session.options);
    for (size_t i = 0; i < session.palette.size(); ++i) canvas.add_exemplar(session.palette_names[i], session.palette[i]);
    canvas.set_progress(progress);
    for (const BrushSession::Op& op : session.ops) {
        if (op.kind == "paint") canvas.paint(op.exemplars.front(), op.stroke);
        else if (op.kind == "direction") canvas.direct(op.stroke);
        else if (op.kind == "erase") canvas.erase(op.stroke);
        else if (op.kind == "fill") canvas.fill(op.exemplars);
        else if (op.kind == "optimize") canvas.optimize(op.iterations);
    }
    return canvas;
}

}  // namespace tessera
