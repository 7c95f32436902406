// The motion analysis for Python (tessera/motion_analysis.hpp; Dynamic Element Textures,
// section 5): decompose_motion with its options as a dict keyed by the Python keywords
// (checked by low_pass_option_table), recombine_motion; and graph synthesis of a still
// (section 4.3, tessera/graph_motion.hpp, graph_motion_option_table); the GIL released while
// they work.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "option_table.hpp"
#include "tessera/graph_motion.hpp"
#include "tessera/motion_analysis.hpp"

namespace py = pybind11;

namespace tessera_python {
namespace {

py::tuple decompose(const tessera::Animation& animation, const py::dict& options) {
    tessera::LowPassOptions o;
    apply_keywords(tessera::low_pass_option_table(), o, options, animation.structure.dimension, "decompose");
    tessera::MotionSplit split;
    {
        py::gil_scoped_release release;
        split = tessera::decompose_motion(animation, o);
    }
    return py::make_tuple(std::move(split.coarse), std::move(split.detail));
}

tessera::Animation recombine(const tessera::Animation& coarse, const tessera::Animation& detail) {
    py::gil_scoped_release release;
    return tessera::recombine_motion(coarse, detail);
}

tessera::Animation animate(const tessera::Animation& clip, const py::dict& options) {
    tessera::GraphMotionOptions o;
    apply_keywords(tessera::graph_motion_option_table(), o, options, clip.structure.dimension, "animate");
    py::gil_scoped_release release;
    return tessera::extend_by_graph(clip, o);
}

}  // namespace

void bind_motion(py::module_& m) {
    m.def("extend_by_graph", &animate, py::arg("clip"), py::arg("options"));
    m.def(
        "enrich_by_graph",
        [](const tessera::Exemplar& still, const py::dict& options) {
            return animate(tessera::animation_from_exemplar(still), options);
        },
        py::arg("still"), py::arg("options"));
    m.def("decompose_motion", &decompose, py::arg("animation"), py::arg("options"));
    m.def("recombine_motion", &recombine, py::arg("coarse"), py::arg("detail"));
}

}  // namespace tessera_python
