// Shared by the bindings that take options and report progress (bind_synthesize.cpp,
// bind_grow.cpp): Python values checked against the type an option needs, with an
// OptionError naming the keyword, and a Python callable as a tessera::Progress.
#pragma once

#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <string>

#include "tessera/error.hpp"
#include "tessera/progress.hpp"

namespace tessera_python {

namespace py = pybind11;

[[noreturn]] inline void bad(const std::string& message) { throw tessera::Error(tessera::ErrorKind::option, message); }

template <class T>
T get(const py::handle& value, const std::string& name, const char* what) {
    try {
        return value.cast<T>();
    } catch (const py::cast_error&) {
        bad(name + " must be " + what + ", got " + std::string(py::repr(value)));
    }
}

inline double number(const py::handle& v, const std::string& name) { return get<double>(v, name, "a number"); }
inline int integer(const py::handle& v, const std::string& name) {
    if (py::isinstance<py::float_>(v)) bad(name + " must be an integer, got " + std::string(py::repr(v)));
    return get<int>(v, name, "an integer");
}
inline std::string text(const py::handle& v, const std::string& name) { return get<std::string>(v, name, "a string"); }

// Wraps a Python callable as a tessera::Progress. The first exception it raises is kept
// and re-raised once the library has unwound (the library sees a cancellation).
struct PythonProgress {
    py::object callback;
    std::shared_ptr<std::optional<py::error_already_set>> raised =
        std::make_shared<std::optional<py::error_already_set>>();

    tessera::Progress progress() const {
        if (callback.is_none()) return {};
        // The library may copy the std::function without the GIL: capture only shared_ptrs,
        // whose copies do not touch Python reference counts.
        auto call = std::make_shared<py::object>(callback);
        return [call, raised = raised](const tessera::ProgressEvent& event) -> bool {
            py::gil_scoped_acquire gil;
            try {
                py::dict d;
                d["stage"] = event.stage;
                d["iteration"] = event.iteration;
                d["iterations"] = event.iterations;
                d["energy"] = event.energy;
                d["elapsed"] = event.elapsed_s;
                d["fraction"] = event.fraction;
                const py::object answer = (*call)(d);
                return !(py::isinstance<py::bool_>(answer) && !answer.cast<bool>());
            } catch (py::error_already_set& e) {
                raised->emplace(std::move(e));
                return false;
            }
        };
    }

    // Raises what the callable raised, if it did.
    void rethrow() const {
        if (!*raised) return;
        py::error_already_set error = std::move(**raised);
        raised->reset();
        throw error;
    }
};

}  // namespace tessera_python
