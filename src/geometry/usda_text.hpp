// geometry/usda_text.hpp — the pieces of USD's text format (.usda) the USD writer needs:
// prim names made into USD identifiers and kept unique, string literals, and numbers at
// the precision of the attribute types written (point3f, float3, quatf: float). Private
// to the library.
#pragma once

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

}  // namespace tessera::geometry::usda
