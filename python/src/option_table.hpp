// Python keywords made from the library's option tables (tessera/option_table.hpp): a
// keyword's value converted to its option's kind and checked by the table, errors naming
// the keyword (`patch_size must be a number >= 0, got -1`); and the tables themselves for
// python/tessera/__init__.py, which builds the signatures and docs of synthesize and
// Grower from them.
#pragma once

#include <pybind11/pybind11.h>

#include <optional>
#include <string>

#include "option_values.hpp"
#include "tessera/option_table.hpp"

namespace tessera_python {

// `value` as the option's kind; nullopt for None (the option keeps its default).
std::optional<tessera::OptionValue> option_value(const tessera::OptionInfo& info, const py::handle& value,
                                                 const std::string& keyword);

// "flag", "integer", "seed", "number", "choice", "text".
const char* kind_name(tessera::OptionKind kind);

// The option's default as a Python value (None for an unset text option).
py::object python_default(const tessera::OptionInfo& info, const tessera::OptionValue& value);

// Stores each keyword of `given` in `options`; an unknown keyword is an OptionError naming
// `owner` ("method 'det'", "Grower").
template <class Options>
void apply_keywords(const tessera::OptionTable<Options>& table, Options& options, const py::dict& given,
                    int dimension, const std::string& owner) {
    for (const auto& [key, value] : given) {
        const std::string keyword = py::str(key);
        const tessera::OptionSpec<Options>* spec = nullptr;
        for (const auto& s : table)
            if (tessera::python_keyword(s) == keyword) spec = &s;
        if (!spec) bad("unknown option '" + keyword + "' for " + owner);
        if (const auto v = option_value(*spec, value, keyword))
            tessera::set_option(*spec, options, *v, {keyword, dimension});
    }
}

// One table as a list of dicts: name, keyword, flag (the CLI's), kind, default, doc, choices,
// accepts (describe_accepted).
template <class Options>
py::list describe_table(const tessera::OptionTable<Options>& table) {
    const Options defaults{};
    py::list rows;
    for (const auto& spec : table) {
        py::dict row;
        row["name"] = spec.name;
        row["keyword"] = tessera::python_keyword(spec);
        row["flag"] = tessera::cli_flag(spec);
        row["kind"] = kind_name(spec.kind);
        row["default"] = python_default(spec, spec.get(defaults));
        row["doc"] = spec.doc;
        row["choices"] = spec.choices;
        row["accepts"] = tessera::describe_accepted(spec);
        rows.append(row);
    }
    return rows;
}

}  // namespace tessera_python
