// tessera::Grower for Python (on-demand growth, include/tessera/grow.hpp). As for synthesize,
// options arrive as a dict keyed by the Python keyword names (checked by the library's
// option table, option_table.hpp), the GIL is released while a grow call or a round runs,
// and the progress callable is called with the GIL held. Reports are dicts.
//
// A Grower is not thread-safe, and releasing the GIL lets another Python thread reach the
// same object mid-call: every method checks, with the GIL held, that no call is under way
// on another thread. The progress callable may still read the arrangement (the library
// calls it between rounds), as `tessera grow --round-pictures` does.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <climits>
#include <optional>
#include <stdexcept>
#include <thread>
#include <utility>

#include "bindings.hpp"
#include "convert.hpp"
#include "option_table.hpp"
#include "option_values.hpp"
#include "tessera/grow.hpp"
#include "tessera/option_text.hpp"

namespace py = pybind11;

namespace tessera_python {
namespace {


py::dict report_of(const tessera::GrowReport& r) {
    py::dict d;
    d["rounds"] = r.rounds, d["added"] = r.added, d["candidates"] = r.candidates, d["merged"] = r.merged;
    d["high_energy"] = r.high_energy, d["outside"] = r.outside, d["reassigned"] = r.reassigned;
    d["last_made"] = r.last_made, d["displaced"] = r.displaced, d["filled"] = r.filled, d["uncovered"] = r.uncovered, d["rare"] = r.rare, d["thinned"] = r.thinned, d["relaxed"] = r.relaxed, d["covered"] = r.covered;
    d["bound_hit"] = r.bound_hit, d["energy"] = r.energy, d["seconds"] = r.seconds;
    return d;
}

// The Grower and who is using it. `busy` and `owner` are read and written with the GIL
// held only, so the GIL orders them.
struct PyGrower {
    explicit PyGrower(tessera::Grower g) : grower(std::move(g)) {}
    tessera::Grower grower;
    bool busy = false;
    std::thread::id owner;
};

[[noreturn]] void busy_elsewhere() {
    throw std::runtime_error("this Grower is in use by another thread (a Grower serves one thread at a time)");
}

// Marks the grower busy for a call that changes it; the GIL is held on entry and exit.
class Changing {
public:
    explicit Changing(PyGrower& g) : g_(g) {
        if (g_.busy) {
            if (g_.owner != std::this_thread::get_id()) busy_elsewhere();
            throw std::runtime_error("the progress callback cannot change the Grower it reports on");
        }
        g_.busy = true;
        g_.owner = std::this_thread::get_id();
    }
    ~Changing() { g_.busy = false; }
    Changing(const Changing&) = delete;
    Changing& operator=(const Changing&) = delete;

private:
    PyGrower& g_;
};

// Reading is allowed between rounds: from no call, or from the progress callable of the
// call under way (on that call's thread).
const tessera::Grower& reading(const PyGrower& g) {
    if (g.busy && g.owner != std::this_thread::get_id()) busy_elsewhere();
    return g.grower;
}

// Runs a grow call with the GIL released and `callback` installed for its duration; the
// callable is removed with the GIL held, so its last reference is dropped under the GIL.
template <class Call>
py::dict run(PyGrower& g, const py::object& callback, const Call& call) {
    const Changing changing(g);
    PythonProgress progress{callback};
    struct Uninstall {
        tessera::Grower& grower;
        ~Uninstall() { grower.set_progress({}); }
    } uninstall{g.grower};
    g.grower.set_progress(progress.progress());
    std::optional<tessera::GrowReport> report;
    {
        py::gil_scoped_release release;
        try {
            report = call(g.grower);
        } catch (const tessera::Cancelled&) {
            if (!*progress.raised) throw;
        }
    }
    progress.rethrow();
    return report_of(*report);
}

// The library names grow(n)'s count `elements` (the CLI's --elements); Python calls it n.
tessera::GrowReport grow_count(tessera::Grower& grower, long long n) {
    static const std::string library_name = "elements:";
    if (n > INT_MAX) bad("n: must be at most " + std::to_string(INT_MAX) + ", got " + std::to_string(n));
    try {
        return grower.grow(static_cast<int>(std::max<long long>(n, INT_MIN)));
    } catch (const tessera::Error& e) {
        const std::string message = e.what();
        if (e.kind() != tessera::ErrorKind::option || message.rfind(library_name, 0) != 0) throw;
        throw tessera::Error(e.kind(), "n:" + message.substr(library_name.size()) + ", got " + std::to_string(n));
    }
}

std::unique_ptr<PyGrower> make_grower(const tessera::Exemplar& exemplar, const py::dict& options) {
    tessera::GrowOptions o;
    apply_keywords(tessera::grow_option_table(), o, options, exemplar.dimension, "Grower");
    py::gil_scoped_release release;  // indexing a large exemplar takes a while
    return std::make_unique<PyGrower>(tessera::Grower(exemplar, o));
}

tessera::Arrangement as_arrangement(const tessera::Exemplar& data) {
    tessera::Arrangement a;
    static_cast<tessera::Exemplar&>(a) = data;
    return a;
}

py::array_t<bool> locked_of(const tessera::Arrangement& a) {
    py::array_t<bool> out(static_cast<py::ssize_t>(a.elements.size()));
    auto m = out.mutable_unchecked<1>();
    for (std::size_t i = 0; i < a.elements.size(); ++i) m(static_cast<py::ssize_t>(i)) = a.elements[i].locked;
    return out;
}

py::array_t<long long> horizon_of(const tessera::Grower& grower) {
    const std::vector<int>& h = grower.horizon();
    return to_array(std::vector<long long>(h.begin(), h.end()));
}

}  // namespace

void bind_grow(py::module_& m) {
    py::class_<PyGrower>(m, "Grower",
                         "On-demand growth: an arrangement grown outward along its horizon, next to elements "
                         "that never move (use tessera.Grower, which wraps this class).")
        .def(py::init(&make_grower), py::arg("exemplar"), py::arg("options"))
        .def(
            "seed",
            [](PyGrower& g, const py::handle& center) {
                const Changing changing(g);
                g.grower.seed(to_vec3(center, "center"));
            },
            py::arg("center"),
            "Start over from a copy of an exemplar patch centred at `center` (its elements are the first horizon).")
        .def(
            "set_arrangement",
            [](PyGrower& g, const tessera::Exemplar& existing) {
                const Changing changing(g);
                g.grower.set_arrangement(as_arrangement(existing));
            },
            py::arg("arrangement"),
            "Start over from `arrangement` (types matched by name): its elements are locked and the first horizon.")
        .def(
            "grow",
            [](PyGrower& g, const tessera::Domain& region, const py::object& progress) {
                return run(g, progress, [&](tessera::Grower& grower) { return grower.grow(region); });
            },
            py::arg("region"), py::arg("progress") = py::none())
        .def(
            "grow",
            [](PyGrower& g, long long n, const py::object& progress) {
                return run(g, progress, [&](tessera::Grower& grower) { return grow_count(grower, n); });
            },
            py::arg("n"), py::arg("progress") = py::none())
        .def(
            "step",
            [](PyGrower& g) { return run(g, py::none(), [](tessera::Grower& grower) { return grower.step(); }); },
            "One round, unbounded (no region); returns its report.")
        .def_property_readonly(
            "arrangement", [](const PyGrower& g) { return reading(g).arrangement(); },
            "The arrangement so far (a copy), framed by the grown regions and elements.")
        .def_property_readonly(
            "locked", [](const PyGrower& g) { return locked_of(reading(g).arrangement()); },
            "Lock flag of each element, E: the elements the grower started from never move.")
        .def_property_readonly(
            "horizon", [](const PyGrower& g) { return horizon_of(reading(g)); },
            "Indices of the current horizon's elements (into the arrangement's elements).")
        .def_property_readonly(
            "last_report", [](const PyGrower& g) { return report_of(reading(g).last_report()); },
            "The report of the last grow call or step, also of one that was cancelled (up to its last "
            "finished round).")
        .def_property_readonly(
            "radius", [](const PyGrower& g) { return reading(g).radius(); },
            "The neighbourhood radius in use (the automatic one when radius=0 was given).")
        .def("__len__", [](const PyGrower& g) { return reading(g).arrangement().elements.size(); });
    // Domain.parse names its argument `domain`; a grow call's is its region (--region in the CLI).
    m.def(
        "parse_region",
        [](const std::string& spec, const tessera::Exemplar& exemplar) {
            return tessera::parse_output_domain(spec, exemplar, 1.0, "region");
        },
        py::arg("spec"), py::arg("exemplar"), "A region from the --region text forms, relative to the exemplar.");
}

}  // namespace tessera_python
