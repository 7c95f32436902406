// io/io_util.hpp — small text helpers shared by the readers and writers in src/io/:
// strict number parsing (a whole field or nothing, so "1.5abc" is an error, not 1.5),
// shortest round-trip number formatting, trimming and case folding, and the
// "FILE:LINE: what" error builder; and the pieces of the JSON and CSV readers and
// writers that the animation formats (animation_json.cpp, animation_csv.cpp) share with
// the static ones, so that both read and write by the same rules. Private to src/io/.
#pragma once

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tessera/animation.hpp"
#include "tessera/error.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/io.hpp"
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

// ---- files (files.cpp, save.cpp) ----

// The extension of a loadable file (".json" or ".csv"); Error(io) naming the file otherwise.
std::string load_extension(const std::string& path);
// Type mesh paths are written relative to the JSON file: makes the relative ones of data
// loaded from `path` relative to the working directory, so that they open from there.
void resolve_mesh_paths(Exemplar& data, const std::string& path);
// A type mesh path as the JSON file at `json_path` names it (relative to its directory).
std::string mesh_path_from(const std::string& json_path, const std::string& mesh);

// ---- native JSON (json_format.cpp), shared with animation_json.cpp ----

using MeshPath = std::function<std::string(const std::string&)>;

// to_json, with every type's non-empty mesh path passed through `mesh_path` (save()
// rewrites them relative to the file it writes; to_json itself keeps them as they are).
std::string to_json_with_mesh_paths(const Exemplar& data, const RunStats* stats, const MeshPath& mesh_path);

// Parses JSON text; a syntax error is Error(input) "source: invalid JSON: ...".
nlohmann::json parse_json_text(const std::string& text, const std::string& source);
// Checks a document's "format", "version" and "dimension" and returns the dimension.
int json_document_dimension(const nlohmann::json& doc, const std::string& source);
// Gives an element of an animated file its samples (frame 0's), by element id; `where` is
// the element's JSON path, for errors.
using JsonFrameSamples = std::function<std::vector<Vec3>(std::uint64_t id, const std::string& where)>;
// Reads a parsed native document as a static exemplar, validated. With `frame_samples` it
// is an animated file's: "frames" is allowed (and left to the caller), every element needs
// an "id" and has no "position", "samples" or "time"; its samples come from frame_samples.
Exemplar read_json_document(const nlohmann::json& doc, const std::string& source,
                            const JsonFrameSamples* frame_samples = nullptr);
// An animated document (an object with "frames", animation_json.cpp) as an animation,
// validated.
Animation read_json_animation(const nlohmann::json& doc, const std::string& source);
// animation_to_json, with mesh paths as to_json_with_mesh_paths writes them.
std::string animation_to_json_with_mesh_paths(const Animation& data, const RunStats* stats,
                                              const MeshPath& mesh_path);
// The reader's checks, for the objects of "frames": only `allowed` keys; a member that
// must be there; an array; a finite number; an element id (a non-negative integer); an
// element's exactly one of "position" (one sample) and "samples" (several) as points of
// `dimension` numbers. Errors name `source` and the JSON path `where`.
void check_json_keys(const nlohmann::json& object, std::initializer_list<const char*> allowed,
                     const std::string& source, const std::string& where);
const nlohmann::json& json_require(const nlohmann::json& object, const char* key, const std::string& source,
                                   const std::string& where);
const nlohmann::json& json_array(const nlohmann::json& value, const std::string& source, const std::string& where);
double json_number(const nlohmann::json& value, const std::string& source, const std::string& where);
std::uint64_t json_element_id(const nlohmann::json& value, const std::string& source, const std::string& where);
std::vector<Vec3> json_element_samples(const nlohmann::json& element, int dimension, const std::string& source,
                                       const std::string& where);

// Which keys of an element the writer writes: all (static files), its definition without
// samples and time (an animated file's "elements"), or its id and samples (a frame's).
enum class JsonElementPart { all, definition, samples };
// One element as one line of compact JSON, numbers in the shortest exact form.
std::string json_element_line(const Exemplar& data, const Element& e, JsonElementPart part);
// A number as the writer writes it.
std::string json_number_text(double value);
// A whole document: header, domain, types, attributes and `element_lines` (one per line),
// then `after_elements` (more top-level members, starting with ",\n") and the stats.
std::string json_document(const Exemplar& data, const std::vector<std::string>& element_lines,
                          const std::string& after_elements, const RunStats* stats, const MeshPath& mesh_path);

// ---- CSV (csv_format.cpp), shared with animation_csv.cpp ----

// One data row of a CSV file, parsed and checked.
struct CsvRow {
    int line = 0;
    Vec3 p;
    std::string cls = "default";
    std::string element;  // element key (empty without an element column)
    long long sample = 0;
    double radius = 0.0;
    std::optional<double> angle;
    std::optional<Quat> q;
    double scale = 1.0;
    std::optional<std::uint64_t> id;
    double time = 0.0;
    bool locked = false;
    std::vector<double> attributes;
    long long frame = 0;  // animations: the frame column
    double t = 0.0;       // animations: the t column
};

// A CSV file read: which columns it has and its rows (at least one).
struct CsvTable {
    int header_line = 0;
    int dimension = 2;
    std::vector<std::string> attribute_names;
    bool element = false, sample = false, id = false, time = false, frame = false, t = false;
    std::vector<CsvRow> rows;
};
using CsvGroup = std::vector<const CsvRow*>;

// Splits one CSV line into fields (double quotes allowed). Errors name source and line.
std::vector<std::string> split_csv_fields(std::string_view line, const std::string& source, int line_number);
// Reads the header and the rows, each checked on its own.
CsvTable read_csv_table(std::string_view text, const std::string& source);
// The exemplar of a table without frames, validated.
Exemplar read_csv_exemplar(const CsvTable& table, const std::string& source, const LoadOptions& options);
// Groups rows into elements: by the element column (first-appearance order, samples
// ordered by the sample column or by row order; rows of one element must agree), else one
// element per row.
std::vector<CsvGroup> group_csv_rows(const CsvTable& table, const std::vector<const CsvRow*>& rows,
                                     const std::string& source);
// Throws Error(input) naming the line of `row` when it differs from `first` (of the same
// element) in anything that belongs to the element (class, radius, pose, id, ...).
void check_same_csv_element(const CsvRow& first, const CsvRow& row, const std::string& source);
// The elements of grouped rows, with the domain unset and not validated.
Exemplar csv_elements(const CsvTable& table, const std::vector<CsvGroup>& groups, const std::string& source);
// The domain of CSV data: options.input_domain, else the bounding box of `points`.
Domain csv_domain(const std::vector<Vec3>& points, int dimension, const LoadOptions& options,
                  const std::string& source);
// A CSV table with a frame or t column as an animation, validated (animation_csv.cpp).
Animation read_csv_animation(CsvTable table, const std::string& source, const LoadOptions& options);
// The writer: the header line, and the rows of `data`'s samples. With `frame_columns` (an
// animation's frame) the columns start with "frame,time,element,sample," and every row with
// `row_lead` (its frame and time fields); there is no per-sample time column then.
std::string csv_header_line(const Exemplar& data, bool frame_columns);
void append_csv_rows(const Exemplar& data, bool frame_columns, const std::string& row_lead, std::string& out);

// "source:line: what" (line > 0) or "source: what".
std::string located(const std::string& source, int line, const std::string& what);
[[noreturn]] inline void fail_input(const std::string& source, int line, const std::string& what) {
    throw Error(ErrorKind::input, located(source, line, what));
}

}  // namespace tessera::io_detail
