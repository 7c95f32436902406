// apps/studio/api_json.cpp — checks of the studio's JSON requests (api_json.hpp).
#include "apps/studio/api_json.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

#include "tessera/error.hpp"

namespace tessera_studio {
namespace {

// Bounds that keep one request's work and memory proportional to its (capped) body.
constexpr size_t max_stroke_points = 100000;
constexpr int max_iterations = 100000;
constexpr size_t max_name_length = 100;

std::string member(const std::string& where, const std::string& key) {
    return where.empty() ? key : where + "." + key;
}

const char* type_name(const Json& value) {
    if (value.is_null()) return "null";
    if (value.is_boolean()) return "true/false";
    if (value.is_number()) return "a number";
    if (value.is_string()) return "text";
    if (value.is_array()) return "an array";
    return "an object";
}

// A JSON value in the form the option table takes: integers as int64 (uint64 above its
// range, for seeds), other numbers as double.
tessera::OptionValue option_value(const Json& value, const std::string& as_written) {
    if (value.is_boolean()) return value.get<bool>();
    if (value.is_number_unsigned()) {
        const auto u = value.get<std::uint64_t>();
        if (u <= static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
            return static_cast<std::int64_t>(u);
        return u;
    }
    if (value.is_number_integer()) return value.get<std::int64_t>();
    if (value.is_number_float()) return value.get<double>();
    if (value.is_string()) return value.get<std::string>();
    bad_request(as_written + ": expected a number, text or true/false, got " + type_name(value));
}

Json to_json_value(const tessera::OptionValue& value) {
    return std::visit([](const auto& v) { return Json(v); }, value);
}

double finite_number(const Json& value, const std::string& where) {
    if (!value.is_number()) bad_request(where + ": expected a number, got " + type_name(value));
    const double x = value.get<double>();
    if (!std::isfinite(x)) bad_request(where + ": expected a finite number");
    return x;
}

tessera::Vec3 stroke_point(const Json& value, int dimension, const std::string& where) {
    const size_t n = value.is_array() ? value.size() : 0;
    const bool ok = dimension == 3 ? n == 3 : (n == 2 || n == 3);
    if (!ok)
        bad_request(where + ": expected " + (dimension == 3 ? "[x, y, z]" : "[x, y] or [x, y, 0]") +
                    " on a " + std::to_string(dimension) + "D canvas");
    tessera::Vec3 p{finite_number(value[0], where + "[0]"), finite_number(value[1], where + "[1]"), 0.0};
    if (n == 3) p.z = finite_number(value[2], where + "[2]");
    if (dimension == 2 && p.z != 0.0) bad_request(where + ": z must be 0 on a 2D canvas");
    return p;
}

tessera::Stroke parse_stroke(const Json& body, int dimension, const std::string& where) {
    const Json& points = require(body, "stroke", where);
    const std::string at = member(where, "stroke");
    if (!points.is_array() || points.empty()) bad_request(at + ": expected a non-empty array of points");
    if (points.size() > max_stroke_points)
        bad_request(at + ": at most " + std::to_string(max_stroke_points) + " points");
    tessera::Stroke stroke;
    for (size_t k = 0; k < points.size(); ++k)
        stroke.points.push_back(stroke_point(points[k], dimension, at + "[" + std::to_string(k) + "]"));
    if (const auto it = body.find("width"); it != body.end()) {
        stroke.width = finite_number(*it, member(where, "width"));
        if (stroke.width < 0) bad_request(member(where, "width") + ": must be >= 0 (0 = the default width)");
    }
    return stroke;
}

std::vector<std::string> parse_palette_names(const Json& value, const std::string& where) {
    if (value.is_string()) return {value.get<std::string>()};
    if (!value.is_array()) bad_request(where + ": expected a palette name or an array of names");
    std::vector<std::string> names;
    for (size_t k = 0; k < value.size(); ++k) {
        if (!value[k].is_string())
            bad_request(where + "[" + std::to_string(k) + "]: expected a palette name");
        names.push_back(value[k].get<std::string>());
    }
    return names;
}

int parse_iterations(const Json& value, const std::string& where) {
    if (!value.is_number_integer() || value.get<std::int64_t>() < 0 ||
        value.get<std::int64_t>() > max_iterations)
        bad_request(where + ": expected an integer from 0 to " + std::to_string(max_iterations));
    return static_cast<int>(value.get<std::int64_t>());
}

}  // namespace

void bad_request(const std::string& message) {
    throw ApiError(400, message);
}

Json parse_body(const std::string& body) {
    Json doc;
    try {
        doc = Json::parse(body);
    } catch (const Json::parse_error& e) {
        // nlohmann's message starts with "[json.exception.parse_error.101] parse error at line 1, ...".
        std::string what = e.what();
        const size_t start = what.find("] ");
        bad_request("malformed JSON body: " + (start == std::string::npos ? what : what.substr(start + 2)));
    }
    if (!doc.is_object()) bad_request(std::string("the body must be a JSON object, got ") + type_name(doc));
    return doc;
}

const Json& require(const Json& object, const std::string& key, const std::string& where) {
    const auto it = object.find(key);
    if (it == object.end()) bad_request(member(where, key) + ": missing");
    return *it;
}

std::string require_string(const Json& object, const std::string& key, const std::string& where) {
    const Json& value = require(object, key, where);
    if (!value.is_string()) bad_request(member(where, key) + ": expected text, got " + type_name(value));
    return value.get<std::string>();
}

void check_keys(const Json& object, const std::vector<std::string>& allowed, const std::string& where) {
    for (const auto& [key, value] : object.items()) {
        bool known = false;
        for (const std::string& a : allowed) known = known || a == key;
        if (!known) bad_request(member(where, key) + ": unknown member");
    }
}

void apply_brush_options(const Json& options, int dimension, tessera::BrushOptions& target) {
    if (!options.is_object())
        bad_request(std::string("options: expected an object, got ") + type_name(options));
    const auto& table = tessera::brush_option_table();
    for (const auto& [name, value] : options.items()) {
        const std::string as_written = "options." + name;
        const auto* spec = tessera::find_option(table, name);
        if (!spec) bad_request(as_written + ": unknown option");
        try {
            tessera::set_option(*spec, target, option_value(value, as_written),
                                tessera::OptionContext{as_written, dimension});
        } catch (const tessera::Error& e) {
            bad_request(e.what());  // the table's message names as_written
        }
    }
}

Json brush_options_json(const tessera::BrushOptions& options) {
    Json out = Json::object();
    for (const auto& spec : tessera::brush_option_table()) out[spec.name] = to_json_value(spec.get(options));
    return out;
}

OpRequest parse_op(const Json& body, int dimension, const std::string& where) {
    if (!body.is_object()) bad_request((where.empty() ? "the op" : where) + ": expected an object");
    OpRequest op;
    op.op = require_string(body, "op", where);
    const std::string palette_at = member(where, "palette");
    if (op.op == "paint") {
        check_keys(body, {"op", "palette", "stroke", "width"}, where);
        op.palette = parse_palette_names(require(body, "palette", where), palette_at);
        if (op.palette.size() != 1) bad_request(palette_at + ": paint takes one palette name");
        op.stroke = parse_stroke(body, dimension, where);
    } else if (op.op == "direction" || op.op == "erase") {
        check_keys(body, {"op", "stroke", "width"}, where);
        op.stroke = parse_stroke(body, dimension, where);
    } else if (op.op == "fill") {
        check_keys(body, {"op", "palette"}, where);
        if (const auto it = body.find("palette"); it != body.end())
            op.palette = parse_palette_names(*it, palette_at);
    } else if (op.op == "optimize") {
        check_keys(body, {"op", "iterations"}, where);
        if (const auto it = body.find("iterations"); it != body.end())
            op.iterations = parse_iterations(*it, member(where, "iterations"));
    } else {
        bad_request(member(where, "op") + ": expected paint, direction, erase, fill or optimize, got '" +
                    op.op + "'");
    }
    for (const std::string& name : op.palette)
        if (name.empty() || name.size() > max_name_length)
            bad_request(palette_at + ": a name of 1 to 100 characters");
    return op;
}

Json op_json(const OpRequest& op, int dimension) {
    Json out = {{"op", op.op}};
    if (op.op == "paint") out["palette"] = op.palette.front();
    if (op.op == "fill" && !op.palette.empty()) out["palette"] = op.palette;
    if (op.op == "optimize" && op.iterations >= 0) out["iterations"] = op.iterations;
    if (!op.stroke.points.empty()) {
        Json points = Json::array();
        for (const tessera::Vec3& p : op.stroke.points)
            points.push_back(dimension == 3 ? Json{p.x, p.y, p.z} : Json{p.x, p.y});
        out["stroke"] = std::move(points);
        if (op.stroke.width > 0) out["width"] = op.stroke.width;
    }
    return out;
}

Json report_json(const tessera::BrushReport& report) {
    return {{"added", report.added},           {"removed", report.removed},
            {"iterations", report.iterations}, {"lbfgs_bound_hits", report.lbfgs_bound_hits},
            {"energy", report.energy},         {"seconds", report.seconds}};
}

}  // namespace tessera_studio
