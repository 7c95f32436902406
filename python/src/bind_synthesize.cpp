// synthesize for Python: options arrive as a dict keyed by the Python keyword names
// (python/tessera/__init__.py fills in the CLI's defaults), the GIL is released while the
// library works, and the progress callable is called with the GIL held. A callable that
// raises cancels the run and its exception reaches the caller; one that returns False
// cancels it with tessera.Cancelled.
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <optional>

#include "bindings.hpp"
#include "convert.hpp"
#include "option_values.hpp"
#include "tessera/det.hpp"
#include "tessera/option_text.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace py = pybind11;

namespace tessera_python {
namespace {

void apply_det(tessera::DetOptions& o, const std::string& key, const py::handle& v, int dimension) {
    if (key == "seed") o.seed = get<std::uint64_t>(v, key, "an unsigned 64-bit integer");
    else if (key == "threads") o.threads = integer(v, key);
    else if (key == "iterations") o.iterations = integer(v, key);
    else if (key == "radius") o.radius = number(v, key);
    else if (key == "k") o.k = integer(v, key);
    else if (key == "search") o.search = tessera::parse_search_mode(text(v, key), key);
    else if (key == "matching") o.matching = tessera::parse_matching(text(v, key), key);
    else if (key == "alpha") o.alpha = number(v, key);
    else if (key == "lambda_") o.lambda = number(v, key);
    else if (key == "patch_size") o.patch_size = number(v, key);
    else if (key == "patch_candidates") o.patch_candidates = integer(v, key);
    else if (key == "relax_sweeps") o.relax_sweeps = integer(v, key);
    else if (key == "physics") o.physics = get<bool>(v, key, "True or False");
    else if (key == "physics_substeps") o.physics_options.substeps = integer(v, key);
    else if (key == "floor_distance") o.floor_distance = number(v, key);
    else if (key == "boundary_distance") o.boundary_distance = number(v, key);
    else if (key == "gravity") {
        if (!v.is_none())
            o.gravity = py::isinstance<py::str>(v) ? tessera::parse_axis_direction(text(v, key), key) : to_vec3(v, key);
    } else if (key == "boundary") {
        if (v.is_none()) return;
        std::string sides;
        if (py::isinstance<py::str>(v)) {
            sides = text(v, key);
        } else {
            for (const auto side : v) sides += (sides.empty() ? "" : ",") + text(side, key);
        }
        o.boundary_sides = tessera::parse_boundary_sides(sides, key);
    } else if (key == "field") {
        if (!v.is_none()) o.field = tessera::OrientationField::parse(text(v, key), dimension, key);
    } else {
        bad("unknown option '" + key + "' for method 'det'");
    }
}

void apply_pcf(tessera::PcfSynthOptions& o, const std::string& key, const py::handle& v) {
    if (key == "seed") o.seed = get<std::uint64_t>(v, key, "an unsigned 64-bit integer");
    else if (key == "threads") o.threads = integer(v, key);
    else if (key == "iterations") o.max_iterations = integer(v, key);
    else if (key == "relax_sweeps") o.relax_sweeps = integer(v, key);
    else if (key == "max_fails") o.max_fails = integer(v, key);
    else if (key == "grid_cells") o.grid_cells = integer(v, key);
    else if (key == "epsilon0") o.epsilon0 = number(v, key);
    else if (key == "epsilon_step") o.epsilon_step = number(v, key);
    else if (key == "convergence") o.convergence = number(v, key);
    else if (key == "stall") o.stall = number(v, key);
    else if (key == "outlier_rounds") o.outlier_rounds = integer(v, key);
    else if (key == "sigma") o.analysis.sigma = number(v, key);
    else if (key == "step") o.analysis.step = number(v, key);
    else if (key == "extent") o.analysis.extent = number(v, key);
    else bad("unknown option '" + key + "' for method 'pcf'");
}


tessera::Arrangement run(const std::function<tessera::Arrangement(const tessera::Progress&)>& method,
                         const py::object& callback) {
    PythonProgress progress{callback};
    const tessera::Progress p = progress.progress();
    std::optional<tessera::Arrangement> result;
    {
        py::gil_scoped_release release;
        try {
            result = method(p);
        } catch (const tessera::Cancelled&) {
            if (!*progress.raised) throw;
        }
    }
    if (*progress.raised) {
        py::error_already_set error = std::move(**progress.raised);
        progress.raised->reset();
        throw error;
    }
    return std::move(*result);
}

tessera::Arrangement synthesize(const tessera::Exemplar& exemplar, const tessera::Domain& domain,
                                const std::string& method, const py::dict& options, const py::object& callback) {
    if (domain.dimension() != exemplar.dimension)
        throw tessera::Error(tessera::ErrorKind::domain, "domain is " + std::to_string(domain.dimension()) +
                                                             "D but the exemplar is " +
                                                             std::to_string(exemplar.dimension) + "D");
    if (method == "det") {
        tessera::DetOptions o;
        for (const auto& [key, value] : options) apply_det(o, py::str(key), value, exemplar.dimension);
        if (!o.boundary_sides.empty() && !(o.boundary_distance > 0.0)) bad("boundary needs boundary_distance > 0");
        return run([&](const tessera::Progress& p) { return tessera::synthesize_det(exemplar, domain, o, p); },
                   callback);
    }
    if (method == "pcf") {
        tessera::PcfSynthOptions o;
        for (const auto& [key, value] : options) apply_pcf(o, py::str(key), value);
        return run([&](const tessera::Progress& p) { return tessera::synthesize_pcf(exemplar, domain, o, p); },
                   callback);
    }
    bad("method must be 'det' or 'pcf', got '" + method + "'");
}

tessera::Arrangement synthesize_model(const tessera::PcfModel& model, const tessera::Domain& domain,
                                      const py::dict& options, const py::object& callback) {
    tessera::PcfSynthOptions o;
    o.analysis = model.settings;
    for (const auto& [key, value] : options) {
        const std::string name = py::str(key);
        if (name == "sigma" || name == "step" || name == "extent")
            bad(name + " is fixed by the analysed model; analyze the exemplar again to change it");
        apply_pcf(o, name, value);
    }
    return run([&](const tessera::Progress& p) { return tessera::synthesize_pcf(model, domain, o, p); }, callback);
}

}  // namespace

void bind_synthesize(py::module_& m) {
    m.def("synthesize", &synthesize, py::arg("exemplar"), py::arg("domain"), py::arg("method"), py::arg("options"),
          py::arg("progress"));
    m.def("synthesize_model", &synthesize_model, py::arg("model"), py::arg("domain"), py::arg("options"),
          py::arg("progress"));
    m.def("default_options", [] {
        const tessera::DetOptions d;
        const tessera::PcfSynthOptions p;
        py::dict det, pcf;
        det["seed"] = d.seed, det["threads"] = d.threads, det["iterations"] = d.iterations;
        det["radius"] = d.radius, det["k"] = d.k, det["search"] = tessera::to_string(d.search);
        det["matching"] = tessera::to_string(d.matching), det["alpha"] = d.alpha, det["lambda_"] = d.lambda;
        det["patch_size"] = d.patch_size, det["patch_candidates"] = d.patch_candidates;
        det["relax_sweeps"] = d.relax_sweeps;
        det["physics"] = d.physics, det["physics_substeps"] = d.physics_options.substeps;
        det["floor_distance"] = d.floor_distance, det["boundary_distance"] = d.boundary_distance;
        pcf["seed"] = p.seed, pcf["threads"] = p.threads, pcf["iterations"] = p.max_iterations;
        pcf["relax_sweeps"] = p.relax_sweeps;
        pcf["max_fails"] = p.max_fails, pcf["grid_cells"] = p.grid_cells, pcf["epsilon0"] = p.epsilon0;
        pcf["epsilon_step"] = p.epsilon_step, pcf["convergence"] = p.convergence, pcf["stall"] = p.stall;
        pcf["outlier_rounds"] = p.outlier_rounds, pcf["sigma"] = p.analysis.sigma, pcf["step"] = p.analysis.step;
        pcf["extent"] = p.analysis.extent;
        py::dict all;
        all["det"] = det;
        all["pcf"] = pcf;
        return all;
    }, "The library's option defaults per method (what the keyword defaults of tessera.synthesize mirror).");
}

}  // namespace tessera_python
