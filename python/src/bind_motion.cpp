// The motion analysis for Python (tessera/motion_analysis.hpp; Dynamic Element Textures,
// section 5): decompose_motion with its options as a dict keyed by the Python keywords
// (checked by low_pass_option_table), recombine_motion; the GIL released while they work.
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "option_table.hpp"
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

}  // namespace

void bind_motion(py::module_& m) {
    m.def("decompose_motion", &decompose, py::arg("animation"), py::arg("options"));
    m.def("recombine_motion", &recombine, py::arg("coarse"), py::arg("detail"));
}

}  // namespace tessera_python
