// tessera::BrushCanvas for Python (brushing element fields, include/tessera/brush.hpp). As for
// Grower, options arrive as a dict keyed by the Python keywords (checked by the library's
// option table), the GIL is released while a call runs, and the progress callable is called
// with the GIL held. A canvas serves one thread at a time: a call from a second thread while
// one runs is a RuntimeError, not a race.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>
#include <stdexcept>
#include <thread>

#include "bindings.hpp"
#include "convert.hpp"
#include "option_table.hpp"
#include "option_values.hpp"
#include "tessera/brush.hpp"

namespace py = pybind11;

namespace tessera_python {
namespace {

py::dict report_of(const tessera::BrushReport& r) {
    py::dict d;
    d["added"] = r.added, d["removed"] = r.removed, d["iterations"] = r.iterations;
    d["lbfgs_bound_hits"] = r.lbfgs_bound_hits, d["solve_bound_hits"] = r.solve_bound_hits;
    d["kept_earlier"] = r.kept_earlier, d["energy"] = r.energy, d["seconds"] = r.seconds;
    return d;
}

struct PyCanvas {
    explicit PyCanvas(tessera::BrushCanvas c) : canvas(std::move(c)) {}
    tessera::BrushCanvas canvas;
    bool busy = false;  // read and written with the GIL held
};

// Runs a call on the canvas with the GIL released and the progress callable installed.
template <class Call>
py::dict run(PyCanvas& c, const py::object& callback, const Call& call) {
    if (c.busy) throw std::runtime_error("this BrushCanvas is in use (a canvas serves one call at a time)");
    c.busy = true;
    struct Done {
        PyCanvas& c;
        ~Done() { c.canvas.set_progress({}), c.busy = false; }
    } done{c};
    PythonProgress progress{callback};
    c.canvas.set_progress(progress.progress());
    std::optional<tessera::BrushReport> report;
    {
        py::gil_scoped_release release;
        try {
            report = call(c.canvas);
        } catch (const tessera::Cancelled&) {
            if (!*progress.raised) throw;
        }
    }
    progress.rethrow();
    return report_of(*report);
}

const tessera::BrushCanvas& reading(const PyCanvas& c) {
    if (c.busy) throw std::runtime_error("this BrushCanvas is in use (a canvas serves one call at a time)");
    return c.canvas;
}

tessera::Stroke stroke_of(const py::handle& points, double width) {
    tessera::Stroke s;
    s.points = to_points(points, "stroke");
    s.width = width;
    return s;
}

py::array_t<double> directions_of(const tessera::BrushCanvas& c) {
    const std::vector<tessera::Vec3>& d = c.sample_directions();
    const int dim = c.arrangement().dimension;
    auto out = new_array<double>({static_cast<py::ssize_t>(d.size()), dim});
    auto m = out.mutable_unchecked<2>();
    for (std::size_t i = 0; i < d.size(); ++i)
        for (int k = 0; k < dim; ++k) m(static_cast<py::ssize_t>(i), k) = d[i][k];
    return out;
}

py::dict energies_of(const tessera::BrushCanvas& c) {
    const tessera::BrushCanvas::Energies e = c.energies();
    py::dict d;
    d["distribution"] = e.distribution, d["conflict"] = e.conflict, d["graph"] = e.graph;
    d["alignment"] = e.alignment, d["continuity"] = e.continuity, d["rigidity"] = e.rigidity;
    return d;
}

std::unique_ptr<PyCanvas> make_canvas(const tessera::Domain& domain, const py::dict& options) {
    tessera::BrushOptions o;
    apply_keywords(tessera::brush_option_table(), o, options, domain.dimension(), "BrushCanvas");
    return std::make_unique<PyCanvas>(tessera::BrushCanvas(domain, o));
}

std::unique_ptr<PyCanvas> replay(const std::string& path, const py::dict& options, const py::object& callback) {
    tessera::BrushSession session = tessera::read_brush_session(path);
    apply_keywords(tessera::brush_option_table(), session.options, options, session.dimension, "brush");
    PythonProgress progress{callback};
    std::optional<tessera::BrushCanvas> canvas;
    {
        py::gil_scoped_release release;
        try {
            canvas.emplace(tessera::replay_brush_session(session, progress.progress()));
        } catch (const tessera::Cancelled&) {
            if (!*progress.raised) throw;
        }
    }
    progress.rethrow();
    return std::make_unique<PyCanvas>(std::move(*canvas));
}

}  // namespace

void bind_brush(py::module_& m) {
    py::class_<PyCanvas>(m, "BrushCanvas", "A canvas painted with element brushes (use tessera.BrushCanvas).")
        .def(py::init(&make_canvas), py::arg("domain"), py::arg("options"))
        .def(
            "add_exemplar",
            [](PyCanvas& c, const std::string& name, const tessera::Exemplar& ex) {
                if (c.busy) throw std::runtime_error("this BrushCanvas is in use");
                return c.canvas.add_exemplar(name, ex);
            },
            py::arg("name"), py::arg("exemplar"))
        .def(
            "paint",
            [](PyCanvas& c, int entry, const py::handle& stroke, double width, const py::object& progress) {
                const tessera::Stroke s = stroke_of(stroke, width);
                return run(c, progress, [&](tessera::BrushCanvas& canvas) { return canvas.paint(entry, s); });
            },
            py::arg("entry"), py::arg("stroke"), py::arg("width"), py::arg("progress"))
        .def(
            "direct",
            [](PyCanvas& c, const py::handle& stroke) {
                const tessera::Stroke s = stroke_of(stroke, 0.0);
                return run(c, py::none(), [&](tessera::BrushCanvas& canvas) { return canvas.direct(s); });
            },
            py::arg("stroke"))
        .def(
            "erase",
            [](PyCanvas& c, const py::handle& stroke, double width) {
                const tessera::Stroke s = stroke_of(stroke, width);
                return run(c, py::none(), [&](tessera::BrushCanvas& canvas) { return canvas.erase(s); });
            },
            py::arg("stroke"), py::arg("width"))
        .def(
            "fill",
            [](PyCanvas& c, const std::vector<int>& entries, const py::object& progress) {
                return run(c, progress, [&](tessera::BrushCanvas& canvas) { return canvas.fill(entries); });
            },
            py::arg("entries"), py::arg("progress"))
        .def(
            "optimize",
            [](PyCanvas& c, int iterations, const py::object& progress) {
                return run(c, progress, [&](tessera::BrushCanvas& canvas) { return canvas.optimize(iterations); });
            },
            py::arg("iterations"), py::arg("progress"))
        .def("find_exemplar", [](const PyCanvas& c, const std::string& name) { return reading(c).find_exemplar(name); })
        .def_property_readonly("palette", [](const PyCanvas& c) { return reading(c).palette(); })
        .def_property_readonly("arrangement", [](const PyCanvas& c) { return reading(c).arrangement(); })
        .def_property_readonly("sample_directions", [](const PyCanvas& c) { return directions_of(reading(c)); })
        .def_property_readonly("sample_exemplars",
                               [](const PyCanvas& c) { return to_array(reading(c).sample_exemplars()); })
        .def_property_readonly("energies", [](const PyCanvas& c) { return energies_of(reading(c)); })
        .def("__len__", [](const PyCanvas& c) { return reading(c).arrangement().elements.size(); });
    m.def("brush_session", &replay, py::arg("path"), py::arg("options"), py::arg("progress"));
}

}  // namespace tessera_python
