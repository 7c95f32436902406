// geometry/usda_text.cpp — USD text helpers (usda_text.hpp). Numbers go through
// std::to_chars, locale-independent and shortest, as the other writers' numbers do.
#include "geometry/usda_text.hpp"

#include <charconv>
#include <cstdio>
#include <limits>

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

std::string pad(int depth) {
    return std::string(static_cast<size_t>(depth) * 4, ' ');
}

std::string int64_id(std::uint64_t id) {
    if (id > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
        throw Error(ErrorKind::input, "element id " + std::to_string(id) +
                                          " is too large for USD's int64 ids; use .json or .csv");
    return std::to_string(id);
}

namespace {

// A time code: the shortest text that reads back exactly ("3" for frame 3).
std::string code_text(double code) {
    char buffer[32];
    const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, code);
    if (ec != std::errc()) throw Error(ErrorKind::internal, "cannot format a time code");
    return std::string(buffer, ptr);
}

}  // namespace

std::string sampled(const std::string& type_and_name, const std::vector<std::string>& per_frame,
                    const std::vector<double>& codes, int depth) {
    if (per_frame.size() == 1) return pad(depth) + type_and_name + " = " + per_frame[0] + "\n";
    std::string out = pad(depth) + type_and_name + ".timeSamples = {\n";
    for (size_t f = 0; f < per_frame.size(); ++f)
        out += pad(depth + 1) + code_text(codes.at(f)) + ": " + per_frame[f] + ",\n";
    return out + pad(depth) + "}\n";
}

std::string layer_header(const std::string& doc, const std::vector<double>& codes, double codes_per_second) {
    std::string out = "#usda 1.0\n(\n";
    out += "    defaultPrim = \"World\"\n";
    out += "    doc = " + quoted(doc) + "\n";
    if (codes.size() > 1) {
        out += "    endTimeCode = " + code_text(codes.back()) + "\n";
        out += "    startTimeCode = " + code_text(codes.front()) + "\n";
        out += "    timeCodesPerSecond = " + real(codes_per_second) + "\n";
    }
    out += "    metersPerUnit = 1\n";
    return out + "    upAxis = \"Z\"\n)\n\n";
}

}  // namespace tessera::geometry::usda
