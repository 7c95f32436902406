// geometry/usda_text.cpp — USD text helpers (usda_text.hpp). Numbers go through
// std::to_chars, locale-independent and shortest, as the other writers' numbers do.
#include "geometry/usda_text.hpp"

#include <charconv>
#include <cstdio>

#include "tessera/error.hpp"

namespace tessera::geometry::usda {

std::string identifier(const std::string& text) {
    std::string out;
    for (char c : text) {
        const bool ok =
            (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
        out += ok ? c : '_';
    }
    if (out.empty() || (out[0] >= '0' && out[0] <= '9')) out = "_" + out;
    return out;
}

std::string NameTable::unique(const std::string& text) {
    const std::string base = identifier(text);
    std::string name = base;
    for (int n = 2; used_.count(name); ++n) name = base + "_" + std::to_string(n);
    used_.insert(name);
    return name;
}

std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (c == '\n') {
            out += "\\n";
        } else if (u < 0x20 || u == 0x7f) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02x", u);
            out += escaped;
        } else {
            out += c;  // UTF-8 passes through: USD strings are UTF-8
        }
    }
    return out + "\"";
}

std::string real(double value) {
    char buffer[32];
    const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, static_cast<float>(value));
    if (ec != std::errc()) throw Error(ErrorKind::internal, "cannot format a number");
    return std::string(buffer, ptr);
}

std::string tuple(const Vec3& v) {
    return "(" + real(v.x) + ", " + real(v.y) + ", " + real(v.z) + ")";
}

std::string list(const std::vector<std::string>& items) {
    std::string out = "[";
    for (size_t i = 0; i < items.size(); ++i) out += (i ? ", " : "") + items[i];
    return out + "]";
}

}  // namespace tessera::geometry::usda
