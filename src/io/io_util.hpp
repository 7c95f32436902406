// io/io_util.hpp — small text helpers shared by the readers and writers in src/io/:
// strict number parsing (a whole field or nothing, so "1.5abc" is an error, not 1.5),
// shortest round-trip number formatting, trimming and case folding, and the
// "FILE:LINE: what" error builder. Private to src/io/.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "tessera/error.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/vec.hpp"

namespace tessera::io_detail {

// Removes leading and trailing spaces, tabs and carriage returns.
std::string_view trim(std::string_view s);
// ASCII lower case (column names and extensions are case-insensitive).
std::string lower(std::string_view s);
// Lower-cased extension of a path including the dot (".json"), or "" if none.
std::string extension_of(const std::string& path);

// Parses a whole field (after trimming) as a double. Accepts a leading '+', "nan" and
// "inf" (callers check finiteness so that they can say which value is not finite).
// Returns nothing if the field is empty or is not entirely a number.
std::optional<double> parse_number(std::string_view field);

// The shortest decimal text that reads back to exactly the same double.
std::string format_number(double value);

// Checks and normalises an element orientation read from a file, shared by the JSON
// and CSV readers so that both apply the same rules: `q` (if given) must be non-zero
// and is normalised unless it already is a unit quaternion (exact values round-trip
// bit for bit); in 2D it must be a rotation about z; given both, `q` and `angle`
// (radians about +z) must describe the same rotation. Without `q` the result is the
// rotation by `angle`, or the identity. Returns the problem as text, or nothing.
std::optional<std::string> resolve_orientation(std::optional<Quat> q, std::optional<double> angle,
                                               int dimension, Quat& result);

// to_json, with every type's non-empty mesh path passed through `mesh_path` (save()
// rewrites them relative to the file it writes; to_json itself keeps them as they are).
std::string to_json_with_mesh_paths(const Exemplar& data, const RunStats* stats,
                                    const std::function<std::string(const std::string&)>& mesh_path);

// "source:line: what" (line > 0) or "source: what".
std::string located(const std::string& source, int line, const std::string& what);
[[noreturn]] inline void fail_input(const std::string& source, int line, const std::string& what) {
    throw Error(ErrorKind::input, located(source, line, what));
}

}  // namespace tessera::io_detail
