// tessera::Domain for Python: the constructors of every kind, queries, and the CLI's text
// forms (tessera/option_text.hpp) through parse_output_domain.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "convert.hpp"
#include "tessera/domain.hpp"
#include "tessera/option_text.hpp"

namespace py = pybind11;

namespace tessera_python {
namespace {

const char* kind_name(tessera::Domain::Kind kind) {
    switch (kind) {
        case tessera::Domain::Kind::box: return "box";
        case tessera::Domain::Kind::polygon: return "polygon";
        case tessera::Domain::Kind::mask: return "mask";
        case tessera::Domain::Kind::mesh: return "mesh";
        case tessera::Domain::Kind::shell: return "shell";
    }
    return "box";
}

py::tuple point_tuple(const tessera::Vec3& p, int dimension) {
    return dimension == 2 ? py::make_tuple(p.x, p.y) : py::make_tuple(p.x, p.y, p.z);
}

}  // namespace

void bind_domain(py::module_& m) {
    py::class_<tessera::Domain>(m, "Domain",
                                "Where elements live: a box, a 2D polygon with holes, a 2D image mask, or the "
                                "volume of / the shell under a 3D mesh (docs/format.md, \"Domains\").")
        .def_static(
            "box",
            [](const py::handle& lo, const py::handle& hi) {
                const tessera::Vec3 a = to_vec3(lo, "lo"), b = to_vec3(hi, "hi");
                const int dimension = py::len(lo) == 3 ? 3 : 2;
                if (static_cast<int>(py::len(hi)) != dimension)
                    throw tessera::Error(tessera::ErrorKind::option, "lo and hi must have the same length (2 or 3)");
                return tessera::Domain::box(a, b, dimension);
            },
            py::arg("lo"), py::arg("hi"),
            "An axis-aligned box from corner lo to corner hi: (x, y) pairs in 2D, (x, y, z) in 3D.")
        .def_static(
            "polygon",
            [](const py::handle& outer, const std::vector<py::object>& holes) {
                std::vector<std::vector<tessera::Vec3>> rings;
                for (const auto& h : holes) rings.push_back(to_points(h, "hole"));
                return tessera::Domain::polygon(to_points(outer, "outer"), rings);
            },
            py::arg("outer"), py::arg("holes") = std::vector<py::object>{},
            "A 2D polygon: outer ring as a sequence of (x, y), optional holes likewise (even-odd rule).")
        .def_static(
            "mask",
            [](const std::string& path, const py::handle& lo, const py::handle& hi, double threshold) {
                return tessera::Domain::mask(path, to_vec3(lo, "lo"), to_vec3(hi, "hi"), threshold);
            },
            py::arg("path"), py::arg("lo"), py::arg("hi"), py::arg("threshold") = 0.5,
            "A 2D grayscale PNG mapped onto the box lo..hi (white = inside, gray level >= threshold).")
        .def_static("mesh", py::overload_cast<const std::string&, int>(&tessera::Domain::mesh), py::arg("path"),
                    py::arg("resolution") = 128,
                    "The volume enclosed by a triangle mesh file (OBJ or ASCII PLY), on a voxel grid of "
                    "`resolution` cells along its longest axis (16..1024).")
        .def_static("shell", py::overload_cast<const std::string&, double, int>(&tessera::Domain::shell),
                    py::arg("path"), py::arg("thickness"), py::arg("resolution") = 128,
                    "The band of a mesh's volume within `thickness` of its surface.")
        .def_static(
            "parse",
            [](const std::string& spec, const tessera::Exemplar& exemplar, double scale) {
                return tessera::parse_output_domain(spec, exemplar, scale, "domain");
            },
            py::arg("spec"), py::arg("exemplar"), py::arg("scale") = 2.0,
            "A domain from the CLI's --domain text (box:W,H[,D], box:xmin,ymin,xmax,ymax[,zmin,zmax], "
            "polygon:..., mask:..., mesh:..., shell:...), relative to the exemplar's domain.")
        .def_property_readonly("kind", [](const tessera::Domain& d) { return kind_name(d.kind()); },
                               "'box', 'polygon', 'mask', 'mesh' or 'shell'.")
        .def_property_readonly("dimension", &tessera::Domain::dimension)
        .def_property_readonly(
            "bounds",
            [](const tessera::Domain& d) {
                return py::make_tuple(point_tuple(d.bounds().lo, d.dimension()),
                                      point_tuple(d.bounds().hi, d.dimension()));
            },
            "The bounding box as (lo, hi).")
        .def_property_readonly("measure", &tessera::Domain::measure, "Area (2D) or volume (3D).")
        .def_property_readonly("notes", &tessera::Domain::notes, "Repairs and remarks about the shape ('' if none).")
        .def(
            "contains", [](const tessera::Domain& d, const py::handle& p) { return d.inside(to_vec3(p, "point")); },
            py::arg("point"), "True when the point is inside the domain.")
        .def("scaled", &tessera::Domain::scaled, py::arg("factor"),
             "The same shape scaled by `factor` about the lower corner of its bounds.")
        .def("__repr__", [](const tessera::Domain& d) { return "<tessera.Domain " + d.describe() + ">"; })
        .def("__str__", &tessera::Domain::describe);
}

}  // namespace tessera_python
