// io/json_format.cpp — the native JSON format ("format": "tessera", version 1),
// documented field by field in docs/format.md. It is the one format that carries
// everything in the data model (types and their flags, domain, pose, attributes,
// ids, locks, time stamps), so a save + load through it is lossless.
//
// The reader is strict: unknown keys, wrong types and out-of-range values are
// errors naming the file and the JSON path ("elements[3].radius"), because a
// silently ignored typo ("raduis") would quietly change a synthesis result.
// The writer puts one element per line: readable, diffable, and still a plain
// JSON document; doubles are written in the shortest form that reads back exactly.
// Animated documents (a top-level "frames" array) are read and written by
// animation_json.cpp through the pieces exposed in io_util.hpp; parse_json gives their
// frame 0, so that every command reading an exemplar accepts them.
#include <algorithm>
#include <filesystem>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "io/io_util.hpp"
#include "tessera/animation.hpp"
#include "tessera/error.hpp"
#include "tessera/io.hpp"
#include "tessera/render.hpp"

namespace tessera {

using namespace io_detail;

namespace {

using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

constexpr int format_version = 1;

// Element type topologies by name, as "topology" holds them (automatic is the default
// and is never written).
constexpr std::pair<ElementTopology, const char*> topology_names[] = {
    {ElementTopology::none, "none"}, {ElementTopology::thread, "thread"}, {ElementTopology::sheet, "sheet"}};

class JsonReader {
public:
    explicit JsonReader(const std::string& source, int dimension = 2) : source_(source), dimension_(dimension) {}

    Domain read_domain_document(const std::string& text, int dimension) {
        dimension_ = dimension;
        Json doc = parse(text);
        if (!doc.is_object()) fail("", "the document must be a JSON object");
        if (!doc.contains("type")) doc["type"] = "polygon";
        return read_domain(doc);
    }

    // A static document, or with `frame_samples` an animated one (io_util.hpp).
    Exemplar read(const Json& doc, const JsonFrameSamples* frame_samples = nullptr) {
        frame_samples_ = frame_samples;
        if (!doc.is_object()) fail("", "the document must be a JSON object");
        check_keys(doc,
                   {"format", "version", "dimension", "domain", "types", "attributes", "elements", "stats", "description"},
                   "", frame_samples ? "frames" : nullptr);
        read_header(doc);
        Exemplar ex;
        ex.dimension = dimension_;
        ex.domain = read_domain(require(doc, "domain", ""));
        read_types(doc, ex);
        read_attribute_names(doc, ex);
        read_elements(require(doc, "elements", ""), ex);
        ex.update_positions();
        ex.validate(source_);
        check_topology(ex, source_);
        return ex;
    }

    // The checks below are shared with the animation reader (io_util.hpp).

    // The header of a document (a JSON object); returns the dimension.
    int read_header(const Json& doc) {
        const Json& format = require(doc, "format", "");
        if (!format.is_string() || format.get<std::string>() != "tessera")
            fail("", "not a tessera file (\"format\" must be \"tessera\", got " + format.dump() + ")");
        const Json& version = require(doc, "version", "");
        if (!version.is_number_integer() || version.get<long long>() != format_version)
            fail("", "unsupported version " + version.dump() + " (this build reads version " +
                         std::to_string(format_version) + ")");
        const long long dimension = integer(require(doc, "dimension", ""), "dimension");
        if (dimension != 2 && dimension != 3)
            fail("dimension", "must be 2 or 3, got " + std::to_string(dimension));
        dimension_ = static_cast<int>(dimension);
        return dimension_;
    }

    // Only the keys `allowed` (and `also_allowed`, when given).
    void check_keys(const Json& object, std::initializer_list<const char*> allowed, const std::string& where,
                    const char* also_allowed = nullptr) const {
        for (const auto& item : object.items()) {
            const bool known = std::any_of(allowed.begin(), allowed.end(),
                                           [&](const char* key) { return item.key() == key; });
            if (!known && !(also_allowed && item.key() == also_allowed))
                fail(where, "unknown key '" + item.key() + "'");
        }
    }

    double number(const Json& value, const std::string& where) const {
        if (!value.is_number()) fail(where, "must be a number, got " + value.dump());
        const double x = value.get<double>();
        if (!std::isfinite(x)) fail(where, "is NaN or infinite");
        return x;
    }

    std::uint64_t element_id(const Json& id, const std::string& where) const {
        if (!id.is_number_unsigned()) fail(where, "must be a non-negative integer, got " + id.dump());
        return id.get<std::uint64_t>();
    }

    std::vector<Vec3> element_samples(const Json& e, const std::string& where) const {
        const bool has_position = e.contains("position");
        const bool has_samples = e.contains("samples");
        if (has_position == has_samples)
            fail(where, "needs exactly one of \"position\" (one sample) and \"samples\" (several)");
        if (has_position) return {point(e["position"], member(where, "position"))};
        const Json& samples = array(e["samples"], member(where, "samples"));
        if (samples.empty()) fail(member(where, "samples"), "must not be empty");
        std::vector<Vec3> points;
        for (size_t s = 0; s < samples.size(); ++s)
            points.push_back(point(samples[s], member(where, "samples[" + std::to_string(s) + "]")));
        return points;
    }

    const Json& require(const Json& object, const char* key, const std::string& where) const {
        const auto it = object.find(key);
        if (it == object.end()) fail(where, std::string("missing \"") + key + "\"");
        return *it;
    }

    const Json& array(const Json& value, const std::string& where) const {
        if (!value.is_array()) fail(where, "must be an array, got " + value.dump());
        return value;
    }

    Json parse(const std::string& text) const {
        try {
            return Json::parse(text);
        } catch (const Json::exception& e) {  // parse_error, or out_of_range for 1e400
            // Drop nlohmann's "[json.exception.parse_error.101] " tag; keep "parse error at line L, column C:
            // ...".
            std::string message = e.what();
            const size_t tag_end = message.find("] ");
            if (message.rfind("[json.exception", 0) == 0 && tag_end != std::string::npos)
                message = message.substr(tag_end + 2);
            fail("", "invalid JSON: " + message);
        }
    }

private:
    std::string source_;
    int dimension_ = 2;
    bool types_declared_ = false;
    const JsonFrameSamples* frame_samples_ = nullptr;

    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        fail_input(source_, 0, where.empty() ? what : where + ": " + what);
    }

    static std::string member(const std::string& where, const std::string& key) {
        return where.empty() ? key : where + "." + key;
    }

    std::string string(const Json& value, const std::string& where) const {
        if (!value.is_string()) fail(where, "must be a string, got " + value.dump());
        return value.get<std::string>();
    }

    bool boolean(const Json& value, const std::string& where) const {
        if (!value.is_boolean()) fail(where, "must be true or false, got " + value.dump());
        return value.get<bool>();
    }

    long long integer(const Json& value, const std::string& where) const {
        if (!value.is_number_integer()) fail(where, "must be an integer, got " + value.dump());
        return value.get<long long>();
    }

    // A point of `dimension_` coordinates.
    Vec3 point(const Json& value, const std::string& where) const {
        if (!value.is_array() || value.size() != static_cast<size_t>(dimension_))
            fail(where,
                 "must be an array of " + std::to_string(dimension_) + " numbers, got " + value.dump());
        Vec3 p;
        for (int k = 0; k < dimension_; ++k) {
            const Json& c = value[static_cast<size_t>(k)];
            if (!c.is_number()) fail(where, "must be an array of numbers, got " + value.dump());
            p[k] = c.get<double>();
            if (!std::isfinite(p[k])) fail(where, "coordinate is NaN or infinite");
        }
        return p;
    }

    Domain read_domain(const Json& value) const {
        const std::string where = "domain";
        if (!value.is_object()) fail(where, "must be an object, got " + value.dump());
        const std::string type = string(require(value, "type", where), member(where, "type"));
        const auto need_dimension = [&](int d) {
            if (dimension_ != d)
                fail(member(where, "type"), "a " + type + " domain is " + std::to_string(d) + "D but the file is " +
                                                std::to_string(dimension_) + "D");
        };
        // Files named in the domain are relative to this JSON file's directory.
        const auto file = [&](const char* key) {
            const std::filesystem::path f = string(require(value, key, where), member(where, key));
            if (f.is_absolute() || source_.empty()) return f.string();
            return (std::filesystem::path(source_).parent_path() / f).lexically_normal().string();
        };
        const auto resolution = [&]() {
            const auto it = value.find("resolution");
            return it == value.end() ? 128 : static_cast<int>(integer(*it, member(where, "resolution")));
        };
        const auto scale = [&](Domain d) {
            const auto it = value.find("scale");
            return it == value.end() ? d : d.scaled(number(*it, member(where, "scale")));
        };
        try {
            if (type == "box") {
                check_keys(value, {"type", "min", "max"}, where);
                const Vec3 lo = point(require(value, "min", where), member(where, "min"));
                const Vec3 hi = point(require(value, "max", where), member(where, "max"));
                return Domain::box(lo, hi, dimension_);
            }
            if (type == "polygon") {
                check_keys(value, {"type", "outer", "holes"}, where);
                need_dimension(2);
                const auto ring = [&](const Json& r, const std::string& at) {
                    if (!r.is_array()) fail(at, "must be an array of [x, y] points, got " + r.dump());
                    std::vector<Vec3> points;
                    for (size_t i = 0; i < r.size(); ++i) points.push_back(point(r[i], at + "[" + std::to_string(i) + "]"));
                    return points;
                };
                std::vector<std::vector<Vec3>> holes;
                const auto it = value.find("holes");
                if (it != value.end()) {
                    if (!it->is_array()) fail(member(where, "holes"), "must be an array of rings, got " + it->dump());
                    for (size_t h = 0; h < it->size(); ++h)
                        holes.push_back(ring((*it)[h], member(where, "holes") + "[" + std::to_string(h) + "]"));
                }
                return Domain::polygon(ring(require(value, "outer", where), member(where, "outer")), holes);
            }
            if (type == "mask") {
                check_keys(value, {"type", "image", "min", "max", "threshold"}, where);
                need_dimension(2);
                const Vec3 lo = point(require(value, "min", where), member(where, "min"));
                const Vec3 hi = point(require(value, "max", where), member(where, "max"));
                const auto it = value.find("threshold");
                const double threshold = it == value.end() ? 0.5 : number(*it, member(where, "threshold"));
                return Domain::mask(file("image"), lo, hi, threshold);
            }
            if (type == "mesh") {
                check_keys(value, {"type", "file", "resolution", "scale"}, where);
                need_dimension(3);
                return scale(Domain::mesh(file("file"), resolution()));
            }
            if (type == "shell") {
                check_keys(value, {"type", "file", "thickness", "resolution", "scale"}, where);
                need_dimension(3);
                const double thickness = number(require(value, "thickness", where), member(where, "thickness"));
                return scale(Domain::shell(file("file"), thickness, resolution()));
            }
        } catch (const Error& e) {
            if (e.kind() == ErrorKind::io) throw;
            throw Error(e.kind(), source_ + ": " + where + ": " + e.what());
        }
        fail(member(where, "type"), "unsupported domain type '" + type + "' (supported: box, polygon, mask, mesh, shell)");
    }

    void read_types(const Json& doc, Exemplar& ex) {
        const auto it = doc.find("types");
        if (it == doc.end()) return;
        types_declared_ = true;
        const Json& types = array(*it, "types");
        for (size_t i = 0; i < types.size(); ++i) {
            const std::string where = "types[" + std::to_string(i) + "]";
            const Json& t = types[i];
            if (!t.is_object()) fail(where, "must be an object, got " + t.dump());
            check_keys(t,
                       {"name", "rigid", "floor", "mesh", "color", "reference", "depends_on", "weights", "graph",
                        "topology", "columns", "glyph"},
                       where);
            ElementType type;
            type.name = string(require(t, "name", where), member(where, "name"));
            if (type.name.empty()) fail(member(where, "name"), "must not be empty");
            if (ex.find_type(type.name) >= 0)
                fail(member(where, "name"), "type '" + type.name + "' is defined twice");
            if (t.contains("rigid")) type.rigid = boolean(t["rigid"], member(where, "rigid"));
            if (t.contains("floor")) type.floor = boolean(t["floor"], member(where, "floor"));
            if (t.contains("mesh")) type.mesh = string(t["mesh"], member(where, "mesh"));
            if (t.contains("color")) {
                type.color = string(t["color"], member(where, "color"));
                if (!parse_color(type.color))
                    fail(member(where, "color"), "'" + type.color + "' is neither #rrggbb nor a colour name (CSS, "
                                                 "such as darkgreen or \"light blue\")");
            }
            if (t.contains("reference")) {
                // The samples' places in the mesh's frame (geometry.hpp); the count is
                // checked against the type's elements by Exemplar::validate.
                const std::string at = member(where, "reference");
                const Json& points = array(t["reference"], at);
                for (size_t k = 0; k < points.size(); ++k)
                    type.reference.push_back(point(points[k], at + "[" + std::to_string(k) + "]"));
            }
            if (t.contains("depends_on")) type.depends_on = depends_on(t["depends_on"], member(where, "depends_on"));
            if (t.contains("weights")) type.weights = weights(t["weights"], member(where, "weights"));
            if (t.contains("graph")) type.graph = graph(t["graph"], member(where, "graph"));
            if (t.contains("topology")) type.topology = topology(t["topology"], member(where, "topology"));
            if (t.contains("columns")) type.sheet_columns = columns(t["columns"], member(where, "columns"));
            if (t.contains("glyph")) type.glyph = glyph(t["glyph"], member(where, "glyph"));
            ex.types.push_back(std::move(type));
        }
        // Names may refer to types listed later, so they are checked once all are read.
        for (size_t i = 0; i < ex.types.size(); ++i) {
            if (!ex.types[i].depends_on) continue;
            for (size_t k = 0; k < ex.types[i].depends_on->size(); ++k) {
                const std::string& name = (*ex.types[i].depends_on)[k];
                if (ex.find_type(name) < 0)
                    fail("types[" + std::to_string(i) + "].depends_on[" + std::to_string(k) + "]",
                         "type '" + ex.types[i].name + "' depends on unknown type '" + name + "'");
            }
        }
    }

    // How the type's single-sample elements are drawn in 2D pictures.
    ElementGlyph glyph(const Json& value, const std::string& where) const {
        const std::string name = string(value, where);
        if (name == "disk") return ElementGlyph::disk;
        if (name == "fish") return ElementGlyph::fish;
        fail(where, "unknown glyph '" + name + "' (known: disk, fish)");
    }

    // How the type's samples hang together in space-time synthesis (animation.hpp).
    ElementTopology topology(const Json& value, const std::string& where) const {
        const std::string name = string(value, where);
        for (const auto& [t, known] : topology_names)
            if (name == known) return t;
        fail(where, "unknown topology '" + name + "' (known: none, thread, sheet)");
    }

    // A sheet's grid columns; whether they fit the topology and the sample count is
    // check_topology's job, once the elements are read.
    int columns(const Json& value, const std::string& where) const {
        const long long n = integer(value, where);
        if (n < 1 || n > std::numeric_limits<int>::max()) fail(where, "must be a positive integer, got " + value.dump());
        return static_cast<int>(n);
    }

    // Brushing's sample weights (brush.hpp): numbers > 0, one per sample id (the count is
    // checked against the type's elements by Exemplar::validate).
    std::vector<double> weights(const Json& value, const std::string& where) const {
        const Json& list = array(value, where);
        std::vector<double> out;
        for (size_t k = 0; k < list.size(); ++k) {
            const std::string at = where + "[" + std::to_string(k) + "]";
            if (!list[k].is_number()) fail(at, "must be a number, got " + list[k].dump());
            out.push_back(list[k].get<double>());
        }
        return out;
    }

    // Brushing's element graph (brush.hpp): pairs [i, j] of sample ids (checked against the
    // type's sample count by Exemplar::validate).
    std::vector<std::array<int, 2>> graph(const Json& value, const std::string& where) const {
        const Json& list = array(value, where);
        std::vector<std::array<int, 2>> out;
        for (size_t k = 0; k < list.size(); ++k) {
            const std::string at = where + "[" + std::to_string(k) + "]";
            const Json& edge = list[k];
            if (!edge.is_array() || edge.size() != 2 || !edge[0].is_number_integer() || !edge[1].is_number_integer())
                fail(at, "must be a pair of sample ids [i, j], got " + edge.dump());
            out.push_back({edge[0].get<int>(), edge[1].get<int>()});
        }
        return out;
    }

    // The classes a type depends on in the PCF method's dependency graph
    // (pcf_synthesis.hpp): an array of distinct type names, possibly empty.
    std::vector<std::string> depends_on(const Json& value, const std::string& where) const {
        const Json& names = array(value, where);
        std::vector<std::string> out;
        for (size_t k = 0; k < names.size(); ++k) {
            const std::string at = where + "[" + std::to_string(k) + "]";
            const std::string name = string(names[k], at);
            if (std::find(out.begin(), out.end(), name) != out.end()) fail(at, "type '" + name + "' is named twice");
            out.push_back(name);
        }
        return out;
    }

    void read_attribute_names(const Json& doc, Exemplar& ex) const {
        const auto it = doc.find("attributes");
        if (it == doc.end()) return;
        const Json& names = array(*it, "attributes");
        for (size_t i = 0; i < names.size(); ++i) {
            const std::string where = "attributes[" + std::to_string(i) + "]";
            const std::string name = string(names[i], where);
            if (name.empty()) fail(where, "must not be empty");
            if (std::find(ex.attribute_names.begin(), ex.attribute_names.end(), name) !=
                ex.attribute_names.end())
                fail(where, "attribute '" + name + "' is named twice");
            ex.attribute_names.push_back(name);
        }
    }

    int element_type(const Json& e, const std::string& where, Exemplar& ex) const {
        const auto it = e.find("type");
        if (it == e.end()) {
            // One declared type, or none declared at all: the type is unambiguous.
            if (types_declared_ && ex.types.size() == 1) return 0;
            if (!types_declared_) return ex.type_index("default");
            fail(where, "missing \"type\" (required when \"types\" declares several types)");
        }
        const std::string name = string(*it, member(where, "type"));
        if (name.empty()) fail(member(where, "type"), "must not be empty");
        if (!types_declared_) return ex.type_index(name);
        const int type = ex.find_type(name);
        if (type < 0) fail(where, "unknown element type '" + name + "'");
        return type;
    }

    Quat element_orientation(const Json& e, const std::string& where) const {
        std::optional<double> angle;
        if (e.contains("angle")) angle = number(e["angle"], member(where, "angle"));
        std::optional<Quat> q;
        if (e.contains("orientation")) {
            const std::string at = member(where, "orientation");
            const Json& value = e["orientation"];
            if (!value.is_array() || value.size() != 4)
                fail(at, "must be an array of 4 numbers [w, x, y, z], got " + value.dump());
            q = Quat{number(value[0], at), number(value[1], at), number(value[2], at), number(value[3], at)};
        }
        Quat result;
        if (const auto problem = resolve_orientation(q, angle, dimension_, result)) fail(where, *problem);
        return result;
    }

    void element_time(const Json& e, const std::string& where, int index, Exemplar& ex) const {
        if (!e.contains("time")) return;
        const std::string at = member(where, "time");
        const Element& element = ex.elements[index];
        const Json& value = e["time"];
        if (value.is_array()) {
            if (value.size() != static_cast<size_t>(element.sample_count))
                fail(at,
                     "must be one number, or one per sample (" + std::to_string(element.sample_count) + ")");
            for (int s = 0; s < element.sample_count; ++s)
                ex.samples[element.first_sample + s].time = number(value[static_cast<size_t>(s)], at);
            return;
        }
        const double t = number(value, at);
        for (int s = 0; s < element.sample_count; ++s) ex.samples[element.first_sample + s].time = t;
    }

    void read_elements(const Json& value, Exemplar& ex) {
        const Json& elements = array(value, "elements");
        std::set<std::uint64_t> ids;
        for (size_t i = 0; i < elements.size(); ++i) {
            const std::string where = "elements[" + std::to_string(i) + "]";
            const Json& e = elements[i];
            if (!e.is_object()) fail(where, "must be an object, got " + e.dump());
            check_keys(e,
                       {"id", "type", "position", "samples", "radius", "angle", "orientation", "scale",
                        "attributes", "locked", "time"},
                       where);
            const int type = element_type(e, where, ex);
            double radius = 0.0;
            if (e.contains("radius")) {
                radius = number(e["radius"], member(where, "radius"));
                if (radius < 0.0) fail(member(where, "radius"), "must be >= 0 (0 means no radius)");
            }
            std::optional<std::uint64_t> id;
            if (e.contains("id")) id = element_id(e["id"], member(where, "id"));
            const int index = ex.add_element(
                type, frame_samples_ ? samples_from_frames(e, id, where) : element_samples(e, where), radius);
            Element& element = ex.elements[index];
            if (id) element.id = *id;
            if (!ids.insert(element.id).second)
                fail(where, "duplicate element id " + std::to_string(element.id));
            element.orientation = element_orientation(e, where);
            if (e.contains("scale")) {
                element.scale = number(e["scale"], member(where, "scale"));
                if (!(element.scale > 0.0)) fail(member(where, "scale"), "must be > 0");
            }
            if (e.contains("locked")) element.locked = boolean(e["locked"], member(where, "locked"));
            read_element_attributes(e, where, ex, element);
            element_time(e, where, index, ex);
        }
    }

    // An animated file's element: its samples are in the frames, which name it by its id.
    std::vector<Vec3> samples_from_frames(const Json& e, std::optional<std::uint64_t> id,
                                          const std::string& where) const {
        for (const char* key : {"position", "samples", "time"})
            if (e.contains(key))
                fail(member(where, key), "not allowed in an animated file (positions and times are in \"frames\")");
        if (!id) fail(where, "missing \"id\" (required in an animated file: frames name elements by id)");
        return (*frame_samples_)(*id, where);
    }

    void read_element_attributes(const Json& e, const std::string& where, const Exemplar& ex,
                                 Element& element) const {
        const size_t expected = ex.attribute_names.size();
        const auto it = e.find("attributes");
        if (it == e.end()) {
            if (expected > 0)
                fail(where, "missing \"attributes\" (" + std::to_string(expected) +
                                " values, one per name in the "
                                "top-level \"attributes\")");
            return;
        }
        const std::string at = member(where, "attributes");
        if (!it->is_array() || it->size() != expected)
            fail(at, "must be an array of " + std::to_string(expected) +
                         " numbers (one per name in the top-level \"attributes\"), got " + it->dump());
        for (const Json& a : *it) element.attributes.push_back(number(a, at));
    }
};

// ---- writing ---------------------------------------------------------------

OrderedJson point_json(const Vec3& p, int dimension) {
    OrderedJson out = OrderedJson::array();
    for (int k = 0; k < dimension; ++k) out.push_back(p[k]);
    return out;
}

// "position" for a single-sample element, else "samples".
void put_samples(OrderedJson& out, const Exemplar& data, const Element& e) {
    if (e.sample_count == 1) {
        out["position"] = point_json(data.samples[e.first_sample].p, data.dimension);
        return;
    }
    OrderedJson samples = OrderedJson::array();
    for (int s = 0; s < e.sample_count; ++s)
        samples.push_back(point_json(data.samples[e.first_sample + s].p, data.dimension));
    out["samples"] = std::move(samples);
}

// Time: one number when all samples share it (the usual case), else one per sample;
// nothing when all are 0.
void put_time(OrderedJson& out, const Exemplar& data, const Element& e) {
    bool uniform = true, all_zero = true;
    for (int s = 0; s < e.sample_count; ++s) {
        const double t = data.samples[e.first_sample + s].time;
        uniform = uniform && t == data.samples[e.first_sample].time;
        all_zero = all_zero && t == 0.0;
    }
    if (!all_zero) {
        if (uniform) {
            out["time"] = data.samples[e.first_sample].time;
        } else {
            OrderedJson times = OrderedJson::array();
            for (int s = 0; s < e.sample_count; ++s) times.push_back(data.samples[e.first_sample + s].time);
            out["time"] = std::move(times);
        }
    }
}

OrderedJson element_json(const Exemplar& data, const Element& e, JsonElementPart part) {
    OrderedJson out;
    out["id"] = e.id;
    if (part != JsonElementPart::samples) out["type"] = data.types.at(static_cast<size_t>(e.type)).name;
    if (part != JsonElementPart::definition) put_samples(out, data, e);
    if (part == JsonElementPart::samples) return out;
    if (e.radius > 0.0) out["radius"] = e.radius;
    if (data.dimension == 2) out["angle"] = e.orientation.angle_z();
    out["orientation"] = {e.orientation.w, e.orientation.x, e.orientation.y, e.orientation.z};
    out["scale"] = e.scale;
    if (!e.attributes.empty()) out["attributes"] = e.attributes;
    if (e.locked) out["locked"] = true;
    if (part == JsonElementPart::all) put_time(out, data, e);
    return out;
}

// The deterministic part of the run statistics.
OrderedJson stats_json(const RunStats& stats) {
    OrderedJson out;
    out["method"] = stats.method;
    out["energy"] = stats.energy;
    out["final_energy"] = stats.final_energy;
    out["radius"] = stats.radius;
    out["solver_bound_hits"] = stats.solver_bound_hits;
    out["fallbacks"] = stats.fallbacks;
    out["notes"] = stats.notes;
    out["seed"] = stats.seed;
    if (stats.physics)
        out["physics"] = {{"interpenetrating_pairs", {stats.penetrations_before, stats.penetrations_after}},
                          {"max_depth", {stats.max_depth_before, stats.max_depth_after}},
                          {"floating", {stats.floating_before, stats.floating_after}}};
    // Timings and the thread count are left out on purpose: the file must be
    // byte-identical for the same input, options and seed on any machine and with
    // any number of threads. They stay in RunStats and the CLI prints them.
    return out;
}

// Writes `items` (compact JSON texts) as a JSON array with one item per line.
void append_array(std::string& out, const std::vector<std::string>& items) {
    if (items.empty()) {
        out += "[]";
        return;
    }
    out += "[\n";
    for (size_t i = 0; i < items.size(); ++i) {
        out += "    " + items[i];
        out += i + 1 < items.size() ? ",\n" : "\n";
    }
    out += "  ]";
}

// The "types" entries, one compact JSON text each.
std::vector<std::string> types_json(const Exemplar& data, const MeshPath& mesh_path) {
    std::vector<std::string> types;
    for (const auto& t : data.types) {
        OrderedJson type{{"name", t.name}, {"rigid", t.rigid}, {"floor", t.floor},
                         {"mesh", t.mesh.empty() ? t.mesh : mesh_path(t.mesh)}};
        if (!t.color.empty()) type["color"] = t.color;
        if (!t.reference.empty()) {
            OrderedJson reference = OrderedJson::array();
            for (const Vec3& p : t.reference) reference.push_back(point_json(p, data.dimension));
            type["reference"] = std::move(reference);
        }
        if (t.depends_on) type["depends_on"] = *t.depends_on;
        if (!t.weights.empty()) type["weights"] = t.weights;
        if (!t.graph.empty()) {
            OrderedJson graph = OrderedJson::array();
            for (const auto& edge : t.graph) graph.push_back({edge[0], edge[1]});
            type["graph"] = std::move(graph);
        }
        for (const auto& [topology, name] : topology_names)
            if (t.topology == topology) type["topology"] = name;
        if (t.sheet_columns != 0) type["columns"] = t.sheet_columns;
        if (t.glyph == ElementGlyph::fish) type["glyph"] = "fish";
        types.push_back(type.dump());
    }
    return types;
}

// The "domain" object (docs/format.md). Files are written as absolute paths: the
// writer does not know where the document will be read from.
OrderedJson domain_json(const Domain& d, int dimension) {
    OrderedJson out;
    const DomainSource src = d.source();
    const auto world = [&](const Vec3& q) { return src.origin + (q - src.origin) * src.scale; };
    const auto absolute = [](const std::string& f) { return std::filesystem::absolute(f).lexically_normal().string(); };
    switch (d.kind()) {
        case Domain::Kind::box:
            out["type"] = "box";
            out["min"] = point_json(d.bounds().lo, dimension);
            out["max"] = point_json(d.bounds().hi, dimension);
            break;
        case Domain::Kind::polygon: {
            out["type"] = "polygon";
            const auto ring = [&](const std::vector<Vec3>& r) {
                OrderedJson a = OrderedJson::array();
                for (const Vec3& v : r) a.push_back(point_json(world(v), 2));
                return a;
            };
            out["outer"] = ring(src.outer);
            OrderedJson holes = OrderedJson::array();
            for (const auto& h : src.holes) holes.push_back(ring(h));
            out["holes"] = holes;
            break;
        }
        case Domain::Kind::mask:
            out["type"] = "mask";
            out["image"] = absolute(src.file);
            out["min"] = point_json(world(src.box.lo), 2);
            out["max"] = point_json(world(src.box.hi), 2);
            out["threshold"] = src.threshold;
            break;
        case Domain::Kind::mesh:
        case Domain::Kind::shell:
            out["type"] = d.kind() == Domain::Kind::mesh ? "mesh" : "shell";
            out["file"] = absolute(src.file);
            if (d.kind() == Domain::Kind::shell) out["thickness"] = src.thickness;
            out["resolution"] = src.resolution;
            if (src.scale != 1.0) out["scale"] = src.scale;
            break;
    }
    return out;
}

}  // namespace

Exemplar parse_json(const std::string& text, const std::string& source) {
    const Json doc = parse_json_text(text, source);
    if (doc.is_object() && doc.contains("frames")) return read_json_animation(doc, source).frame(0);
    return read_json_document(doc, source);
}

Domain load_domain_json(const std::string& path, int dimension) {
    return JsonReader(path).read_domain_document(read_file(path), dimension);
}

std::string run_stats_json(const RunStats& stats) { return stats_json(stats).dump(); }

std::string to_json(const Exemplar& data, const RunStats* stats) {
    return to_json_with_mesh_paths(data, stats, [](const std::string& mesh) { return mesh; });
}

// ---- pieces shared with animation_json.cpp (io_util.hpp) -------------------

Json io_detail::parse_json_text(const std::string& text, const std::string& source) {
    return JsonReader(source).parse(text);
}

int io_detail::json_document_dimension(const Json& doc, const std::string& source) {
    return JsonReader(source).read_header(doc);
}

Exemplar io_detail::read_json_document(const Json& doc, const std::string& source,
                                       const JsonFrameSamples* frame_samples) {
    return JsonReader(source).read(doc, frame_samples);
}

void io_detail::check_json_keys(const Json& object, std::initializer_list<const char*> allowed,
                                const std::string& source, const std::string& where) {
    JsonReader(source).check_keys(object, allowed, where);
}

const Json& io_detail::json_require(const Json& object, const char* key, const std::string& source,
                                   const std::string& where) {
    return JsonReader(source).require(object, key, where);
}

const Json& io_detail::json_array(const Json& value, const std::string& source, const std::string& where) {
    return JsonReader(source).array(value, where);
}

double io_detail::json_number(const Json& value, const std::string& source, const std::string& where) {
    return JsonReader(source).number(value, where);
}

std::uint64_t io_detail::json_element_id(const Json& value, const std::string& source, const std::string& where) {
    return JsonReader(source).element_id(value, where);
}

std::vector<Vec3> io_detail::json_element_samples(const Json& element, int dimension, const std::string& source,
                                                  const std::string& where) {
    return JsonReader(source, dimension).element_samples(element, where);
}

std::string io_detail::json_element_line(const Exemplar& data, const Element& e, JsonElementPart part) {
    return element_json(data, e, part).dump();
}

std::string io_detail::json_number_text(double value) { return OrderedJson(value).dump(); }

std::string io_detail::to_json_with_mesh_paths(const Exemplar& data, const RunStats* stats,
                                               const MeshPath& mesh_path) {
    std::vector<std::string> elements;
    elements.reserve(data.elements.size());
    for (const auto& e : data.elements) elements.push_back(element_json(data, e, JsonElementPart::all).dump());
    return json_document(data, elements, "", stats, mesh_path);
}

std::string io_detail::json_document(const Exemplar& data, const std::vector<std::string>& element_lines,
                                     const std::string& after_elements, const RunStats* stats,
                                     const MeshPath& mesh_path) {
    std::string out = "{\n";
    out += "  \"format\": \"tessera\",\n";
    out += "  \"version\": " + std::to_string(format_version) + ",\n";
    out += "  \"dimension\": " + std::to_string(data.dimension) + ",\n";
    out += "  \"domain\": " + domain_json(data.domain, data.dimension).dump() + ",\n";
    out += "  \"types\": ";
    append_array(out, types_json(data, mesh_path));
    out += ",\n";
    if (!data.attribute_names.empty())
        out += "  \"attributes\": " + OrderedJson(data.attribute_names).dump() + ",\n";
    out += "  \"elements\": ";
    append_array(out, element_lines);
    out += after_elements;
    if (stats) out += ",\n  \"stats\": " + stats_json(*stats).dump();
    out += "\n}\n";
    return out;
}

}  // namespace tessera
