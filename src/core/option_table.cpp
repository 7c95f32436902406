// The parts of the option tables (tessera/option_table.hpp) that do not depend on a method:
// spellings, checks against an option's limits, reading CLI text, formatting defaults.
#include "tessera/option_table.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "tessera/error.hpp"

namespace tessera {

namespace {

[[noreturn]] void bad(const std::string& as_written, const OptionInfo& info, const std::string& got) {
    throw Error(ErrorKind::option, as_written + " must be " + describe_accepted(info) + ", got " + got);
}

std::string bound_text(double v) { return format_option_value(OptionValue{v}); }

std::string range_text(const OptionInfo& info) {
    const bool has_lo = std::isfinite(info.lo), has_hi = std::isfinite(info.hi);
    if (has_lo && has_hi && !info.lo_open && !info.hi_open)
        return " from " + bound_text(info.lo) + " to " + bound_text(info.hi);
    std::string text;
    if (has_lo) text += std::string(info.lo_open ? " > " : " >= ") + bound_text(info.lo);
    if (has_hi) text += std::string(has_lo ? " and" : "") + (info.hi_open ? " < " : " <= ") + bound_text(info.hi);
    return text;
}

std::string automatic_text(const OptionInfo& info) { return info.zero_is_automatic ? ", or 0 (automatic)" : ""; }

bool in_range(const OptionInfo& info, double v) {
    if (info.zero_is_automatic && v == 0.0) return true;
    if (info.lo_open ? !(v > info.lo) : !(v >= info.lo)) return false;
    return info.hi_open ? v < info.hi : v <= info.hi;
}

std::string quoted(const std::string& text) { return "'" + text + "'"; }

}  // namespace

std::string cli_flag(const OptionInfo& info) {
    std::string flag = "--" + info.name;
    for (char& c : flag)
        if (c == '_') c = '-';
    return flag;
}

std::string python_keyword(const OptionInfo& info) {
    // The options' names that are reserved words in Python.
    static const char* const reserved[] = {"lambda", "from", "in", "is", "global", "class", "def", "with"};
    for (const char* word : reserved)
        if (info.name == word) return info.name + "_";
    return info.name;
}

std::string describe_accepted(const OptionInfo& info) {
    switch (info.kind) {
        case OptionKind::flag: return "true or false";
        case OptionKind::seed: return "an unsigned 64-bit integer";
        case OptionKind::integer: return "an integer" + range_text(info) + automatic_text(info);
        case OptionKind::number:
            return (range_text(info).empty() ? "a finite number" : "a number") + range_text(info) + automatic_text(info);
        case OptionKind::choice: {
            std::string text;
            for (size_t i = 0; i < info.choices.size(); ++i)
                text += (i == 0 ? "" : i + 1 == info.choices.size() ? " or " : ", ") + info.choices[i];
            return text;
        }
        case OptionKind::text: return "text";
    }
    return "a value";
}

std::string format_option_value(const OptionValue& value) {
    if (const bool* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
    if (const auto* i = std::get_if<std::int64_t>(&value)) return std::to_string(*i);
    if (const auto* u = std::get_if<std::uint64_t>(&value)) return std::to_string(*u);
    if (const auto* s = std::get_if<std::string>(&value)) return *s;
    const double d = std::get<double>(value);
    if (!std::isfinite(d)) return d != d ? "nan" : d > 0 ? "inf" : "-inf";
    char text[32];
    if (d == std::floor(d) && std::fabs(d) < 1e15) {  // whole numbers without an exponent: 1000, not 1e+03
        std::snprintf(text, sizeof text, "%.0f", d);
        return text;
    }
    for (int digits = 1; digits <= 17; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, d);
        if (std::strtod(text, nullptr) == d) break;
    }
    return text;
}

OptionValue check_option_value(const OptionInfo& info, const OptionValue& value, const std::string& as_written) {
    const std::string got = std::holds_alternative<std::string>(value) && info.kind != OptionKind::text
                                ? quoted(std::get<std::string>(value))
                                : format_option_value(value);
    switch (info.kind) {
        case OptionKind::flag:
            if (!std::holds_alternative<bool>(value)) bad(as_written, info, got);
            return value;
        case OptionKind::seed:
            if (const auto* i = std::get_if<std::int64_t>(&value)) {
                if (*i < 0) bad(as_written, info, got);
                return static_cast<std::uint64_t>(*i);
            }
            if (!std::holds_alternative<std::uint64_t>(value)) bad(as_written, info, got);
            return value;
        case OptionKind::integer: {
            const auto* i = std::get_if<std::int64_t>(&value);
            if (!i || !in_range(info, static_cast<double>(*i))) bad(as_written, info, got);
            // Integer options are int fields.
            if (*i < std::numeric_limits<int>::min() || *i > std::numeric_limits<int>::max())
                throw Error(ErrorKind::option, as_written + ": " + got + " is out of range (" +
                                                   std::to_string(std::numeric_limits<int>::min()) + " to " +
                                                   std::to_string(std::numeric_limits<int>::max()) + ")");
            return value;
        }
        case OptionKind::number: {
            double v = 0.0;
            if (const auto* d = std::get_if<double>(&value)) v = *d;
            else if (const auto* i = std::get_if<std::int64_t>(&value)) v = static_cast<double>(*i);
            else if (const auto* u = std::get_if<std::uint64_t>(&value)) v = static_cast<double>(*u);
            else bad(as_written, info, got);
            if (!std::isfinite(v) || !in_range(info, v)) bad(as_written, info, got);
            return v;
        }
        case OptionKind::choice: {
            const auto* s = std::get_if<std::string>(&value);
            if (s)
                for (const std::string& choice : info.choices)
                    if (*s == choice) return value;
            bad(as_written, info, got);
        }
        case OptionKind::text:
            if (!std::holds_alternative<std::string>(value)) bad(as_written, info, got);
            return value;
    }
    return value;
}

OptionValue parse_option_text(const OptionInfo& info, const std::string& text, const std::string& as_written) {
    const char* first = text.data();
    const char* last = first + text.size();
    switch (info.kind) {
        case OptionKind::flag:
            if (text == "true" || text == "1") return check_option_value(info, true, as_written);
            if (text == "false" || text == "0") return check_option_value(info, false, as_written);
            bad(as_written, info, quoted(text));
        case OptionKind::integer:
        case OptionKind::seed: {
            if (!text.empty() && text[0] != '-') {
                std::uint64_t u = 0;
                const auto r = std::from_chars(first + (text[0] == '+'), last, u);
                if (r.ec == std::errc() && r.ptr == last) {
                    if (info.kind == OptionKind::seed) return check_option_value(info, u, as_written);
                    if (u <= static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
                        return check_option_value(info, static_cast<std::int64_t>(u), as_written);
                }
            } else {
                std::int64_t i = 0;
                const auto r = std::from_chars(first, last, i);
                if (r.ec == std::errc() && r.ptr == last) return check_option_value(info, i, as_written);
            }
            bad(as_written, info, quoted(text));
        }
        case OptionKind::number: {
            char* end = nullptr;
            const double v = text.empty() ? 0.0 : std::strtod(first, &end);
            if (text.empty() || end != last) bad(as_written, info, quoted(text));
            return check_option_value(info, v, as_written);
        }
        case OptionKind::choice:
        case OptionKind::text: return check_option_value(info, text, as_written);
    }
    return text;
}

}  // namespace tessera
