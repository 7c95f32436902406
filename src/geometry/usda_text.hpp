// geometry/usda_text.hpp — the pieces of USD's text format (.usda) the USD writer needs:
// prim names made into USD identifiers and kept unique, string literals, and numbers at
// the precision of the attribute types written (point3f, float3, quatf: float). Private
// to the library.
#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "tessera/vec.hpp"

namespace tessera::geometry::usda {

// A USD identifier ([A-Za-z_][A-Za-z0-9_]*) from any text: other bytes become '_', a
// leading digit gets a '_' in front, the empty text becomes "_".
std::string identifier(const std::string& text);

// Identifiers unique among those handed out: a name taken before gets _2, _3, ...
class NameTable {
public:
    explicit NameTable(std::set<std::string> reserved = {}) : used_(std::move(reserved)) {}
    std::string unique(const std::string& text);

private:
    std::set<std::string> used_;
};

// A USD string literal: double quotes, with backslash, quote and control characters escaped.
std::string quoted(const std::string& text);
// The shortest decimal text that reads back to `value` rounded to float.
std::string real(double value);
// "(x, y, z)" at float precision.
std::string tuple(const Vec3& v);
// "[a, b, ...]".
std::string list(const std::vector<std::string>& items);
// "    " x depth.
std::string pad(int depth);
// An element id as USD's int64; Error(input) for an id of 2^63 or more, which would not
// read back.
std::string int64_id(std::uint64_t id);

// `type name = value` at `depth` for one frame; for several, USD's time samples (the
// value at each time code), `type name.timeSamples = {code: value, ...}`, one per line.
std::string sampled(const std::string& type_and_name, const std::vector<std::string>& per_frame,
                    const std::vector<double>& codes, int depth);
// "#usda 1.0" and the layer metadata: defaultPrim "World", `doc`, the time code range
// and rate when `codes` has several frames, metersPerUnit 1 and upAxis "Z" (coordinates
// are not converted).
std::string layer_header(const std::string& doc, const std::vector<double>& codes, double codes_per_second);

}  // namespace tessera::geometry::usda
