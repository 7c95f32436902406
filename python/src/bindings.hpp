// python/src/bindings.hpp — the parts of the `tessera._tessera` extension module, one
// file each. The module binds only the library's public API (include/tessera/), so the
// Python package can do nothing the library does not expose; python/tessera/*.py adds
// the keyword-argument front end, defaults and docstrings users see.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace tessera {
struct RunStats;
}

namespace tessera_python {

// Exemplar / Arrangement <-> numpy arrays (bind_data.cpp).
void bind_data(pybind11::module_& m);
// Animation / AnimatedArrangement <-> numpy arrays, their files and the animated PNG (bind_animation.cpp).
void bind_animation(pybind11::module_& m);
// decompose_motion / recombine_motion: coarse and detail motion (bind_motion.cpp).
void bind_motion(pybind11::module_& m);
// Domain and its constructors (bind_domain.cpp).
void bind_domain(pybind11::module_& m);
// tessera::Error -> the exception classes of tessera.errors (bind_errors.cpp).
void bind_errors(pybind11::module_& m);
// synthesize_det / synthesize_pcf / synthesize_dynamic with options, progress and the GIL released (bind_synthesize.cpp).
void bind_synthesize(pybind11::module_& m);
// Grower (on-demand growth) with options, progress and the GIL released (bind_grow.cpp).
void bind_grow(pybind11::module_& m);
// BrushCanvas (brushing element fields) and session replay (bind_brush.cpp).
void bind_brush(pybind11::module_& m);
// TileMaker, the streaming World and tiles as numpy arrays (bind_world.cpp, tile_arrays.hpp).
void bind_world(pybind11::module_& m);
// load, save, render, metrics, the PCF model (bind_io.cpp, bind_analysis.cpp).
void bind_io(pybind11::module_& m);
void bind_analysis(pybind11::module_& m);

// "--patch-size must be ..." -> "patch_size must be ...": library messages name options by
// their CLI flags; Python users know them by their keyword names.
std::string python_option_names(const std::string& message);

// A run's statistics as the dict of Arrangement.stats (bind_data.cpp).
pybind11::dict stats_of(const tessera::RunStats& stats);

}  // namespace tessera_python
