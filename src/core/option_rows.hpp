// Builders for the rows of the option tables (tessera/option_table.hpp), so that a table
// reads as one line per option: its name, its doc, the struct field it sets, its check.
// `field` is a generic lambda returning a reference to the field, e.g.
// [](auto& o) -> auto& { return o.radius; }: it serves the getter (const) and the setter.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tessera/option_table.hpp"
#include "tessera/vec.hpp"

namespace tessera::options {

struct Range {
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    bool lo_open = false, hi_open = false;
};
inline Range any_finite() { return {}; }
inline Range at_least(double lo) { return {lo, std::numeric_limits<double>::infinity(), false, false}; }
inline Range above(double lo) { return {lo, std::numeric_limits<double>::infinity(), true, false}; }
inline Range between(double lo, double hi) { return {lo, hi, false, false}; }
inline Range above_up_to(double lo, double hi) { return {lo, hi, true, false}; }

// Shared docs: these options mean the same in every method.
inline const char* const seed_doc =
    "Seed of every random draw (unsigned 64-bit). The same seed and options give the same output, whatever "
    "--threads is.";
inline const char* const threads_doc =
    "Worker threads; 0 = all hardware threads. Results are byte-identical for every value.";

template <class O>
OptionSpec<O> row(std::string name, OptionKind kind, std::string doc, Range range = {}) {
    OptionSpec<O> s;
    s.name = std::move(name);
    s.kind = kind;
    s.doc = std::move(doc);
    s.lo = range.lo, s.hi = range.hi, s.lo_open = range.lo_open, s.hi_open = range.hi_open;
    return s;
}

template <class O, class Field>
OptionSpec<O> flag_row(std::string name, std::string doc, Field field) {
    OptionSpec<O> s = row<O>(std::move(name), OptionKind::flag, std::move(doc));
    s.get = [field](const O& o) { return OptionValue{static_cast<bool>(field(o))}; };
    s.set = [field](O& o, const OptionValue& v, const OptionContext&) { field(o) = std::get<bool>(v); };
    return s;
}

template <class O, class Field>
OptionSpec<O> integer_row(std::string name, std::string doc, Field field, Range range) {
    OptionSpec<O> s = row<O>(std::move(name), OptionKind::integer, std::move(doc), range);
    s.get = [field](const O& o) { return OptionValue{static_cast<std::int64_t>(field(o))}; };
    s.set = [field](O& o, const OptionValue& v, const OptionContext&) {
        field(o) = static_cast<int>(std::get<std::int64_t>(v));
    };
    return s;
}

template <class O, class Field>
OptionSpec<O> seed_row(Field field) {
    OptionSpec<O> s = row<O>("seed", OptionKind::seed, seed_doc);
    s.get = [field](const O& o) { return OptionValue{static_cast<std::uint64_t>(field(o))}; };
    s.set = [field](O& o, const OptionValue& v, const OptionContext&) { field(o) = std::get<std::uint64_t>(v); };
    return s;
}

template <class O, class Field>
OptionSpec<O> threads_row(Field field) {
    return integer_row<O>("threads", threads_doc, field, at_least(0));
}

template <class O, class Field>
OptionSpec<O> number_row(std::string name, std::string doc, Field field, Range range) {
    OptionSpec<O> s = row<O>(std::move(name), OptionKind::number, std::move(doc), range);
    s.get = [field](const O& o) { return OptionValue{static_cast<double>(field(o))}; };
    s.set = [field](O& o, const OptionValue& v, const OptionContext&) { field(o) = std::get<double>(v); };
    return s;
}

// An enum option: `words` pairs each accepted word with its value.
template <class O, class Field, class Enum>
OptionSpec<O> choice_row(std::string name, std::string doc, Field field, std::vector<std::pair<std::string, Enum>> words) {
    OptionSpec<O> s = row<O>(std::move(name), OptionKind::choice, std::move(doc));
    for (const auto& [word, value] : words) s.choices.push_back(word);
    s.get = [field, words](const O& o) {
        for (const auto& [word, value] : words)
            if (field(o) == value) return OptionValue{word};
        return OptionValue{std::string()};
    };
    s.set = [field, words](O& o, const OptionValue& v, const OptionContext&) {
        for (const auto& [word, value] : words)
            if (std::get<std::string>(v) == word) field(o) = value;
    };
    return s;
}

// A text option with its own parser; `get` gives its text form ("" = unset).
template <class O, class Get, class Parse>
OptionSpec<O> text_row(std::string name, std::string doc, Get get, Parse parse, bool needs_dimension = false) {
    OptionSpec<O> s = row<O>(std::move(name), OptionKind::text, std::move(doc));
    s.needs_dimension = needs_dimension;
    s.get = [get](const O& o) { return OptionValue{std::string(get(o))}; };
    s.set = [parse](O& o, const OptionValue& v, const OptionContext& context) {
        parse(o, std::get<std::string>(v), context);
    };
    return s;
}

// The orientation field rows of det and grow (the --field forms of docs/fields.md).
inline const char* const field_doc =
    "Local orientation field of the output (Eq. 7): constant:DX,DY[,DZ] (one direction), radial:CX,CY[,CZ] "
    "(away from a centre; in 3D from the vertical axis through it) or vortex:CX,CY[,CZ] (circling a centre "
    "counter-clockwise about +z), polyline:X1,Y1[,Z1],X2,Y2[,Z2],... (tangent of the nearest segment) or "
    "trefoil:CX,CY,CZ,SCALE (3D). The exemplar's +x axis follows the field. From files (docs/fields.md): "
    "grid:FILE.json (vectors at grid nodes, interpolated) or mesh:FILE.ply|FILE.obj (3D, a direction per "
    "vertex). Default: none (the exemplar's frame everywhere).";

// The vector text of text options (det's --gravity X,Y[,Z], dynamic's --flow): 2 or 3 finite
// numbers separated by commas; nullopt when `text` is not that.
inline std::optional<Vec3> parse_vector_components(const std::string& text) {
    Vec3 v;
    int count = 0;
    const char* p = text.c_str();
    while (*p && count < 3) {
        char* end = nullptr;
        v[count++] = std::strtod(p, &end);
        if (end == p || (*end != ',' && *end != '\0') || !std::isfinite(v[count - 1])) return std::nullopt;
        p = *end == ',' ? end + 1 : end;
    }
    if (*p != '\0' || count < 2) return std::nullopt;
    return v;
}

// A vector as text that parse_vector_components reads back exactly; "" for the zero vector
// (the options' "unset").
inline std::string vector_text(const Vec3& v) {
    if (v == Vec3{}) return "";
    char text[96];
    std::snprintf(text, sizeof text, "%.17g,%.17g,%.17g", v[0], v[1], v[2]);
    return text;
}

}  // namespace tessera::options
