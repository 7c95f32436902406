// tessera/option_table.hpp — every option of every method, declared once.
//
// Each method's options (DetOptions for `synth --method det`, PcfSynthOptions for
// `--method pcf`, GrowOptions for `grow`, EditOptions for `edit`, PcfAnalysisSettings for
// `analyze`, PcfOptions for the pair correlation estimate) are listed in one table: the
// option's name, its kind, its one-line doc, its check, and how to read and write it in the
// options struct.
// Every front end is built from or checked against these tables: the CLI makes its flags
// from them (--patch-size, with the doc as help and the default shown), the Python module
// its keywords (patch_size=, with the same default), and requests of a JSON API would be
// checked by the same code. A value is checked here, once, and an error names the option
// as the caller wrote it (`OptionContext::as_written`: "--patch-size", "patch_size").
//
// Adding an option: a field in the options struct, a row in its method's table
// (src/det/det_option_table.cpp, src/pcf/pcf_option_table.cpp,
// src/grow/grow_option_table.cpp, src/det/edit_option_table.cpp,
// src/pcf/pcf_analysis_option_table.cpp, src/metrics/pair_correlation_option_table.cpp,
// src/brush/brush_option_table.cpp, src/dynamic/dynamic_option_table.cpp,
// src/analysis/low_pass_option_table.cpp),
// the code that uses it, and a line in docs/cli.md.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <variant>
#include <vector>

namespace tessera {

struct DetOptions;
struct PcfSynthOptions;
struct GrowOptions;
struct EditOptions;
struct PcfAnalysisSettings;
struct PcfOptions;
struct BrushOptions;
struct DynamicOptions;
struct LowPassOptions;

enum class OptionKind {
    flag,     // true / false (a CLI flag without a value)
    integer,  // a signed integer within the limits
    seed,     // an unsigned 64-bit integer
    number,   // a finite number within the limits
    choice,   // one of `choices`
    text,     // a text form parsed by the option's own setter (a field, an axis, sides); "" = unset
};

// A value as a front end hands it over: CLI text parsed by kind, a Python object converted.
// Integers arrive as int64 (uint64 for a seed above int64's range), numbers as double.
using OptionValue = std::variant<bool, std::int64_t, std::uint64_t, double, std::string>;

// Where a value comes from: the option's name as the caller wrote it (named by errors) and,
// for options whose text depends on it (OptionInfo::needs_dimension), the exemplar's dimension.
struct OptionContext {
    std::string as_written;
    int dimension = 0;
};

struct OptionInfo {
    std::string name;  // the options struct's field name, snake_case ("patch_size")
    OptionKind kind = OptionKind::number;
    std::string doc;   // one line: what --help and the Python docstring show
    // integer and number: the accepted range; open bounds exclude the limit itself.
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    bool lo_open = false, hi_open = false;
    // integer and number: 0 is accepted besides the range, and means "automatic" (bins: 0 or
    // from 2 on).
    bool zero_is_automatic = false;
    std::vector<std::string> choices;  // choice: the accepted words
    bool needs_dimension = false;      // text parsed against the exemplar's dimension (a field)
};

template <class Options>
struct OptionSpec : OptionInfo {
    std::function<OptionValue(const Options&)> get;  // the value in the text or number form set() takes
    // Stores a value already checked against the info (check_option_value); text kinds parse
    // it here and throw Error(option) naming context.as_written.
    std::function<void(Options&, const OptionValue&, const OptionContext&)> set;
};

template <class Options>
using OptionTable = std::vector<OptionSpec<Options>>;

const OptionTable<DetOptions>& det_option_table();
const OptionTable<PcfSynthOptions>& pcf_option_table();
const OptionTable<GrowOptions>& grow_option_table();
const OptionTable<EditOptions>& edit_option_table();
// Dynamic synthesis (`tessera synth --method dynamic`, synthesize_dynamic).
const OptionTable<DynamicOptions>& dynamic_option_table();
// The motion analysis (`tessera analyze --decompose`, decompose_motion, Python's decompose).
const OptionTable<LowPassOptions>& low_pass_option_table();
// Brushing (`tessera brush`, session files' "options", the studio's requests).
const OptionTable<BrushOptions>& brush_option_table();
// The PCF method's analysis (`tessera analyze`, analyze_distribution); pcf_option_table()
// holds the same rows, read through PcfSynthOptions::analysis.
const OptionTable<PcfAnalysisSettings>& pcf_analysis_option_table();
// The standard pair correlation estimate (pair_correlation, metrics: `tessera analyze
// --standard-pcf`, `tessera metrics`, Python's pair_correlation and metrics).
const OptionTable<PcfOptions>& pair_correlation_option_table();

// The spellings of an option in each front end: --patch-size; patch_size (a Python keyword
// such as lambda gets a trailing underscore: lambda_).
std::string cli_flag(const OptionInfo& info);
std::string python_keyword(const OptionInfo& info);

// What the option accepts, for messages and docs: "an integer >= 1", "a number > 0 and <= 1",
// "kcoherence or exhaustive".
std::string describe_accepted(const OptionInfo& info);

// `value` converted to the option's kind (an integer is a valid number; a number with a
// fraction is not an integer) and checked against its limits or choices; Error(option)
// "<as_written> must be <describe_accepted>, got <value>" otherwise.
OptionValue check_option_value(const OptionInfo& info, const OptionValue& value, const std::string& as_written);

// Text as typed on a command line, read as the option's kind (Error(option) naming
// `as_written` when it is not one), then checked like check_option_value.
OptionValue parse_option_text(const OptionInfo& info, const std::string& text, const std::string& as_written);

// A value as text: integers in decimal, numbers in the shortest form that reads back the
// same ("0.001", "-1"), flags as true/false. What --help shows as the default.
std::string format_option_value(const OptionValue& value);

template <class Options>
const OptionSpec<Options>* find_option(const OptionTable<Options>& table, const std::string& name) {
    for (const OptionSpec<Options>& spec : table)
        if (spec.name == name) return &spec;
    return nullptr;
}

// Checks `value` and stores it.
template <class Options>
void set_option(const OptionSpec<Options>& spec, Options& options, const OptionValue& value,
                const OptionContext& context) {
    spec.set(options, check_option_value(spec, value, context.as_written), context);
}

// Checks every option of a struct filled in by C++ code (the library's entry points call
// this), naming the field: "patch_size must be a number >= 0, got -1". Text options are
// checked where they are parsed.
template <class Options>
void check_options(const OptionTable<Options>& table, const Options& options) {
    for (const OptionSpec<Options>& spec : table)
        if (spec.kind != OptionKind::text) check_option_value(spec, spec.get(options), spec.name);
}

}  // namespace tessera
