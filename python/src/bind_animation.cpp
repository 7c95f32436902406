// Animation and AnimatedArrangement for Python (tessera/animation.hpp): frames of one element
// set. Arrays go out as numpy copies, as for Exemplar (bind_data.cpp):
//   times (F), positions (F x S x d: frames along the leading axis, samples in the order of
//   the exemplar's samples), velocities (F x S x d)
// make_animation builds one from an exemplar and such arrays, checked by Animation::validate.
// Also the animation files (tessera/animation_io.hpp) and the animated PNG
// (tessera/animation_render.hpp).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cctype>

#include "bindings.hpp"
#include "convert.hpp"
#include "option_values.hpp"
#include "tessera/animation.hpp"
#include "tessera/animation_io.hpp"
#include "tessera/animation_render.hpp"
#include "tessera/dynamic.hpp"
#include "tessera/io.hpp"

namespace py = pybind11;

namespace tessera_python {
namespace {

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Paths drawn behind each particle in an animated PNG, in frames (as `tessera synth` draws them).
constexpr int png_trail = 6;

std::string shape_text(const py::array& a) {
    std::string shape = "(";
    for (py::ssize_t k = 0; k < a.ndim(); ++k) shape += (k ? ", " : "") + std::to_string(a.shape(k));
    return shape + (a.ndim() == 1 ? ",)" : ")");
}

Doubles doubles(const py::handle& value, const std::string& name) {
    try {
        Doubles a = py::cast<Doubles>(value);
        if (a) return a;
    } catch (const py::cast_error&) {
    }
    bad(name + " must be a numeric array");
}

// The F x S x d positions array, checked against the exemplar's samples and dimension.
Doubles checked_positions(const py::handle& value, const tessera::Exemplar& exemplar) {
    Doubles a = doubles(value, "positions");
    const auto samples = static_cast<py::ssize_t>(exemplar.samples.size());
    if (a.ndim() != 3 || a.shape(1) != samples || a.shape(2) != exemplar.dimension)
        bad("positions must be an F x " + std::to_string(samples) + " x " + std::to_string(exemplar.dimension) +
            " array (frames x the exemplar's samples x its dimension), got shape " + shape_text(a));
    return a;
}

// F x S x d -> frame-major Vec3s (Animation::positions).
std::vector<tessera::Vec3> flat_positions(const Doubles& a) {
    const auto p = a.unchecked<3>();
    std::vector<tessera::Vec3> out;
    out.reserve(static_cast<std::size_t>(a.shape(0) * a.shape(1)));
    for (py::ssize_t f = 0; f < a.shape(0); ++f)
        for (py::ssize_t s = 0; s < a.shape(1); ++s)
            out.push_back({p(f, s, 0), p(f, s, 1), a.shape(2) == 3 ? p(f, s, 2) : 0.0});
    return out;
}

std::vector<double> frame_times(const py::handle& value, py::ssize_t frames) {
    std::vector<double> times;
    if (value.is_none()) {
        for (py::ssize_t f = 0; f < frames; ++f) times.push_back(static_cast<double>(f));
        return times;
    }
    const Doubles a = doubles(value, "times");
    if (a.ndim() != 1 || a.shape(0) != frames)
        bad("times must be a 1-D array of " + std::to_string(frames) + " time stamps (one per frame), got shape " +
            shape_text(a));
    const auto t = a.unchecked<1>();
    for (py::ssize_t f = 0; f < frames; ++f) times.push_back(t(f));
    return times;
}

tessera::Animation make_animation(const tessera::Exemplar& exemplar, const py::handle& positions,
                                  const py::handle& times) {
    const Doubles p = checked_positions(positions, exemplar);
    tessera::Animation a;
    a.structure = exemplar;
    a.positions = flat_positions(p);
    a.times = frame_times(times, p.shape(0));
    a.validate("arrays");
    // The structure holds frame 0 (its samples' positions and time stamps, element centroids).
    a.structure = a.frame(0);
    return a;
}

// Frame-major Vec3s (positions or velocities) as an F x S x d array.
py::array_t<double> frames_array(const tessera::Animation& a, const std::vector<tessera::Vec3>& values) {
    const py::ssize_t frames = a.frame_count(), samples = a.sample_count(), d = a.structure.dimension;
    auto out = new_array<double>({frames, samples, d});
    auto m = out.mutable_unchecked<3>();
    for (py::ssize_t f = 0; f < frames; ++f)
        for (py::ssize_t s = 0; s < samples; ++s)
            for (py::ssize_t k = 0; k < d; ++k)
                m(f, s, k) = values[static_cast<std::size_t>(f * samples + s)][static_cast<int>(k)];
    return out;
}

// Python's indexing: -1 is the last frame; IndexError outside.
tessera::Exemplar frame_of(const tessera::Animation& a, int f) {
    const int index = f < 0 ? f + a.frame_count() : f;
    if (index < 0 || index >= a.frame_count())
        throw py::index_error("frame " + std::to_string(f) + " of an animation of " + std::to_string(a.frame_count()) +
                              " frames");
    return a.frame(index);
}

bool is_png(const std::string& path) {
    if (path.size() < 4) return false;
    std::string ext = path.substr(path.size() - 4);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext == ".png";
}

// .png: the APNG `tessera synth` writes; .json / .csv: the files (with `stats` in .json).
void save_animation(const tessera::Animation& data, const tessera::RunStats* stats, const std::string& path) {
    py::gil_scoped_release release;
    if (is_png(path)) {
        tessera::AnimationRenderOptions options;
        options.trail = png_trail;
        tessera::write_file_atomic(path, tessera::render_animation_png(data, options));
    } else if (stats) {
        tessera::save_animation(data, *stats, path);
    } else {
        tessera::save_animation(data, path);
    }
}

std::string describe(const tessera::Animation& a, const std::string& name) {
    const tessera::Exemplar& e = a.structure;
    return "<tessera." + name + " " + std::to_string(e.dimension) + "D, " + std::to_string(e.elements.size()) +
           " elements x " + std::to_string(a.frame_count()) + " frames in " + e.domain.describe() + ">";
}

void animation_properties(py::class_<tessera::Animation>& c) {
    using A = tessera::Animation;
    c.def_property_readonly("exemplar", [](const A& a) { return a.frame(0); },
                            "Frame 0 as an Exemplar: the elements (classes, ids, radii, ...) and the domain.")
        .def_property_readonly("times", [](const A& a) { return to_array(a.times); }, "Time stamp of each frame, F.")
        .def_property_readonly("positions", [](const A& a) { return frames_array(a, a.positions); },
                               "Sample positions per frame, F x S x d, samples in the exemplar's order (a copy).")
        .def_property_readonly("velocities",
                               [](const A& a) { return frames_array(a, tessera::sample_velocities(a)); },
                               "Sample velocities per frame, F x S x d: (p(f) - p(f-1)) / (t(f) - t(f-1)); frame "
                               "0 has frame 1's.")
        .def_property_readonly("frame_count", &A::frame_count)
        .def_property_readonly("sample_count", &A::sample_count)
        .def_property_readonly("element_count", [](const A& a) { return a.structure.elements.size(); })
        .def_property_readonly("dimension", [](const A& a) { return a.structure.dimension; })
        .def_property_readonly("domain", [](const A& a) { return a.structure.domain; })
        .def("__len__", &A::frame_count)
        .def("frame", &frame_of, py::arg("f"),
             "Frame f as an Exemplar (negative f counts from the end); IndexError outside.")
        .def("copy", [](const A& a) { return a; })
        .def("__repr__", [](const A& a) { return describe(a, "Animation"); });
}

void bind_animation_classes(py::module_& m) {
    py::class_<tessera::Animation> animation(
        m, "Animation", "Elements in space and time: the element structure of an Exemplar and the position of every "
                        "sample in every frame.");
    animation_properties(animation);
    py::class_<tessera::AnimatedArrangement, tessera::Animation> animated(
        m, "AnimatedArrangement", "The output of dynamic synthesis: an Animation plus the statistics of the run.");
    animated.def_property_readonly(
        "stats", [](const tessera::AnimatedArrangement& a) { return stats_of(a.stats); },
        "Statistics of the run as a dict, as Arrangement.stats.");
    animated.def("copy", [](const tessera::AnimatedArrangement& a) { return a; });
    animated.def("__repr__", [](const tessera::Animation& a) { return describe(a, "AnimatedArrangement"); });
}

}  // namespace

void bind_animation(py::module_& m) {
    bind_animation_classes(m);
    m.def("make_animation", &make_animation, py::arg("exemplar"), py::arg("positions"), py::arg("times"));
    m.def("animation_from_exemplar", [](const tessera::Exemplar& e) { return tessera::animation_from_exemplar(e); },
          py::arg("exemplar"));
    m.def(
        "load_animation",
        [](const std::string& path, const py::object& input_domain) {
            tessera::LoadOptions options;
            if (!input_domain.is_none()) options.input_domain = input_domain.cast<tessera::Domain>();
            py::gil_scoped_release release;
            return tessera::load_animation(path, options);
        },
        py::arg("path"), py::arg("input_domain"));
    m.def(
        "has_frames",
        [](const std::string& path) {
            py::gil_scoped_release release;
            return tessera::has_frames(path);
        },
        py::arg("path"));
    // AnimatedArrangement first: pybind11 tries overloads in order, and its JSON records the run statistics.
    m.def(
        "save_animation",
        [](const tessera::AnimatedArrangement& a, const std::string& path) { save_animation(a, &a.stats, path); },
        py::arg("animation"), py::arg("path"));
    m.def(
        "save_animation",
        [](const tessera::Animation& a, const std::string& path) { save_animation(a, nullptr, path); },
        py::arg("animation"), py::arg("path"));
}

}  // namespace tessera_python
