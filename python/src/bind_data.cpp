// Exemplar and Arrangement for Python. Arrays go both ways as numpy copies (the C++ storage
// stays private, so an array kept by a user never dangles):
//   per sample : positions (S x d), element_of_sample (S), sample_ids (S), times (S)
//   per element: classes (E), radii (E), orientations (E x 4, quaternion w, x, y, z),
//                scales (E), ids (E, uint64), locked (E), centroids (E x d), attributes (E x A)
// make_exemplar builds an exemplar from such arrays and checks it like a file is checked
// (Exemplar::validate), naming the array at fault.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <set>

#include "bindings.hpp"
#include "convert.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/io.hpp"
#include "tessera/render.hpp"

namespace py = pybind11;

namespace tessera_python {
namespace {

[[noreturn]] void bad(const std::string& message) { throw tessera::Error(tessera::ErrorKind::option, message); }

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Longs = py::array_t<long long, py::array::c_style | py::array::forcecast>;

// An array argument, checked for its shape: rows == `rows` (or any when -1), and columns
// one of `columns` (empty: a 1-D array).
template <class Array>
Array shaped(const py::handle& value, const std::string& name, py::ssize_t rows, std::vector<py::ssize_t> columns) {
    Array a;
    try {
        a = py::cast<Array>(value);
    } catch (const py::cast_error&) {
        bad(name + " must be a numeric array");
    }
    if (!a) bad(name + " must be a numeric array");
    std::string expected = columns.empty() ? "a 1-D array" : "an N x " + std::to_string(columns.front()) + " array";
    if (columns.size() == 2) expected = "an N x 2 or N x 3 array";
    const bool ok_dims = columns.empty() ? a.ndim() == 1 : a.ndim() == 2;
    bool ok_cols = columns.empty();
    if (!columns.empty() && a.ndim() == 2)
        for (py::ssize_t c : columns) ok_cols |= a.shape(1) == c;
    if (!ok_dims || !ok_cols) {
        std::string shape = "(";
        for (py::ssize_t k = 0; k < a.ndim(); ++k) shape += (k ? ", " : "") + std::to_string(a.shape(k));
        bad(name + " must be " + expected + ", got shape " + shape + (a.ndim() == 1 ? ",)" : ")"));
    }
    if (rows >= 0 && a.shape(0) != rows)
        bad(name + " must have " + std::to_string(rows) + " rows (one per " +
            (name == "times" || name == "sample_ids" || name == "element_of_sample" ? "sample" : "element") +
            "), got " + std::to_string(a.shape(0)));
    return a;
}

py::array_t<double> positions_of(const tessera::Exemplar& e) {
    const py::ssize_t n = static_cast<py::ssize_t>(e.samples.size()), d = e.dimension;
    auto a = new_array<double>({n, d});
    auto m = a.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < n; ++i)
        for (py::ssize_t k = 0; k < d; ++k) m(i, k) = e.samples[static_cast<std::size_t>(i)].p[static_cast<int>(k)];
    return a;
}

py::array_t<double> centroids_of(const tessera::Exemplar& e) {
    const py::ssize_t n = static_cast<py::ssize_t>(e.elements.size()), d = e.dimension;
    auto a = new_array<double>({n, d});
    auto m = a.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < n; ++i)
        for (py::ssize_t k = 0; k < d; ++k)
            m(i, k) = e.elements[static_cast<std::size_t>(i)].position[static_cast<int>(k)];
    return a;
}

template <class T, class F>
py::array_t<T> per_element(const tessera::Exemplar& e, F&& get) {
    py::array_t<T> a(static_cast<py::ssize_t>(e.elements.size()));
    auto m = a.template mutable_unchecked<1>();
    for (std::size_t i = 0; i < e.elements.size(); ++i) m(static_cast<py::ssize_t>(i)) = get(e.elements[i]);
    return a;
}

template <class T, class F>
py::array_t<T> per_sample(const tessera::Exemplar& e, F&& get) {
    py::array_t<T> a(static_cast<py::ssize_t>(e.samples.size()));
    auto m = a.template mutable_unchecked<1>();
    for (std::size_t i = 0; i < e.samples.size(); ++i) m(static_cast<py::ssize_t>(i)) = get(e.samples[i]);
    return a;
}

py::array_t<double> orientations_of(const tessera::Exemplar& e) {
    auto a = new_array<double>({static_cast<py::ssize_t>(e.elements.size()), 4});
    auto m = a.mutable_unchecked<2>();
    for (std::size_t i = 0; i < e.elements.size(); ++i) {
        const tessera::Quat& q = e.elements[i].orientation;
        const auto r = static_cast<py::ssize_t>(i);
        m(r, 0) = q.w, m(r, 1) = q.x, m(r, 2) = q.y, m(r, 3) = q.z;
    }
    return a;
}

py::array_t<double> attributes_of(const tessera::Exemplar& e) {
    const auto columns = static_cast<py::ssize_t>(e.attribute_names.size());
    auto a = new_array<double>({static_cast<py::ssize_t>(e.elements.size()), columns});
    auto m = a.mutable_unchecked<2>();
    for (std::size_t i = 0; i < e.elements.size(); ++i)
        for (py::ssize_t k = 0; k < columns; ++k)
            m(static_cast<py::ssize_t>(i), k) = e.elements[i].attributes[static_cast<std::size_t>(k)];
    return a;
}

py::list types_of(const tessera::Exemplar& e) {
    py::list types;
    for (const tessera::ElementType& t : e.types) {
        py::dict d;
        d["name"] = t.name;
        d["rigid"] = t.rigid;
        d["floor"] = t.floor;
        d["mesh"] = t.mesh;
        d["color"] = t.color;
        std::vector<std::vector<double>> reference;
        for (const auto& p : t.reference) reference.push_back({p.x, p.y, p.z});
        d["reference"] = reference;
        d["depends_on"] = t.depends_on ? py::cast(*t.depends_on) : py::none();
        types.append(d);
    }
    return types;
}

// Applies {"name": ..., "rigid": ..., "floor": ..., "mesh": ..., "color": ..., "reference": ...,
// "depends_on": ...}.
void apply_type(tessera::ElementType& type, const py::dict& d, const std::string& where) {
    for (const auto& [key_handle, value] : d) {
        const std::string key = py::str(key_handle);
        try {
            if (key == "name") continue;
            if (key == "rigid") type.rigid = value.cast<bool>();
            else if (key == "floor") type.floor = value.cast<bool>();
            else if (key == "mesh") type.mesh = value.cast<std::string>();
            else if (key == "color") {
                type.color = value.cast<std::string>();
                if (!type.color.empty() && !tessera::parse_color(type.color))
                    bad(where + ": color '" + type.color + "' is neither #rrggbb nor a colour name (CSS, such as "
                                "darkgreen or 'light blue')");
            }
            else if (key == "reference") type.reference = to_points(value, where + " reference");
            else if (key == "depends_on")
                type.depends_on = value.is_none() ? std::nullopt
                                                  : std::optional<std::vector<std::string>>(
                                                        value.cast<std::vector<std::string>>());
            else
                bad(where + ": unknown key '" + key + "' (name, rigid, floor, mesh, color, reference, depends_on)");
        } catch (const py::cast_error&) {
            bad(where + ": '" + key + "' has the wrong type");
        }
    }
}

tessera::Domain bounding_box(const tessera::Exemplar& e) {
    tessera::Vec3 lo = e.samples.front().p, hi = lo;
    for (const auto& s : e.samples)
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], s.p[k]), hi[k] = std::max(hi[k], s.p[k]);
    for (int k = 0; k < e.dimension; ++k)
        if (!(hi[k] > lo[k]))
            throw tessera::Error(tessera::ErrorKind::domain,
                                 std::string("domain: the positions have no extent along ") + "xyz"[k] +
                                     "; give domain= explicitly");
    return tessera::Domain::box(lo, hi, e.dimension);
}

tessera::Exemplar make_exemplar(const py::handle& positions_arg, const py::handle& classes_arg,
                                const py::handle& class_names_arg, const py::handle& radii_arg,
                                const py::handle& orientations_arg, const py::handle& scales_arg,
                                const py::handle& ids_arg, const py::handle& locked_arg,
                                const py::handle& element_of_sample_arg, const py::handle& sample_ids_arg,
                                const py::handle& times_arg, const py::handle& attributes_arg,
                                const py::handle& attribute_names_arg, const py::handle& domain_arg,
                                const py::handle& types_arg) {
    const Doubles positions = shaped<Doubles>(positions_arg, "positions", -1, {2, 3});
    const py::ssize_t samples = positions.shape(0);
    if (samples == 0) bad("positions must hold at least one point");
    const auto p = positions.unchecked<2>();
    tessera::Exemplar e;
    e.dimension = static_cast<int>(positions.shape(1));

    // Which element each sample belongs to: contiguous runs numbered 0, 1, 2, ...
    std::vector<long long> owner(static_cast<std::size_t>(samples));
    if (element_of_sample_arg.is_none()) {
        for (py::ssize_t i = 0; i < samples; ++i) owner[static_cast<std::size_t>(i)] = i;
    } else {
        const Longs a = shaped<Longs>(element_of_sample_arg, "element_of_sample", samples, {});
        const auto m = a.unchecked<1>();
        for (py::ssize_t i = 0; i < samples; ++i) {
            owner[static_cast<std::size_t>(i)] = m(i);
            const long long previous = i == 0 ? -1 : m(i - 1);
            if (m(i) != previous && m(i) != previous + 1)
                bad("element_of_sample must number elements 0, 1, 2, ... with each element's samples in one run; "
                    "row " + std::to_string(i) + " has " + std::to_string(m(i)) + " after " + std::to_string(previous));
        }
    }
    const py::ssize_t elements = static_cast<py::ssize_t>(owner.back() + 1);
    if (!sample_ids_arg.is_none()) {
        const Longs a = shaped<Longs>(sample_ids_arg, "sample_ids", samples, {});
        const auto m = a.unchecked<1>();
        long long expected = 0;
        for (py::ssize_t i = 0; i < samples; ++i) {
            if (i > 0 && owner[static_cast<std::size_t>(i)] != owner[static_cast<std::size_t>(i - 1)]) expected = 0;
            if (m(i) != expected)
                bad("sample_ids must count 0, 1, 2, ... within each element; row " + std::to_string(i) + " has " +
                    std::to_string(m(i)) + ", expected " + std::to_string(expected));
            ++expected;
        }
    }

    std::vector<long long> classes(static_cast<std::size_t>(elements), 0);
    if (!classes_arg.is_none()) {
        const Longs a = shaped<Longs>(classes_arg, "classes", elements, {});
        const auto m = a.unchecked<1>();
        for (py::ssize_t i = 0; i < elements; ++i) {
            if (m(i) < 0) bad("classes must be >= 0, element " + std::to_string(i) + " has " + std::to_string(m(i)));
            classes[static_cast<std::size_t>(i)] = m(i);
        }
    }
    const long long class_count = *std::max_element(classes.begin(), classes.end()) + 1;
    std::vector<std::string> names;
    if (!class_names_arg.is_none()) {
        try {
            names = class_names_arg.cast<std::vector<std::string>>();
        } catch (const py::cast_error&) {
            bad("class_names must be a sequence of strings");
        }
        if (static_cast<long long>(names.size()) < class_count)
            bad("class_names has " + std::to_string(names.size()) + " names but classes go up to " +
                std::to_string(class_count - 1));
        std::set<std::string> unique(names.begin(), names.end());
        if (unique.size() != names.size()) bad("class_names must not repeat a name");
    } else {
        for (long long c = 0; c < class_count; ++c) names.push_back(std::to_string(c));
    }
    for (const std::string& name : names) e.type_index(name);

    // Elements from the sample runs.
    std::vector<tessera::Vec3> points;
    py::ssize_t first = 0;
    for (py::ssize_t el = 0; el < elements; ++el) {
        points.clear();
        py::ssize_t i = first;
        for (; i < samples && owner[static_cast<std::size_t>(i)] == el; ++i)
            points.push_back({p(i, 0), p(i, 1), e.dimension == 3 ? p(i, 2) : 0.0});
        e.add_element(static_cast<int>(classes[static_cast<std::size_t>(el)]), points);
        first = i;
    }

    if (!radii_arg.is_none()) {
        const auto a = shaped<Doubles>(radii_arg, "radii", elements, {}).unchecked<1>();
        for (py::ssize_t i = 0; i < elements; ++i) e.elements[static_cast<std::size_t>(i)].radius = a(i);
    }
    if (!orientations_arg.is_none()) {
        const Doubles arr = shaped<Doubles>(orientations_arg, "orientations", elements, {4});
        const auto a = arr.unchecked<2>();
        for (py::ssize_t i = 0; i < elements; ++i) {
            const double n = std::sqrt(a(i, 0) * a(i, 0) + a(i, 1) * a(i, 1) + a(i, 2) * a(i, 2) + a(i, 3) * a(i, 3));
            if (!(std::abs(n - 1.0) < 1e-6))
                bad("orientations must be unit quaternions (w, x, y, z); row " + std::to_string(i) + " has length " +
                    std::to_string(n));
            e.elements[static_cast<std::size_t>(i)].orientation = {a(i, 0), a(i, 1), a(i, 2), a(i, 3)};
        }
    }
    if (!scales_arg.is_none()) {
        const auto a = shaped<Doubles>(scales_arg, "scales", elements, {}).unchecked<1>();
        for (py::ssize_t i = 0; i < elements; ++i) {
            if (!(std::isfinite(a(i)) && a(i) > 0.0)) bad("scales must be numbers > 0, row " + std::to_string(i));
            e.elements[static_cast<std::size_t>(i)].scale = a(i);
        }
    }
    if (!ids_arg.is_none()) {
        using Ids = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>;
        const Ids arr = shaped<Ids>(ids_arg, "ids", elements, {});
        const auto a = arr.unchecked<1>();
        std::set<std::uint64_t> seen;
        for (py::ssize_t i = 0; i < elements; ++i) {
            if (!seen.insert(a(i)).second) bad("ids must be unique; " + std::to_string(a(i)) + " repeats");
            e.elements[static_cast<std::size_t>(i)].id = a(i);
        }
    }
    if (!locked_arg.is_none()) {
        using Bools = py::array_t<bool, py::array::c_style | py::array::forcecast>;
        const Bools arr = shaped<Bools>(locked_arg, "locked", elements, {});
        const auto a = arr.unchecked<1>();
        for (py::ssize_t i = 0; i < elements; ++i) e.elements[static_cast<std::size_t>(i)].locked = a(i);
    }
    if (!times_arg.is_none()) {
        const auto a = shaped<Doubles>(times_arg, "times", samples, {}).unchecked<1>();
        for (py::ssize_t i = 0; i < samples; ++i) e.samples[static_cast<std::size_t>(i)].time = a(i);
    }
    if (!attribute_names_arg.is_none()) {
        try {
            e.attribute_names = attribute_names_arg.cast<std::vector<std::string>>();
        } catch (const py::cast_error&) {
            bad("attribute_names must be a sequence of strings");
        }
    }
    if (!attributes_arg.is_none()) {
        if (e.attribute_names.empty()) bad("attributes need attribute_names (one name per column)");
        const Doubles arr = shaped<Doubles>(attributes_arg, "attributes", elements,
                                            {static_cast<py::ssize_t>(e.attribute_names.size())});
        const auto a = arr.unchecked<2>();
        for (py::ssize_t i = 0; i < elements; ++i)
            for (py::ssize_t k = 0; k < arr.shape(1); ++k)
                e.elements[static_cast<std::size_t>(i)].attributes.push_back(a(i, k));
    } else if (!e.attribute_names.empty()) {
        bad("attribute_names given without attributes");
    }
    if (!types_arg.is_none()) {
        std::vector<py::dict> types;
        try {
            types = types_arg.cast<std::vector<py::dict>>();
        } catch (const py::cast_error&) {
            bad("types must be a list of dicts");
        }
        for (std::size_t t = 0; t < types.size(); ++t) {
            const std::string where = "types[" + std::to_string(t) + "]";
            if (!types[t].contains("name")) bad(where + " needs a 'name'");
            const std::string name = py::str(types[t]["name"]);
            const int index = e.find_type(name);
            if (index < 0) bad(where + ": '" + name + "' is not one of class_names");
            apply_type(e.types[static_cast<std::size_t>(index)], types[t], where);
        }
    }
    if (domain_arg.is_none()) {
        e.domain = bounding_box(e);
    } else {
        try {
            e.domain = domain_arg.cast<tessera::Domain>();
        } catch (const py::cast_error&) {
            bad("domain must be a tessera.Domain");
        }
        if (e.domain.dimension() != e.dimension)
            throw tessera::Error(tessera::ErrorKind::domain,
                                 "domain is " + std::to_string(e.domain.dimension()) + "D but positions are " +
                                     std::to_string(e.dimension) + "D");
    }
    e.validate("arrays");
    return e;
}

template <class Class>
void data_properties(Class& c) {
    using E = tessera::Exemplar;
    c.def_property_readonly("dimension", [](const E& e) { return e.dimension; }, "2 or 3.")
        .def_property_readonly(
            "class_names",
            [](const E& e) {
                std::vector<std::string> names;
                for (const auto& t : e.types) names.push_back(t.name);
                return names;
            },
            "Names of the element classes (types); `classes` indexes this list.")
        .def_property_readonly("types", &types_of,
                               "Element types as dicts: name, rigid, floor, mesh, color, reference, depends_on.")
        .def_property_readonly("attribute_names", [](const E& e) { return e.attribute_names; })
        .def_property("domain", [](const E& e) { return e.domain; },
                      [](E& e, const tessera::Domain& d) {
                          if (d.dimension() != e.dimension) bad("domain must have the data's dimension");
                          e.domain = d;
                      },
                      "The domain the elements live in.")
        .def_property_readonly("element_count", [](const E& e) { return e.elements.size(); })
        .def_property_readonly("sample_count", [](const E& e) { return e.samples.size(); })
        .def("__len__", [](const E& e) { return e.elements.size(); })
        .def_property_readonly("positions", &positions_of, "Sample positions, S x d (a copy).")
        .def_property_readonly(
            "element_of_sample", [](const E& e) { return per_sample<long long>(e, [](const auto& s) { return s.element; }); },
            "Index of each sample's element, S.")
        .def_property_readonly(
            "sample_ids", [](const E& e) { return per_sample<long long>(e, [](const auto& s) { return s.sample_id; }); },
            "Position of each sample within its element (0, 1, ...), S.")
        .def_property_readonly(
            "times", [](const E& e) { return per_sample<double>(e, [](const auto& s) { return s.time; }); },
            "Time stamp of each sample, S (0 for static data).")
        .def_property_readonly(
            "classes", [](const E& e) { return per_element<long long>(e, [](const auto& el) { return el.type; }); },
            "Class (type index) of each element, E.")
        .def_property_readonly(
            "radii", [](const E& e) { return per_element<double>(e, [](const auto& el) { return el.radius; }); },
            "Radius of each element, E (0 = none).")
        .def_property_readonly("orientations", &orientations_of, "Orientation quaternion of each element, E x 4 (w, x, y, z).")
        .def_property_readonly(
            "scales", [](const E& e) { return per_element<double>(e, [](const auto& el) { return el.scale; }); },
            "Uniform scale of each element, E.")
        .def_property_readonly(
            "ids", [](const E& e) { return per_element<std::uint64_t>(e, [](const auto& el) { return el.id; }); },
            "Stable id of each element, E (uint64).")
        .def_property_readonly(
            "locked", [](const E& e) { return per_element<bool>(e, [](const auto& el) { return el.locked; }); },
            "Lock flag of each element, E (locked elements are never moved).")
        .def_property_readonly("centroids", &centroids_of, "Position of each element (its samples' centroid), E x d.")
        .def_property_readonly("attributes", &attributes_of, "Free attributes, E x len(attribute_names).")
        .def("copy", [](const typename Class::type& e) { return e; });
}

}  // namespace

// The "stats" object of an output .json file (one list of fields, kept by the library's
// writer), plus the timings and thread count a file leaves out for byte-identical output.
py::dict stats_of(const tessera::RunStats& s) {
    py::dict d = py::module_::import("json").attr("loads")(tessera::run_stats_json(s));
    d["iteration_seconds"] = s.iteration_seconds;
    d["init_seconds"] = s.init_seconds;
    d["total_seconds"] = s.total_seconds;
    d["threads"] = s.threads;
    return d;
}

void bind_data(py::module_& m) {
    py::class_<tessera::Exemplar> exemplar(m, "Exemplar",
                                           "Elements (of one or more samples) with their classes, poses and the "
                                           "domain they were observed in.");
    data_properties(exemplar);
    exemplar.def("__repr__", [](const tessera::Exemplar& e) {
        return "<tessera.Exemplar " + std::to_string(e.dimension) + "D, " + std::to_string(e.elements.size()) +
               " elements of " + std::to_string(e.types.size()) + " classes in " + e.domain.describe() + ">";
    });
    py::class_<tessera::Arrangement, tessera::Exemplar> arrangement(
        m, "Arrangement", "The output of a synthesis: an Exemplar plus the statistics of the run.");
    arrangement.def_property_readonly("stats", [](const tessera::Arrangement& a) { return stats_of(a.stats); },
                                      "Statistics of the run as a dict: the \"stats\" object of a saved .json (method, energy "
                                      "per iteration, notes, fallbacks, ...) plus iteration_seconds, init_seconds, "
                                      "total_seconds and threads.");
    arrangement.def("copy", [](const tessera::Arrangement& a) { return a; });
    arrangement.def("__repr__", [](const tessera::Arrangement& e) {
        return "<tessera.Arrangement " + std::to_string(e.dimension) + "D, " + std::to_string(e.elements.size()) +
               " elements of " + std::to_string(e.types.size()) + " classes in " + e.domain.describe() + ">";
    });
    m.def("make_exemplar", &make_exemplar, py::arg("positions"), py::arg("classes"), py::arg("class_names"),
          py::arg("radii"), py::arg("orientations"), py::arg("scales"), py::arg("ids"), py::arg("locked"),
          py::arg("element_of_sample"), py::arg("sample_ids"), py::arg("times"), py::arg("attributes"),
          py::arg("attribute_names"), py::arg("domain"), py::arg("types"));
}

}  // namespace tessera_python
