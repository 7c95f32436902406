// Files, pictures and statistics for Python: load and save by extension (tessera/io.hpp;
// save also writes the scenes of the elements' geometry), preview pictures
// (tessera/render.hpp), and the metrics of tessera/metrics.hpp.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "convert.hpp"
#include "option_table.hpp"
#include "tessera/io.hpp"
#include "tessera/metrics.hpp"
#include "tessera/option_text.hpp"
#include "tessera/render.hpp"

namespace py = pybind11;

namespace tessera_python {
namespace {

// The estimate's keywords (r_max=, bandwidth=, bins=), checked by its option table.
tessera::PcfOptions pcf_options(const py::dict& given, const std::string& owner) {
    tessera::PcfOptions o;
    apply_keywords(tessera::pair_correlation_option_table(), o, given, 0, owner);
    return o;
}

template <class Data>
void save_data(const Data& data, const std::string& path, const std::string& gltf_instancing) {
    tessera::SaveOptions options;
    options.gltf_instancing = tessera::parse_gltf_instancing(gltf_instancing, "gltf_instancing");
    py::gil_scoped_release release;
    tessera::save(data, path, options);
}

}  // namespace

void bind_io(py::module_& m) {
    m.def(
        "load",
        [](const std::string& path, const py::object& input_domain) {
            tessera::LoadOptions options;
            if (!input_domain.is_none()) options.input_domain = input_domain.cast<tessera::Domain>();
            py::gil_scoped_release release;
            return tessera::load(path, options);
        },
        py::arg("path"), py::arg("input_domain"));
    // Arrangement first: pybind11 tries overloads in order, and its JSON records the run statistics.
    m.def("save", &save_data<tessera::Arrangement>, py::arg("data"), py::arg("path"), py::arg("gltf_instancing"));
    m.def("save", &save_data<tessera::Exemplar>, py::arg("data"), py::arg("path"), py::arg("gltf_instancing"));
    m.def(
        "render",
        [](const tessera::Exemplar& data, const std::string& path, int width, const std::string& meshes,
           bool legend) {
            tessera::RenderOptions options;
            options.width = width;
            options.meshes = tessera::parse_render_meshes(meshes, "meshes");
            options.show_legend = legend;
            py::gil_scoped_release release;
            tessera::render_to_file(data, path, options);
        },
        py::arg("data"), py::arg("path"), py::arg("width"), py::arg("meshes"), py::arg("legend"));
    m.def(
        "metrics_report",
        [](const tessera::Exemplar& exemplar, const tessera::Exemplar& output, const py::dict& options) {
            const tessera::PcfOptions o = pcf_options(options, "metrics");
            py::gil_scoped_release release;
            return tessera::metrics_report_json(exemplar, output, o);
        },
        py::arg("exemplar"), py::arg("output"), py::arg("options"));
    m.def(
        "pair_correlation",
        [](const tessera::Exemplar& data, const py::dict& options) {
            const tessera::PcfOptions o = pcf_options(options, "pair_correlation");
            tessera::PcfResult result;
            {
                py::gil_scoped_release release;
                result = tessera::pair_correlation(data, o);
            }
            py::dict curves;
            for (const auto& c : result.curves) curves[py::make_tuple(c.name_a, c.name_b)] = to_array(c.g);
            return py::make_tuple(to_array(result.r), curves, result.bandwidth);
        },
        py::arg("data"), py::arg("options"));
}

}  // namespace tessera_python
