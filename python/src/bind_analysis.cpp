// The PCF method's analysed model for Python (tessera/pcf_synthesis.hpp, pcf_plot.hpp):
// analyze an exemplar, read and write the model's JSON, draw it, measure an arrangement
// against it and compare the two.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "convert.hpp"
#include "tessera/io.hpp"
#include "tessera/pcf_plot.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace py = pybind11;

namespace tessera_python {
namespace {

py::list envelopes(const std::vector<tessera::PcfEnvelope>& pcfs, const tessera::PcfModel& model) {
    py::list out;
    for (const auto& p : pcfs) {
        py::dict d;
        d["parent"] = model.classes[static_cast<std::size_t>(p.parent)];
        d["child"] = model.classes[static_cast<std::size_t>(p.child)];
        d["mean"] = to_array(p.mean);
        d["lower"] = to_array(p.lower);
        d["upper"] = to_array(p.upper);
        out.append(d);
    }
    return out;
}

py::dict shares(const tessera::DiskConfigurationShares& s) {
    py::dict d;
    d["disjoint"] = s.disjoint, d["tangent"] = s.tangent, d["overlapping"] = s.overlapping, d["nested"] = s.nested;
    d["pairs"] = s.pairs;
    return d;
}

}  // namespace

void bind_analysis(py::module_& m) {
    py::class_<tessera::PcfModel>(m, "PcfModel",
                                  "An exemplar analysed by the PCF method: its classes, dependency graph, r_max and "
                                  "one mean PCF with its validity envelope per class and per dependency.")
        .def_property_readonly("classes", [](const tessera::PcfModel& p) { return p.classes; })
        .def_property_readonly(
            "parents",
            [](const tessera::PcfModel& p) {
                py::dict d;
                for (std::size_t c = 0; c < p.classes.size(); ++c) {
                    std::vector<std::string> names;
                    for (int q : p.parents[c]) names.push_back(p.classes[static_cast<std::size_t>(q)]);
                    d[py::str(p.classes[c])] = names;
                }
                return d;
            },
            "The dependency graph: class name -> the classes it depends on.")
        .def_property_readonly(
            "order",
            [](const tessera::PcfModel& p) {
                std::vector<std::string> names;
                for (int c : p.order) names.push_back(p.classes[static_cast<std::size_t>(c)]);
                return names;
            },
            "The classes in the order synthesis places them.")
        .def_property_readonly("x", [](const tessera::PcfModel& p) { return to_array(p.x); },
                               "The normalised distance axis of every PCF.")
        .def_property_readonly("pcfs", [](const tessera::PcfModel& p) { return envelopes(p.pcfs, p); },
                               "One dict per PCF: parent, child, mean, lower, upper (arrays over x).")
        .def_property_readonly("counts", [](const tessera::PcfModel& p) { return p.counts; })
        .def_property_readonly("radii",
                               [](const tessera::PcfModel& p) {
                                   py::list l;
                                   for (const auto& r : p.radii) l.append(to_array(r));
                                   return l;
                               })
        .def_property_readonly("disks", [](const tessera::PcfModel& p) { return p.disks; })
        .def_property_readonly("r_max", [](const tessera::PcfModel& p) { return p.r_max; })
        .def_property_readonly("area", [](const tessera::PcfModel& p) { return p.area; })
        .def("to_json", &tessera::pcf_model_to_json, "The model as JSON text (what `tessera analyze -o` writes).")
        .def("__repr__", [](const tessera::PcfModel& p) {
            return "<tessera.PcfModel " + std::to_string(p.classes.size()) + " classes, " +
                   std::to_string(p.pcfs.size()) + " PCFs, r_max " + std::to_string(p.r_max) + ">";
        });
    m.def(
        "analyze",
        [](const tessera::Exemplar& exemplar, double sigma, double step, double extent) {
            tessera::PcfAnalysisSettings s;
            s.sigma = sigma, s.step = step, s.extent = extent;
            py::gil_scoped_release release;
            return tessera::analyze_distribution(exemplar, s);
        },
        py::arg("exemplar"), py::arg("sigma"), py::arg("step"), py::arg("extent"));
    m.def(
        "model_from_json",
        [](const std::string& text, const std::string& source) { return tessera::pcf_model_from_json(text, source); },
        py::arg("text"), py::arg("source"));
    m.def(
        "load_model", [](const std::string& path) { return tessera::pcf_model_from_json(tessera::read_file(path), path); },
        py::arg("path"));
    m.def(
        "save_model",
        [](const tessera::PcfModel& model, const std::string& path) {
            tessera::write_file_atomic(path, tessera::pcf_model_to_json(model));
        },
        py::arg("model"), py::arg("path"));
    m.def(
        "plot_model",
        [](const tessera::PcfModel& model, const std::string& path, const py::object& compare) {
            tessera::PcfPlotOptions options;
            if (!compare.is_none()) options.measured = tessera::measure_distribution(model, compare.cast<tessera::Exemplar>());
            py::gil_scoped_release release;
            tessera::write_pcf_plot(model, path, options);
        },
        py::arg("model"), py::arg("path"), py::arg("compare"));
    m.def(
        "measure",
        [](const tessera::PcfModel& model, const tessera::Exemplar& data) {
            return envelopes(tessera::measure_distribution(model, data), model);
        },
        py::arg("model"), py::arg("data"));
    m.def(
        "compare",
        [](const tessera::PcfModel& model, const tessera::Exemplar& exemplar, const tessera::Exemplar& output) {
            tessera::PcfQuality q;
            {
                py::gil_scoped_release release;
                q = tessera::compare_distribution(model, exemplar, output);
            }
            py::dict d;
            d["inside_fraction"] = to_array(q.inside_fraction);
            py::dict ratio;
            for (std::size_t c = 0; c < q.count_ratio.size(); ++c) ratio[py::str(model.classes[c])] = q.count_ratio[c];
            d["count_ratio"] = ratio;
            d["input_shares"] = shares(q.input_shares);
            d["output_shares"] = shares(q.output_shares);
            return d;
        },
        py::arg("model"), py::arg("exemplar"), py::arg("output"));
}

}  // namespace tessera_python
