// synthesize for Python (det, pcf; dynamic over animations): options arrive as a dict keyed
// by the Python keyword names (checked by the library's option tables, option_table.hpp), the
// GIL is released while the library works, and the progress callable is called with the GIL
// held. A callable that raises cancels the run and its exception reaches the caller; one that
// returns False cancels it with tessera.Cancelled.
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <optional>
#include <type_traits>

#include "bindings.hpp"
#include "convert.hpp"
#include "option_table.hpp"
#include "option_values.hpp"
#include "tessera/brush.hpp"
#include "tessera/det.hpp"
#include "tessera/dynamic.hpp"
#include "tessera/edit.hpp"
#include "tessera/graph_motion.hpp"
#include "tessera/option_text.hpp"
#include "tessera/grow.hpp"
#include "tessera/metrics.hpp"
#include "tessera/motion_analysis.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace py = pybind11;

namespace tessera_python {
namespace {

// Runs `method(progress)` with the GIL released; its result (Arrangement, AnimatedArrangement).
template <class Method>
auto run(const Method& method, const py::object& callback) {
    using Result = std::invoke_result_t<const Method&, const tessera::Progress&>;
    PythonProgress progress{callback};
    const tessera::Progress p = progress.progress();
    std::optional<Result> result;
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

void check_dimension(const tessera::Domain& domain, const tessera::Exemplar& exemplar) {
    if (domain.dimension() != exemplar.dimension)
        throw tessera::Error(tessera::ErrorKind::domain, "domain is " + std::to_string(domain.dimension()) +
                                                             "D but the exemplar is " +
                                                             std::to_string(exemplar.dimension) + "D");
}

tessera::Arrangement synthesize(const tessera::Exemplar& exemplar, const tessera::Domain& domain,
                                const std::string& method, const py::dict& options, const py::object& callback) {
    check_dimension(domain, exemplar);
    if (method == "det") {
        tessera::DetOptions o;
        apply_keywords(tessera::det_option_table(), o, options, exemplar.dimension, "method 'det'");
        if (!o.boundary_sides.empty() && !(o.boundary_distance > 0.0)) bad("boundary needs boundary_distance > 0");
        return run([&](const tessera::Progress& p) { return tessera::synthesize_det(exemplar, domain, o, p); },
                   callback);
    }
    if (method == "pcf") {
        tessera::PcfSynthOptions o;
        apply_keywords(tessera::pcf_option_table(), o, options, exemplar.dimension, "method 'pcf'");
        return run([&](const tessera::Progress& p) { return tessera::synthesize_pcf(exemplar, domain, o, p); },
                   callback);
    }
    bad("method must be 'det' or 'pcf', got '" + method + "'");
}

// method="dynamic": an animation over `domain`, frame by frame (tessera/dynamic.hpp).
tessera::AnimatedArrangement synthesize_dynamic(const tessera::Animation& exemplar, const tessera::Domain& domain,
                                                const py::dict& options, const py::object& callback) {
    check_dimension(domain, exemplar.structure);
    tessera::DynamicOptions o;
    apply_keywords(tessera::dynamic_option_table(), o, options, exemplar.structure.dimension, "method 'dynamic'");
    return run([&](const tessera::Progress& p) { return tessera::synthesize_dynamic(exemplar, domain, o, p); },
               callback);
}

// coarse=: the exemplar's detail motion on a coarse motion, all frames together.
tessera::AnimatedArrangement synthesize_on_coarse(const tessera::Animation& exemplar, const tessera::Animation& coarse,
                                                  const py::dict& options, const py::object& callback) {
    tessera::DynamicOptions o;
    apply_keywords(tessera::dynamic_option_table(), o, options, exemplar.structure.dimension, "method 'dynamic'");
    return run([&](const tessera::Progress& p) { return tessera::synthesize_on_coarse(exemplar, coarse, o, p); },
               callback);
}

tessera::Arrangement synthesize_model(const tessera::PcfModel& model, const tessera::Domain& domain,
                                      const py::dict& options, const py::object& callback) {
    tessera::PcfSynthOptions o;
    o.analysis = model.settings;
    for (const auto& [key, value] : options) {
        const std::string name = py::str(key);
        if (name == "sigma" || name == "step" || name == "extent")
            bad(name + " is fixed by the analysed model; analyze the exemplar again to change it");
    }
    apply_keywords(tessera::pcf_option_table(), o, options, 2, "method 'pcf'");
    return run([&](const tessera::Progress& p) { return tessera::synthesize_pcf(model, domain, o, p); }, callback);
}

}  // namespace

void bind_synthesize(py::module_& m) {
    m.def("synthesize", &synthesize, py::arg("exemplar"), py::arg("domain"), py::arg("method"), py::arg("options"),
          py::arg("progress"));
    m.def("synthesize_dynamic", &synthesize_dynamic, py::arg("exemplar"), py::arg("domain"), py::arg("options"),
          py::arg("progress"));
    m.def("synthesize_on_coarse", &synthesize_on_coarse, py::arg("exemplar"), py::arg("coarse"), py::arg("options"),
          py::arg("progress"));
    m.def("synthesize_model", &synthesize_model, py::arg("model"), py::arg("domain"), py::arg("options"),
          py::arg("progress"));
    m.def(
        "option_tables",
        [] {
            py::dict tables;
            tables["det"] = describe_table(tessera::det_option_table());
            tables["pcf"] = describe_table(tessera::pcf_option_table());
            tables["dynamic"] = describe_table(tessera::dynamic_option_table());  // synthesize(method="dynamic")
            tables["grow"] = describe_table(tessera::grow_option_table());
            tables["brush"] = describe_table(tessera::brush_option_table());  // tessera.BrushCanvas, tessera.brush
            tables["edit"] = describe_table(tessera::edit_option_table());  // `tessera edit` (no Python call yet)
            tables["analyze"] = describe_table(tessera::pcf_analysis_option_table());  // tessera.analyze
            tables["low_pass"] = describe_table(tessera::low_pass_option_table());  // tessera.decompose
            tables["graph_motion"] = describe_table(tessera::graph_motion_option_table());  // tessera.animate
            // tessera.pair_correlation and tessera.metrics (`analyze --standard-pcf`, `metrics`)
            tables["pair_correlation"] = describe_table(tessera::pair_correlation_option_table());
            return tables;
        },
        "Every option of every method, from the library's tables (tessera/option_table.hpp): per method a "
        "list of dicts (name, keyword, flag, kind, default, doc, choices, accepts). tessera.synthesize and "
        "tessera.Grower, tessera.pair_correlation and tessera.metrics take their keywords from them.");
}

}  // namespace tessera_python
