// io/io_util.cpp — text helpers for the readers and writers (see io_util.hpp).
// Numbers go through std::from_chars / std::to_chars: locale-independent (a German
// locale must not turn "0.5" into an error) and exact, which the round-trip
// guarantees of the formats rely on.
#include "io/io_util.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <system_error>

namespace tessera::io_detail {

std::string_view trim(std::string_view s) {
    const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
    while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
    while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
    return s;
}

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::string extension_of(const std::string& path) {
    return lower(std::filesystem::path(path).extension().string());
}

std::optional<double> parse_number(std::string_view field) {
    field = trim(field);
    // from_chars rejects a leading '+', which spreadsheets sometimes write.
    if (!field.empty() && field.front() == '+') field.remove_prefix(1);
    if (field.empty() || field.front() == '+' || field.front() == ' ') return std::nullopt;
    double value = 0.0;
    const char* end = field.data() + field.size();
    const auto [ptr, ec] = std::from_chars(field.data(), end, value);
    // result_out_of_range (e.g. 1e400) is reported as not a number rather than
    // silently becoming infinity or zero.
    if (ec != std::errc() || ptr != end) return std::nullopt;
    return value;
}

std::string format_number(double value) {
    char buffer[64];
    const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    if (ec != std::errc()) throw Error(ErrorKind::internal, "cannot format a number");
    return std::string(buffer, ptr);
}

std::optional<std::string> resolve_orientation(std::optional<Quat> q, std::optional<double> angle,
                                               int dimension, Quat& result) {
    // A hand-typed quaternion with 4 decimals is normalised rather than rejected,
    // but a 2D rotation must really be about z and angle/orientation must agree.
    constexpr double unit_tolerance = 1e-12;
    constexpr double agreement_tolerance = 1e-9;
    if (!q) {
        result = angle ? Quat::from_angle_z(*angle) : Quat{};
        return std::nullopt;
    }
    Quat r = *q;
    const double n2 = r.w * r.w + r.x * r.x + r.y * r.y + r.z * r.z;
    if (!(n2 > 0.0)) return "the orientation must not be the zero quaternion";
    if (std::abs(n2 - 1.0) > unit_tolerance) {
        const double n = std::sqrt(n2);
        r = {r.w / n, r.x / n, r.y / n, r.z / n};
    }
    if (dimension == 2) {
        if (std::abs(r.x) > agreement_tolerance || std::abs(r.y) > agreement_tolerance)
            return "in 2D the orientation must be a rotation about z (qx and qy must be 0)";
        r.x = r.y = 0.0;
    }
    if (angle) {
        const Quat a = Quat::from_angle_z(*angle);
        if (std::abs(a.w * r.w + a.x * r.x + a.y * r.y + a.z * r.z) < 1.0 - agreement_tolerance)
            return "the angle and the orientation quaternion describe different rotations";
    }
    result = r;
    return std::nullopt;
}

std::string load_extension(const std::string& path) {
    const std::string extension = extension_of(path);
    if (extension != ".json" && extension != ".csv")
        throw Error(ErrorKind::io, "cannot load " + path + ": unsupported extension '" + extension +
                                       "' (supported: .json, .csv)");
    return extension;
}

void resolve_mesh_paths(Exemplar& data, const std::string& path) {
    const std::filesystem::path directory = std::filesystem::path(path).parent_path();
    for (ElementType& type : data.types)
        if (!type.mesh.empty() && std::filesystem::path(type.mesh).is_relative())
            type.mesh = (directory / type.mesh).lexically_normal().string();
}

// Relative to the file's directory, so that the file and its meshes can move together;
// absolute when the two share no directory but the root (a relative path would then
// climb to the root anyway).
std::string mesh_path_from(const std::string& json_path, const std::string& mesh) {
    namespace fs = std::filesystem;
    const fs::path directory = fs::absolute(fs::path(json_path)).parent_path().lexically_normal();
    const fs::path file = fs::absolute(mesh).lexically_normal();
    const auto top = [](const fs::path& p) {
        auto it = p.begin();
        return it == p.end() || ++it == p.end() ? fs::path() : *it;
    };
    const fs::path relative = file.lexically_relative(directory);
    if (relative.empty() || top(file) != top(directory)) return file.string();
    return relative.string();
}

std::string located(const std::string& source, int line, const std::string& what) {
    if (line > 0) return source + ":" + std::to_string(line) + ": " + what;
    return source + ": " + what;
}

}  // namespace tessera::io_detail
