// The compact form of a world's tile (tile_arrays.hpp): writing it, and reading it back with
// every field checked, naming the tile and the key at fault.
#include "tile_arrays.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "convert.hpp"
#include "option_values.hpp"

namespace tessera_python {
namespace {

const std::vector<std::string> tile_keys = {"dimension", "box_min", "box_max", "types", "attribute_names",
                                            "sample_counts", "classes", "radii", "orientations", "scales",
                                            "ids", "locked", "attributes", "positions", "times"};
const std::vector<std::string> type_keys = {"name", "rigid", "floor", "mesh", "color", "reference", "depends_on"};

// ---- writing ----------------------------------------------------------------------------

template <class T, class Get>
py::array_t<T> column(std::size_t n, const Get& get) {
    py::array_t<T> a(static_cast<py::ssize_t>(n));
    auto m = a.template mutable_unchecked<1>();
    for (std::size_t i = 0; i < n; ++i) m(static_cast<py::ssize_t>(i)) = get(i);
    return a;
}

template <class Get>
py::array_t<double> matrix(std::size_t n, std::size_t columns, const Get& get) {
    auto a = new_array<double>({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(columns)});
    auto m = a.mutable_unchecked<2>();
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < columns; ++k) m(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(k)) = get(i, k);
    return a;
}

py::array_t<double> point_array(const std::vector<tessera::Vec3>& points, int dimension) {
    return matrix(points.size(), static_cast<std::size_t>(dimension),
                  [&](std::size_t i, std::size_t k) { return points[i][static_cast<int>(k)]; });
}

py::list types_list(const tessera::Exemplar& tile) {
    py::list types;
    for (const tessera::ElementType& t : tile.types) {
        py::dict d;
        d["name"] = t.name, d["rigid"] = t.rigid, d["floor"] = t.floor, d["mesh"] = t.mesh, d["color"] = t.color;
        d["reference"] = point_array(t.reference, tile.dimension);
        d["depends_on"] = t.depends_on ? py::cast(*t.depends_on) : py::none();
        types.append(d);
    }
    return types;
}

void write_elements(const tessera::Exemplar& tile, py::dict& out) {
    const auto& e = tile.elements;
    const std::size_t n = e.size();
    out["sample_counts"] = column<std::int32_t>(n, [&](std::size_t i) { return e[i].sample_count; });
    out["classes"] = column<std::int32_t>(n, [&](std::size_t i) { return e[i].type; });
    out["radii"] = column<double>(n, [&](std::size_t i) { return e[i].radius; });
    out["orientations"] = matrix(n, 4, [&](std::size_t i, std::size_t k) {
        const tessera::Quat& q = e[i].orientation;
        return k == 0 ? q.w : k == 1 ? q.x : k == 2 ? q.y : q.z;
    });
    out["scales"] = column<double>(n, [&](std::size_t i) { return e[i].scale; });
    out["ids"] = column<std::uint64_t>(n, [&](std::size_t i) { return e[i].id; });
    out["locked"] = column<bool>(n, [&](std::size_t i) { return e[i].locked; });
    out["attributes"] = matrix(n, tile.attribute_names.size(), [&](std::size_t i, std::size_t k) { return e[i].attributes[k]; });
}

void write_samples(const tessera::Exemplar& tile, py::dict& out) {
    const auto& s = tile.samples;
    out["positions"] = matrix(s.size(), static_cast<std::size_t>(tile.dimension),
                              [&](std::size_t i, std::size_t k) { return s[i].p[static_cast<int>(k)]; });
    out["times"] = column<double>(s.size(), [&](std::size_t i) { return s[i].time; });
}

// ---- reading ----------------------------------------------------------------------------

std::string shape_of(const py::array& a) {
    std::string shape = "(";
    for (py::ssize_t k = 0; k < a.ndim(); ++k) shape += (k ? ", " : "") + std::to_string(a.shape(k));
    return shape + (a.ndim() == 1 ? ",)" : ")");
}

// A checked array with its element access, kept together so that the access never outlives
// the (possibly converted) array.
template <class T>
class Checked {
public:
    using Array = py::array_t<T, py::array::c_style | py::array::forcecast>;
    explicit Checked(Array a) : a_(std::move(a)), columns_(a_.ndim() == 2 ? a_.shape(1) : 1) {}
    py::ssize_t rows() const { return a_.shape(0); }
    T operator()(py::ssize_t row, py::ssize_t column = 0) const { return a_.data()[row * columns_ + column]; }

private:
    Array a_;
    py::ssize_t columns_;
};

// The fields of one compact dict, each checked as it is taken; `where` is "tile['types'][0]" and such.
class Fields {
public:
    Fields(const py::handle& value, std::string where, const std::vector<std::string>& keys)
        : where_(std::move(where)) {
        if (!py::isinstance<py::dict>(value)) bad(where_ + " must be a dict (a compact tile), got " + type_name(value));
        dict_ = py::reinterpret_borrow<py::dict>(value);
        for (const auto& item : dict_) {
            const std::string key = py::str(item.first);
            if (std::find(keys.begin(), keys.end(), key) == keys.end()) bad(where_ + ": unknown key '" + key + "'");
        }
    }

    py::handle at(const char* key) const {
        if (!dict_.contains(key)) bad(where_ + ": missing '" + key + "'");
        return dict_[key];
    }
    std::string name(const char* key) const { return where_ + "['" + key + "']"; }

    // An array of `rows` rows (-1: any) and `columns` columns (-1: a 1-D array), of a dtype
    // kind in `kinds` ("f" float, "i"/"u" integer, "b" bool), converted to T.
    template <class T>
    Checked<T> array(const char* key, py::ssize_t rows, py::ssize_t columns, const std::string& kinds) const {
        const py::array raw = py::array::ensure(at(key));
        if (!raw || kinds.find(raw.dtype().kind()) == std::string::npos)
            bad(name(key) + " must be " + kind_text(kinds) + ", got " +
                (raw ? "dtype " + std::string(py::str(raw.dtype())) : type_name(at(key))));
        const bool ok = columns < 0 ? raw.ndim() == 1 : raw.ndim() == 2 && raw.shape(1) == columns;
        const std::string expected = columns < 0 ? "a 1-D array" : "an N x " + std::to_string(columns) + " array";
        if (!ok) bad(name(key) + " must be " + expected + ", got shape " + shape_of(raw));
        if (rows >= 0 && raw.shape(0) != rows)
            bad(name(key) + " must have " + std::to_string(rows) + " rows, got " + std::to_string(raw.shape(0)));
        return Checked<T>(Checked<T>::Array::ensure(raw));
    }

    template <class T>
    T value(const char* key, const char* what) const {
        return get<T>(at(key), name(key), what);
    }

private:
    static std::string kind_text(const std::string& kinds) {
        return kinds == "b" ? "a bool array" : kinds == "iu" ? "an integer array" : "a numeric array";
    }
    static std::string type_name(const py::handle& v) { return py::str(py::type::handle_of(v).attr("__name__")); }
    std::string where_;
    py::dict dict_;
};

constexpr const char* numeric = "fiu";
constexpr const char* integral = "iu";

std::vector<tessera::Vec3> points_of(const Fields& f, const char* key, int dimension) {
    const auto a = f.array<double>(key, -1, dimension, numeric);
    std::vector<tessera::Vec3> points(static_cast<std::size_t>(a.rows()));
    for (py::ssize_t i = 0; i < a.rows(); ++i)
        for (int k = 0; k < dimension; ++k) points[static_cast<std::size_t>(i)][k] = a(i, k);
    return points;
}

// A corner of the tile's box: a 1-D array of `dimension` coordinates.
tessera::Vec3 corner(const Fields& f, const char* key, int dimension) {
    const auto a = f.array<double>(key, dimension, -1, numeric);
    tessera::Vec3 p;
    for (int k = 0; k < dimension; ++k) p[k] = a(k);
    return p;
}

tessera::ElementType read_type(const py::handle& value, const std::string& where, int dimension) {
    const Fields f(value, where, type_keys);
    tessera::ElementType t;
    t.name = f.value<std::string>("name", "a string");
    t.rigid = f.value<bool>("rigid", "True or False");
    t.floor = f.value<bool>("floor", "True or False");
    t.mesh = f.value<std::string>("mesh", "a string");
    t.color = f.value<std::string>("color", "a string");
    t.reference = points_of(f, "reference", dimension);
    if (!f.at("depends_on").is_none())
        t.depends_on = f.value<std::vector<std::string>>("depends_on", "None or a list of type names");
    return t;
}

void read_header(const Fields& f, tessera::Arrangement& tile) {
    tile.dimension = f.value<int>("dimension", "2 or 3");
    if (tile.dimension != 2 && tile.dimension != 3) bad(f.name("dimension") + " must be 2 or 3");
    try {
        tile.domain = tessera::Domain::box(corner(f, "box_min", tile.dimension), corner(f, "box_max", tile.dimension),
                                           tile.dimension);
    } catch (const tessera::Error& e) {
        throw tessera::Error(e.kind(), f.name("box_min") + ", " + f.name("box_max") + ": " + e.what());
    }
    const py::handle types_value = f.at("types");
    if (!py::isinstance<py::list>(types_value) && !py::isinstance<py::tuple>(types_value))
        bad(f.name("types") + " must be a list of dicts");
    const auto types = py::reinterpret_borrow<py::sequence>(types_value);
    for (std::size_t i = 0; i < types.size(); ++i) {
        tessera::ElementType t = read_type(types[i], f.name("types") + "[" + std::to_string(i) + "]", tile.dimension);
        if (tile.find_type(t.name) >= 0) bad(f.name("types") + ": type '" + t.name + "' is named twice");
        tile.types.push_back(std::move(t));
    }
    tile.attribute_names = f.value<std::vector<std::string>>("attribute_names", "a list of strings");
}

// The elements with their samples, types and radii, in the order of their runs.
void read_elements(const Fields& f, tessera::Arrangement& tile) {
    const auto counts = f.array<std::int64_t>("sample_counts", -1, -1, integral);
    const py::ssize_t n = counts.rows();
    const auto classes = f.array<std::int64_t>("classes", n, -1, integral);
    const auto radii = f.array<double>("radii", n, -1, numeric);
    const std::vector<tessera::Vec3> positions = points_of(f, "positions", tile.dimension);
    std::size_t first = 0;
    for (py::ssize_t i = 0; i < n; ++i) {
        if (counts(i) < 1 || static_cast<std::size_t>(counts(i)) > positions.size() - first)
            bad(f.name("sample_counts") + ": element " + std::to_string(i) + " has " + std::to_string(counts(i)) +
                " samples; the counts must be >= 1 and add up to the rows of " + f.name("positions"));
        if (classes(i) < 0 || classes(i) >= static_cast<std::int64_t>(tile.types.size()))
            bad(f.name("classes") + ": element " + std::to_string(i) + " has class " + std::to_string(classes(i)) +
                ", not one of the " + std::to_string(tile.types.size()) + " types");
        const auto end = positions.begin() + static_cast<std::ptrdiff_t>(first + static_cast<std::size_t>(counts(i)));
        tile.add_element(static_cast<int>(classes(i)),
                         std::vector<tessera::Vec3>(positions.begin() + static_cast<std::ptrdiff_t>(first), end), radii(i));
        first += static_cast<std::size_t>(counts(i));
    }
    if (first != positions.size())
        bad(f.name("sample_counts") + " add up to " + std::to_string(first) + " samples but " + f.name("positions") +
            " has " + std::to_string(positions.size()) + " rows");
}

void read_poses(const Fields& f, tessera::Arrangement& tile) {
    const auto n = static_cast<py::ssize_t>(tile.elements.size());
    const auto q = f.array<double>("orientations", n, 4, numeric);
    const auto scales = f.array<double>("scales", n, -1, numeric);
    for (py::ssize_t i = 0; i < n; ++i) {
        tessera::Element& e = tile.elements[static_cast<std::size_t>(i)];
        e.orientation = {q(i, 0), q(i, 1), q(i, 2), q(i, 3)};
        const double length = std::sqrt(q(i, 0) * q(i, 0) + q(i, 1) * q(i, 1) + q(i, 2) * q(i, 2) + q(i, 3) * q(i, 3));
        if (!(std::abs(length - 1.0) < 1e-6))
            bad(f.name("orientations") + ": row " + std::to_string(i) + " is not a unit quaternion");
        e.scale = scales(i);
        if (!(std::isfinite(e.scale) && e.scale > 0.0)) bad(f.name("scales") + ": row " + std::to_string(i) + " is not > 0");
    }
}

void read_flags(const Fields& f, tessera::Arrangement& tile) {
    const auto n = static_cast<py::ssize_t>(tile.elements.size());
    const auto ids = f.array<std::uint64_t>("ids", n, -1, integral);
    const auto locked = f.array<bool>("locked", n, -1, "b");
    const auto columns = static_cast<py::ssize_t>(tile.attribute_names.size());
    const auto attributes = f.array<double>("attributes", n, columns, numeric);
    std::set<std::uint64_t> seen;
    for (py::ssize_t i = 0; i < n; ++i) {
        tessera::Element& e = tile.elements[static_cast<std::size_t>(i)];
        e.id = ids(i);
        if (!seen.insert(e.id).second) bad(f.name("ids") + ": id " + std::to_string(e.id) + " repeats");
        e.locked = locked(i);
        for (py::ssize_t k = 0; k < columns; ++k) e.attributes.push_back(attributes(i, k));
    }
}

void read_times(const Fields& f, tessera::Arrangement& tile) {
    const auto times = f.array<double>("times", static_cast<py::ssize_t>(tile.samples.size()), -1, numeric);
    for (std::size_t i = 0; i < tile.samples.size(); ++i) tile.samples[i].time = times(static_cast<py::ssize_t>(i));
}

}  // namespace

py::dict compact_tile(const tessera::Exemplar& tile) {
    if (tile.domain.kind() != tessera::Domain::Kind::box)
        bad("a tile's domain is a box; this arrangement's is " + tile.domain.describe());
    py::dict out;
    out["dimension"] = tile.dimension;
    const tessera::Box& box = tile.domain.bounds();
    out["box_min"] = column<double>(static_cast<std::size_t>(tile.dimension), [&](std::size_t k) { return box.lo[static_cast<int>(k)]; });
    out["box_max"] = column<double>(static_cast<std::size_t>(tile.dimension), [&](std::size_t k) { return box.hi[static_cast<int>(k)]; });
    out["types"] = types_list(tile);
    out["attribute_names"] = tile.attribute_names;
    write_elements(tile, out);
    write_samples(tile, out);
    return out;
}

tessera::Arrangement tile_from_compact(const py::handle& compact, const std::string& what) {
    const Fields f(compact, what, tile_keys);
    tessera::Arrangement tile;
    read_header(f, tile);
    read_elements(f, tile);
    read_poses(f, tile);
    read_flags(f, tile);
    read_times(f, tile);
    tile.validate(what);
    return tile;
}

}  // namespace tessera_python
