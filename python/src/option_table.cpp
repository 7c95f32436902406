// Python values <-> the option tables' values (option_table.hpp).
#include "option_table.hpp"

#include <pybind11/stl.h>

namespace tessera_python {

namespace {

[[noreturn]] void wrong(const tessera::OptionInfo& info, const std::string& keyword, const py::handle& value) {
    bad(keyword + " must be " + tessera::describe_accepted(info) + ", got " + std::string(py::repr(value)));
}

// A text option's value: a string, or a sequence of strings or numbers written as its
// comma-separated text form (boundary=["-x", "+x"], gravity=(0, 0, -1)).
std::string text_of(const tessera::OptionInfo& info, const py::handle& value, const std::string& keyword) {
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    if (info.kind != tessera::OptionKind::text || !py::isinstance<py::sequence>(value)) wrong(info, keyword, value);
    std::string text;
    for (const py::handle item : value) {
        std::string part;
        if (py::isinstance<py::str>(item)) part = item.cast<std::string>();
        else if (py::isinstance<py::int_>(item) || py::isinstance<py::float_>(item))
            part = tessera::format_option_value(item.cast<double>());
        else wrong(info, keyword, value);
        text += (text.empty() ? "" : ",") + part;
    }
    return text;
}

}  // namespace

std::optional<tessera::OptionValue> option_value(const tessera::OptionInfo& info, const py::handle& value,
                                                 const std::string& keyword) {
    using tessera::OptionKind;
    if (value.is_none()) return std::nullopt;
    const bool is_bool = py::isinstance<py::bool_>(value);
    switch (info.kind) {
        case OptionKind::flag:
            if (!is_bool) wrong(info, keyword, value);
            return tessera::OptionValue{value.cast<bool>()};
        case OptionKind::integer:
        case OptionKind::seed: {
            // Integers only (numpy's too, through __index__): not True, not 2.0.
            if (is_bool || py::isinstance<py::float_>(value) || !py::hasattr(value, "__index__"))
                wrong(info, keyword, value);
            const py::int_ i = py::reinterpret_steal<py::int_>(PyNumber_Index(value.ptr()));
            if (!i) throw py::error_already_set();
            if (i < py::int_(0)) {
                try {
                    return tessera::OptionValue{i.cast<std::int64_t>()};
                } catch (const py::cast_error&) {
                    wrong(info, keyword, value);
                }
            }
            try {
                const auto u = i.cast<std::uint64_t>();
                if (info.kind == OptionKind::seed) return tessera::OptionValue{u};
                if (u > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) wrong(info, keyword, value);
                return tessera::OptionValue{static_cast<std::int64_t>(u)};
            } catch (const py::cast_error&) {
                wrong(info, keyword, value);
            }
        }
        case OptionKind::number:
            if (is_bool || py::isinstance<py::str>(value)) wrong(info, keyword, value);
            try {
                return tessera::OptionValue{value.cast<double>()};
            } catch (const py::cast_error&) {
                wrong(info, keyword, value);
            }
        case OptionKind::choice:
        case OptionKind::text: return tessera::OptionValue{text_of(info, value, keyword)};
    }
    wrong(info, keyword, value);
}

const char* kind_name(tessera::OptionKind kind) {
    switch (kind) {
        case tessera::OptionKind::flag: return "flag";
        case tessera::OptionKind::integer: return "integer";
        case tessera::OptionKind::seed: return "seed";
        case tessera::OptionKind::number: return "number";
        case tessera::OptionKind::choice: return "choice";
        case tessera::OptionKind::text: return "text";
    }
    return "text";
}

py::object python_default(const tessera::OptionInfo& info, const tessera::OptionValue& value) {
    if (const bool* b = std::get_if<bool>(&value)) return py::bool_(*b);
    if (const auto* i = std::get_if<std::int64_t>(&value)) return py::int_(*i);
    if (const auto* u = std::get_if<std::uint64_t>(&value)) return py::int_(*u);
    if (const auto* d = std::get_if<double>(&value)) return py::float_(*d);
    const std::string& text = std::get<std::string>(value);
    if (info.kind == tessera::OptionKind::text && text.empty()) return py::none();
    return py::str(text);
}

}  // namespace tessera_python
