// tessera/io.hpp — reading exemplars and writing arrangements, chosen by file
// extension. Formats are documented in docs/format.md.
//   read:  .json (native, "format": "tessera"), .csv (x,y[,z][,class][,radius][,angle])
//   write: .json, .csv, .ply (3D points with pose), .png / .svg (preview pictures)
// Writers write to a temporary file in the target directory and rename it, so a
// failed run never leaves a partial file. Errors name the file and, where
// possible, the line.
#pragma once

#include <optional>
#include <string>

#include "tessera/domain.hpp"
#include "tessera/exemplar.hpp"

namespace tessera {

struct LoadOptions {
    // Observation window for CSV inputs (JSON files carry their own domain).
    // Unset: the bounding box of the points (an error if it has zero extent).
    std::optional<Domain> input_domain;
};

// Loads an exemplar (or a previous output) from .json or .csv.
// Throws Error(io) when the file cannot be read, Error(input) when its content is invalid.
Exemplar load(const std::string& path, const LoadOptions& options = {});

// Writes by extension: .json, .csv, .ply, .png, .svg. Throws Error(io) / Error(option).
void save(const Exemplar& data, const std::string& path);
// Arrangement overload: .json also records the run statistics.
void save(const Arrangement& data, const std::string& path);

// Parsing/serialising in memory (used by the file functions and by tests).
// `source` names the origin in error messages.
Exemplar parse_json(const std::string& text, const std::string& source);
Exemplar parse_csv(const std::string& text, const std::string& source, const LoadOptions& options = {});
std::string to_json(const Exemplar& data, const RunStats* stats = nullptr);
// A JSON file holding just a "domain" object (docs/format.md), as `--domain polygon:FILE.json`
// takes; "type" may be omitted for a polygon ({"outer": [...], "holes": [...]}).
// Files it names are relative to `path`'s directory.
Domain load_domain_json(const std::string& path, int dimension);
std::string to_csv(const Exemplar& data);
std::string to_ply(const Exemplar& data);

// Writes `content` to `path` atomically (temporary file + rename). Throws Error(io).
void write_file_atomic(const std::string& path, const std::string& content);
// Reads a whole file. Throws Error(io) naming the path.
std::string read_file(const std::string& path);

// Parses "xmin,ymin,xmax,ymax[,zmin,zmax]" into a box domain; `parameter` names the
// option in errors (e.g. "--input-domain").
Domain parse_box_domain(const std::string& text, const std::string& parameter);

}  // namespace tessera
