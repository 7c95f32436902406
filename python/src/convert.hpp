// python/src/convert.hpp — small conversions shared by the binding files: Python sequences
// to Vec3, and numpy array construction.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "tessera/error.hpp"
#include "tessera/vec.hpp"

namespace tessera_python {

// A point given as a sequence of 2 or 3 numbers; `what` names it in errors.
inline tessera::Vec3 to_vec3(const pybind11::handle& value, const std::string& what) {
    const auto fail = [&] {
        throw tessera::Error(tessera::ErrorKind::option, what + " must be a sequence of 2 or 3 numbers");
    };
    if (!pybind11::isinstance<pybind11::sequence>(value) || pybind11::isinstance<pybind11::str>(value)) fail();
    const auto seq = pybind11::reinterpret_borrow<pybind11::sequence>(value);
    if (seq.size() != 2 && seq.size() != 3) fail();
    tessera::Vec3 v;
    for (std::size_t k = 0; k < seq.size(); ++k) {
        try {
            v[static_cast<int>(k)] = seq[k].cast<double>();
        } catch (const pybind11::cast_error&) {
            fail();
        }
    }
    return v;
}

inline std::vector<tessera::Vec3> to_points(const pybind11::handle& value, const std::string& what) {
    std::vector<tessera::Vec3> points;
    if (!pybind11::isinstance<pybind11::sequence>(value) && !pybind11::isinstance<pybind11::array>(value))
        throw tessera::Error(tessera::ErrorKind::option, what + " must be a sequence of points");
    for (const auto item : value) points.push_back(to_vec3(item, what + " point"));
    return points;
}

// A new numpy array of the given shape (C order).
template <class T>
pybind11::array_t<T> new_array(std::vector<pybind11::ssize_t> shape) {
    return pybind11::array_t<T>(shape);
}

template <class T>
pybind11::array_t<T> to_array(const std::vector<T>& values) {
    pybind11::array_t<T> a(static_cast<pybind11::ssize_t>(values.size()));
    auto m = a.template mutable_unchecked<1>();
    for (std::size_t i = 0; i < values.size(); ++i) m(static_cast<pybind11::ssize_t>(i)) = values[i];
    return a;
}

}  // namespace tessera_python
