// tessera::Error -> Python exceptions. The classes live in tessera/errors.py so that they
// can derive from the built-in exceptions users already catch (ValueError, OSError); the
// translator looks them up by the error's kind.
#include <pybind11/pybind11.h>

#include <regex>

#include "bindings.hpp"
#include "tessera/error.hpp"

namespace py = pybind11;

namespace tessera_python {

std::string python_option_names(const std::string& message) {
    static const std::regex flag("--([a-z][a-z0-9-]*)");
    std::string out;
    std::sregex_iterator it(message.begin(), message.end(), flag), end;
    std::size_t last = 0;
    for (; it != end; ++it) {
        out.append(message, last, static_cast<std::size_t>(it->position()) - last);
        std::string name = (*it)[1].str();
        for (char& c : name)
            if (c == '-') c = '_';
        if (name == "lambda") name = "lambda_";  // a Python keyword
        out += name;
        last = static_cast<std::size_t>(it->position() + it->length());
    }
    out.append(message, last, std::string::npos);
    return out;
}

namespace {

const char* class_name(tessera::ErrorKind kind) {
    switch (kind) {
        case tessera::ErrorKind::input: return "InputError";
        case tessera::ErrorKind::domain: return "DomainError";
        case tessera::ErrorKind::option: return "OptionError";
        case tessera::ErrorKind::io: return "FileError";
        case tessera::ErrorKind::cancelled: return "Cancelled";
        case tessera::ErrorKind::internal: break;
    }
    return "InternalError";
}

}  // namespace

void bind_errors(py::module_&) {
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const tessera::Error& e) {
            const py::object cls = py::module_::import("tessera.errors").attr(class_name(e.kind()));
            PyErr_SetString(cls.ptr(), python_option_names(e.what()).c_str());
        }
    });
}

}  // namespace tessera_python
