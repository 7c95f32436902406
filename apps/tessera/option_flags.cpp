// OptionFlags (option_flags.hpp): CLI11 flags made from the library's option tables.
#include "option_flags.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "common.hpp"

namespace tessera_cli {

namespace {

// One option over the methods that have it.
struct Merged {
    const tessera::OptionInfo* info = nullptr;
    std::vector<std::string> methods, docs, defaults;
};

std::vector<Merged> merge(const std::vector<MethodOptions>& methods) {
    std::vector<Merged> merged;
    for (const MethodOptions& m : methods)
        for (size_t i = 0; i < m.infos.size(); ++i) {
            auto it = std::find_if(merged.begin(), merged.end(),
                                   [&](const Merged& x) { return x.info->name == m.infos[i]->name; });
            if (it == merged.end()) it = merged.insert(merged.end(), Merged{m.infos[i], {}, {}, {}});
            it->methods.push_back(m.method);
            it->docs.push_back(m.infos[i]->doc);
            it->defaults.push_back(m.defaults[i]);
        }
    return merged;
}

bool all_equal(const std::vector<std::string>& v) { return std::all_of(v.begin(), v.end(), [&](auto& x) { return x == v[0]; }); }

// The help of a merged option: its doc, each method's where they differ, and the method
// named when only some methods have it; defaults per method when they differ.
std::string help_of(const Merged& m, size_t method_count) {
    std::string help;
    if (all_equal(m.docs)) {
        help = (m.methods.size() < method_count ? m.methods[0] + ": " : "") + m.docs[0];
    } else {
        for (size_t i = 0; i < m.docs.size(); ++i) help += (i ? " " : "") + m.methods[i] + ": " + m.docs[i];
    }
    const bool numeric = m.info->kind == tessera::OptionKind::integer || m.info->kind == tessera::OptionKind::number;
    if (numeric && (std::isfinite(m.info->lo) || std::isfinite(m.info->hi)))
        help += " Accepts " + tessera::describe_accepted(*m.info) + ".";
    if (!all_equal(m.defaults)) {
        help += " (default:";
        for (size_t i = 0; i < m.defaults.size(); ++i) help += (i ? ", " : " ") + m.methods[i] + " " + m.defaults[i];
        help += ")";
    }
    return help;
}

std::string type_name_of(const tessera::OptionInfo& info) {
    switch (info.kind) {
        case tessera::OptionKind::integer: return "INT";
        case tessera::OptionKind::seed: return "UINT";
        case tessera::OptionKind::number: return "FLOAT";
        case tessera::OptionKind::choice: {
            std::string text;
            for (const std::string& c : info.choices) text += (text.empty() ? "" : "|") + c;
            return text;
        }
        default: return "TEXT";
    }
}

}  // namespace

void OptionFlags::add(CLI::App& cmd, const std::vector<MethodOptions>& methods) {
    for (const Merged& m : merge(methods)) {
        Flag& flag = flags_[m.info->name];
        const std::string name = tessera::cli_flag(*m.info), help = help_of(m, methods.size());
        flag.as_written = name;
        if (m.info->kind == tessera::OptionKind::flag) {
            flag.option = cmd.add_flag(name, flag.on, help);
            continue;
        }
        flag.option = cmd.add_option(name, flag.text, help)->type_name(type_name_of(*m.info));
        if (all_equal(m.defaults) && !m.defaults[0].empty()) flag.option->default_str(m.defaults[0]);
        // Integers in any decimal notation of an integral value ("1e3") that fits the int field;
        // the table checks the option's own range.
        if (m.info->kind == tessera::OptionKind::integer)
            flag.option->transform(integer_notation(std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
        if (m.info->kind == tessera::OptionKind::seed)
            flag.option->transform(integer_notation(0, std::numeric_limits<std::uint64_t>::max()));
    }
}

bool OptionFlags::given(const std::string& name) const {
    const auto it = flags_.find(name);
    return it != flags_.end() && it->second.option->count() > 0;
}

std::vector<std::string> OptionFlags::given_outside(const MethodOptions& method) const {
    std::vector<std::string> outside;
    for (const auto& [name, flag] : flags_) {
        const bool mine = std::any_of(method.infos.begin(), method.infos.end(), [&](auto* i) { return i->name == name; });
        if (!mine && flag.option->count() > 0) outside.push_back(flag.as_written);
    }
    return outside;
}

}  // namespace tessera_cli
