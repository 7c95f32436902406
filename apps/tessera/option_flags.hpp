// apps/tessera/option_flags.hpp — a command's method options as flags, made from the
// library's option tables (tessera/option_table.hpp): one flag per option (--patch-size for
// patch_size), its doc as help, its default shown, its value checked by the table and
// errors naming the flag. A command with several methods (synth: det and pcf) shows an
// option the methods share once.
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <string>
#include <vector>

#include "tessera/option_table.hpp"

namespace tessera_cli {

// One method's options: their infos and defaults, in table order.
struct MethodOptions {
    std::string method;  // "det", "pcf"; named in the help when the command has several
    std::vector<const tessera::OptionInfo*> infos;
    std::vector<std::string> defaults;
};

template <class Options>
MethodOptions method_options(const std::string& method, const tessera::OptionTable<Options>& table) {
    MethodOptions m{method, {}, {}};
    const Options defaults{};
    for (const auto& spec : table) {
        m.infos.push_back(&spec);
        m.defaults.push_back(tessera::format_option_value(spec.get(defaults)));
    }
    return m;
}

class OptionFlags {
public:
    // Adds a flag for every option of `methods` to `cmd`.
    void add(CLI::App& cmd, const std::vector<MethodOptions>& methods);
    // Whether the user gave option `name` (the table's name).
    bool given(const std::string& name) const;
    // The flags given that `method` does not have, as typed ("--max-fails").
    std::vector<std::string> given_outside(const MethodOptions& method) const;

    // Stores the given values in `options`: those that need the exemplar's dimension only
    // when `dimension` > 0, the others only when it is 0 (so they fail before inputs load).
    template <class Options>
    void apply(const tessera::OptionTable<Options>& table, Options& options, int dimension = 0) const {
        for (const auto& spec : table) {
            if (!given(spec.name) || spec.needs_dimension != (dimension > 0)) continue;
            const Flag& flag = flags_.at(spec.name);
            const std::string as_written = tessera::cli_flag(spec);
            const tessera::OptionValue value = spec.kind == tessera::OptionKind::flag
                                                   ? tessera::OptionValue{flag.on}
                                                   : tessera::parse_option_text(spec, flag.text, as_written);
            tessera::set_option(spec, options, value, {as_written, dimension});
        }
    }

private:
    struct Flag {
        std::string text;  // the value as typed (integers already in plain digits)
        bool on = false;   // a flag option's value
        CLI::Option* option = nullptr;
        std::string as_written;  // "--patch-size"
    };
    std::map<std::string, Flag> flags_;  // by option name; map nodes stay put for CLI11's pointers
};

}  // namespace tessera_cli
