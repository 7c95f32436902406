// The `tessera._tessera` extension module: registers its parts (bindings.hpp).
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "tessera/version.hpp"

PYBIND11_MODULE(_tessera, m) {
    m.doc() = "tessera's C++ library (use the `tessera` package, which wraps this module).";
    m.attr("version") = tessera::version;
    m.attr("format_version") = tessera::format_version;
    tessera_python::bind_errors(m);
    tessera_python::bind_domain(m);
    tessera_python::bind_data(m);
    tessera_python::bind_animation(m);
    tessera_python::bind_motion(m);
    tessera_python::bind_synthesize(m);
    tessera_python::bind_grow(m);
    tessera_python::bind_brush(m);
    tessera_python::bind_world(m);
    tessera_python::bind_io(m);
    tessera_python::bind_analysis(m);
}
