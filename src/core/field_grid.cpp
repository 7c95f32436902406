// core/field_grid.cpp — orientation fields given at the nodes of a regular 2D/3D grid
// and their JSON file ({"format": "tessera-field", ...}, docs/fields.md).
//
// The direction at p is the bilinear / trilinear blend of the (normalised) node
// vectors of p's cell, normalised; p is clamped into the grid first. The reader is
// strict like the exemplar reader: unknown keys, wrong counts and bad values are
// errors naming the file and the JSON path ("vectors[12]", "spacing[1]"). JSON is
// parsed through a SAX handler that tracks the path, so that even a number that
// overflows to infinity (1e999, the only non-finite number JSON can spell) is
// reported with its path and line.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/field_data.hpp"
#include "tessera/error.hpp"
#include "tessera/field.hpp"

namespace tessera {
namespace field_detail {

struct GridData {
    FieldGrid grid;  // node vectors normalised
    std::string source;
    std::size_t nodes = 0;
};

}  // namespace field_detail

namespace {

using Json = nlohmann::json;
using field_detail::GridData;

[[noreturn]] void fail(const std::string& source, const std::string& where, const std::string& what) {
    throw Error(ErrorKind::input, source + ": " + (where.empty() ? what : where + ": " + what));
}

std::string node_name(const FieldGrid& g, std::size_t index) {
    const std::size_t nx = static_cast<std::size_t>(g.size[0]), ny = static_cast<std::size_t>(g.size[1]);
    std::string s = "(" + std::to_string(index % nx) + "," + std::to_string(index / nx % ny);
    if (g.dimension == 3) s += "," + std::to_string(index / (nx * ny));
    return s + ")";
}

// Checks everything OrientationField::grid needs; `source` names the file or caller.
void check_grid(const FieldGrid& g, const std::string& source) {
    if (g.dimension != 2 && g.dimension != 3) fail(source, "dimension", "must be 2 or 3");
    const int dim = g.dimension;
    double nodes = 1.0;
    for (int a = 0; a < dim; ++a) {
        const std::string at = "[" + std::to_string(a) + "]";
        if (!std::isfinite(g.origin[a])) fail(source, "origin" + at, "must be finite");
        if (!std::isfinite(g.spacing[a]) || !(g.spacing[a] > 0.0))
            fail(source, "spacing" + at, "must be a finite number > 0");
        if (g.size[a] < 2) fail(source, "size" + at, "must be >= 2 (a grid has at least 2 nodes along each axis)");
        nodes *= g.size[a];
    }
    if (dim == 2 && g.size[2] != 1) fail(source, "size[2]", "must be 1 for a 2D grid");
    if (nodes != static_cast<double>(g.vectors.size())) {
        std::string shape = std::to_string(g.size[0]) + " x " + std::to_string(g.size[1]);
        if (dim == 3) shape += " x " + std::to_string(g.size[2]);
        std::ostringstream expected;
        expected.precision(15);
        expected << nodes;
        fail(source, "vectors",
             "expected " + expected.str() + " vectors (size " + shape + "), got " + std::to_string(g.vectors.size()));
    }
    for (std::size_t k = 0; k < g.vectors.size(); ++k) {
        Vec3 v = g.vectors[k];
        if (dim == 2) v.z = 0.0;
        const std::string at = "vectors[" + std::to_string(k) + "]";
        if (!is_finite(v)) fail(source, at, "must be finite (node " + node_name(g, k) + ")");
        if (!(norm(v) > field_detail::degenerate_norm))
            fail(source, at, "zero vector at node " + node_name(g, k) + " (every node needs a direction)");
    }
}

// A SAX handler that builds the DOM like nlohmann::json::parse but knows the JSON path
// of the value being read, so that parse errors (notably number overflow) name it.
class PathTrackingSax {
public:
    PathTrackingSax(Json& root, std::string source) : root_(root), source_(std::move(source)) {}

    bool null() { return add(Json(nullptr)); }
    bool boolean(bool v) { return add(Json(v)); }
    bool number_integer(Json::number_integer_t v) { return add(Json(v)); }
    bool number_unsigned(Json::number_unsigned_t v) { return add(Json(v)); }
    bool number_float(Json::number_float_t v, const Json::string_t&) { return add(Json(v)); }
    bool string(Json::string_t& v) { return add(Json(v)); }
    bool binary(Json::binary_t& v) { return add(Json(v)); }
    bool start_object(std::size_t) { return open(Json::object()); }
    bool start_array(std::size_t) { return open(Json::array()); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }
    bool key(Json::string_t& k) {
        stack_.back().key = k;
        return true;
    }
    bool parse_error(std::size_t, const std::string& token, const nlohmann::detail::exception& e) {
        std::string message = e.what();
        const std::size_t tag_end = message.find("] ");
        if (message.rfind("[json.exception", 0) == 0 && tag_end != std::string::npos)
            message = message.substr(tag_end + 2);
        if (e.id == 406)  // out_of_range: number overflow
            fail(source_, pending_path(),
                 "the number '" + token + "' is not finite (JSON numbers must be finite)");
        fail(source_, "", "invalid JSON: " + message);
    }

private:
    struct Level {
        Json* node;
        std::string key;
    };
    Json& root_;
    std::string source_;
    std::vector<Level> stack_;

    Json* place(Json&& value) {
        if (stack_.empty()) {
            root_ = std::move(value);
            return &root_;
        }
        Level& top = stack_.back();
        if (top.node->is_array()) {
            top.node->push_back(std::move(value));
            return &top.node->back();
        }
        Json& slot = (*top.node)[top.key];
        slot = std::move(value);
        return &slot;
    }
    bool add(Json&& value) {
        place(std::move(value));
        return true;
    }
    bool open(Json&& container) {
        stack_.push_back({place(std::move(container)), {}});
        return true;
    }
    bool close() {
        stack_.pop_back();
        return true;
    }
    // Path of the value about to be added ("vectors[3][1]").
    std::string pending_path() const {
        std::string path;
        for (std::size_t k = 0; k < stack_.size(); ++k) {
            const Json& node = *stack_[k].node;
            // An open container's child being read is its last element (or the next one at the top).
            const std::size_t index = node.size() - (k + 1 < stack_.size() ? 1 : 0);
            if (node.is_array())
                path += "[" + std::to_string(index) + "]";
            else
                path += (path.empty() ? "" : ".") + stack_[k].key;
        }
        return path;
    }
};

Json parse_json(const std::string& text, const std::string& source) {
    Json root;
    PathTrackingSax sax(root, source);
    Json::sax_parse(text, &sax);
    return root;
}

double number(const Json& v, const std::string& source, const std::string& where) {
    if (!v.is_number()) fail(source, where, "must be a number, got " + std::string(v.type_name()));
    return v.get<double>();
}

// An array of exactly `dimension` numbers.
Vec3 numbers(const Json& v, int dimension, const std::string& source, const std::string& where) {
    if (!v.is_array()) fail(source, where, "must be an array of " + std::to_string(dimension) + " numbers");
    if (static_cast<int>(v.size()) != dimension)
        fail(source, where,
             "expected " + std::to_string(dimension) + " numbers (the grid's dimension is " +
                 std::to_string(dimension) + "), got " + std::to_string(v.size()));
    Vec3 out;
    for (int a = 0; a < dimension; ++a) out[a] = number(v[a], source, where + "[" + std::to_string(a) + "]");
    return out;
}

const Json& require(const Json& doc, const char* key, const std::string& source) {
    if (!doc.contains(key)) fail(source, "", std::string("missing key '") + key + "'");
    return doc.at(key);
}

}  // namespace

FieldGrid parse_field_grid(const std::string& text, const std::string& source) {
    const Json doc = parse_json(text, source);
    if (!doc.is_object()) fail(source, "", "the document must be a JSON object");
    for (const auto& item : doc.items()) {
        static const char* const allowed[] = {"format", "dimension", "origin", "spacing", "size", "vectors",
                                              "description"};
        if (std::none_of(std::begin(allowed), std::end(allowed), [&](const char* k) { return item.key() == k; }))
            fail(source, "", "unknown key '" + item.key() + "'");
    }
    const Json& format = require(doc, "format", source);
    if (!format.is_string() || format.get<std::string>() != "tessera-field")
        fail(source, "format", "must be \"tessera-field\"");
    if (doc.contains("description") && !doc["description"].is_string())
        fail(source, "description", "must be a string");
    const Json& dimension = require(doc, "dimension", source);
    if (!dimension.is_number_integer() || (dimension.get<long long>() != 2 && dimension.get<long long>() != 3))
        fail(source, "dimension", "must be 2 or 3");
    FieldGrid g;
    g.dimension = static_cast<int>(dimension.get<long long>());
    const int dim = g.dimension;
    g.origin = numbers(require(doc, "origin", source), dim, source, "origin");
    g.spacing = numbers(require(doc, "spacing", source), dim, source, "spacing");
    if (dim == 2) g.spacing.z = 1.0;
    const Json& size = require(doc, "size", source);
    if (!size.is_array() || static_cast<int>(size.size()) != dim)
        fail(source, "size",
             "expected " + std::to_string(dim) + " integers (the grid's dimension is " + std::to_string(dim) + ")");
    for (int a = 0; a < dim; ++a) {
        const Json& n = size[a];
        const std::string where = "size[" + std::to_string(a) + "]";
        if (!n.is_number_integer() || n.get<long long>() < 2 || n.get<long long>() > (1 << 24))
            fail(source, where, "must be an integer >= 2 (a grid has at least 2 nodes along each axis)");
        g.size[a] = static_cast<int>(n.get<long long>());
    }
    g.size[2] = dim == 3 ? g.size[2] : 1;
    const Json& vectors = require(doc, "vectors", source);
    if (!vectors.is_array()) fail(source, "vectors", "must be an array of vectors");
    g.vectors.reserve(vectors.size());
    for (std::size_t k = 0; k < vectors.size(); ++k)
        g.vectors.push_back(numbers(vectors[k], dim, source, "vectors[" + std::to_string(k) + "]"));
    check_grid(g, source);
    return g;
}

FieldGrid read_field_grid(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw Error(ErrorKind::io, path + ": cannot open the field file");
    std::ostringstream buffer;
    buffer << file.rdbuf();
    return parse_field_grid(buffer.str(), path);
}

OrientationField OrientationField::grid(const FieldGrid& grid, const std::string& source) {
    check_grid(grid, source);
    auto data = std::make_shared<GridData>();
    data->grid = grid;
    data->source = source;
    data->nodes = grid.vectors.size();
    for (Vec3& v : data->grid.vectors) {
        if (grid.dimension == 2) v.z = 0.0;
        v = v / norm(v);
    }
    if (grid.dimension == 2) data->grid.origin.z = 0.0, data->grid.spacing.z = 1.0, data->grid.size[2] = 1;
    OrientationField f;
    f.kind_ = Kind::grid;
    f.grid_ = std::move(data);
    return f;
}

OrientationField OrientationField::grid_file(const std::string& path) { return grid(read_field_grid(path), path); }

namespace field_detail {

Vec3 grid_direction(const GridData& data, const Vec3& p) {
    const FieldGrid& g = data.grid;
    int i[3] = {0, 0, 0};
    double t[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < g.dimension; ++a) {
        // Clamped to the grid (NaN goes to the first node), then split into cell and fraction.
        double u = (p[a] - g.origin[a]) / g.spacing[a];
        const double last = g.size[a] - 1;
        u = u > 0.0 ? std::min(u, last) : 0.0;
        i[a] = std::min(static_cast<int>(u), g.size[a] - 2);
        t[a] = u - i[a];
    }
    const std::size_t nx = static_cast<std::size_t>(g.size[0]), nxy = nx * static_cast<std::size_t>(g.size[1]);
    const std::size_t base = static_cast<std::size_t>(i[0]) + nx * static_cast<std::size_t>(i[1]) +
                             nxy * static_cast<std::size_t>(i[2]);
    Vec3 sum;
    const int corners = g.dimension == 3 ? 8 : 4;
    for (int c = 0; c < corners; ++c) {
        const int dx = c & 1, dy = (c >> 1) & 1, dz = (c >> 2) & 1;
        const double w = (dx ? t[0] : 1.0 - t[0]) * (dy ? t[1] : 1.0 - t[1]) * (dz ? t[2] : 1.0 - t[2]);
        if (w == 0.0) continue;  // exact at nodes and faces
        sum += g.vectors[base + static_cast<std::size_t>(dx) + nx * static_cast<std::size_t>(dy) +
                         nxy * static_cast<std::size_t>(dz)] *
               w;
    }
    const double n = norm(sum);
    if (!(n > degenerate_norm)) return {};
    return sum / n;
}

int grid_dimension(const GridData& data) { return data.grid.dimension; }

std::string grid_describe(const GridData& data) {
    const FieldGrid& g = data.grid;
    std::string s = "grid " + data.source + " (" + std::to_string(g.size[0]) + " x " + std::to_string(g.size[1]);
    if (g.dimension == 3) s += " x " + std::to_string(g.size[2]);
    return s + " nodes)";
}

}  // namespace field_detail
}  // namespace tessera
