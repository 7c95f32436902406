// tessera/io.hpp — reading exemplars and writing arrangements, chosen by file
// extension. Formats are documented in docs/format.md.
//   read:  .json (native, "format": "tessera"), .csv (x,y[,z][,class][,radius][,angle])
//   write: .json, .csv, .ply (one point per element with its pose, for instancing),
//          .png / .svg (preview pictures), and the elements' geometry as a scene
//          (geometry.hpp): .usda (USD PointInstancer), .gltf / .glb, .obj, .mesh.ply
// Writers write to a temporary file in the target directory and rename it, so a
// failed run never leaves a partial file. Errors name the file and, where
// possible, the line.
#pragma once

#include <optional>
#include <string>

#include "tessera/domain.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/geometry.hpp"

namespace tessera {

struct LoadOptions {
    // Observation window for CSV inputs (JSON files carry their own domain).
    // Unset: the bounding box of the points (an error if it has zero extent). A window that
    // holds none of the points is an error (Error(domain), naming the file).
    std::optional<Domain> input_domain;
};

// Loads an exemplar (or a previous output) from .json or .csv.
// Throws Error(io) when the file cannot be read, Error(input) when its content is invalid.
Exemplar load(const std::string& path, const LoadOptions& options = {});

struct SaveOptions {
    // Scene outputs (.usda, .gltf, .glb, .obj, .mesh.ply): how build_scene rebuilds the
    // elements' geometry. Mesh paths as loaded are already usable (load() resolves them).
    GeometryOptions geometry;
    // .gltf / .glb: instances as one EXT_mesh_gpu_instancing node per shared mesh (gpu),
    // or one node per element for viewers without the extension (nodes).
    GltfInstancing gltf_instancing = GltfInstancing::gpu;
};

// Writes by extension (case-insensitive): .json, .csv, .ply, .png, .svg from the data;
// .usda, .gltf, .glb, .obj, .mesh.ply from the scene of the data (build_scene +
// write_scene, see save_scene). Throws Error(option) for another extension, Error(io)
// when the file cannot be written, and build_scene's errors for scene outputs.
void save(const Exemplar& data, const std::string& path, const SaveOptions& options = {});
// Arrangement overload: .json also records the run statistics.
void save(const Arrangement& data, const std::string& path, const SaveOptions& options = {});

// Builds the scene of `data` (build_scene with options.geometry) and writes it to the
// scene path `path` (is_scene_path: .usda, .gltf, .glb, .obj, .mesh.ply); returns the
// scene, e.g. for reports. Throws Error(option) for another extension, else as save().
Scene save_scene(const Exemplar& data, const std::string& path, const SaveOptions& options = {});

// Parsing/serialising in memory (used by the file functions and by tests).
// `source` names the origin in error messages.
Exemplar parse_json(const std::string& text, const std::string& source);
Exemplar parse_csv(const std::string& text, const std::string& source, const LoadOptions& options = {});
std::string to_json(const Exemplar& data, const RunStats* stats = nullptr);
// The deterministic part of the run statistics as one line of JSON: the "stats" object of
// an output .json file (docs/format.md). Timings and the thread count are not in it.
std::string run_stats_json(const RunStats& stats);
// A JSON file holding just a "domain" object (docs/format.md), as `--domain polygon:FILE.json`
// takes; "type" may be omitted for a polygon ({"outer": [...], "holes": [...]}).
// Files it names are relative to `path`'s directory.
Domain load_domain_json(const std::string& path, int dimension);
std::string to_csv(const Exemplar& data);
// The .ply point output: one vertex per element (docs/format.md, "PLY"). Throws
// Error(input) for an element id above 2^53, which PLY cannot hold exactly.
std::string to_ply(const Exemplar& data);

// Writes `content` to `path` atomically (temporary file + rename). Throws Error(io).
void write_file_atomic(const std::string& path, const std::string& content);
// Reads a whole file. Throws Error(io) naming the path.
std::string read_file(const std::string& path);

// Parses "xmin,ymin,xmax,ymax[,zmin,zmax]" into a box domain; `parameter` names the
// option in errors (e.g. "--input-domain").
Domain parse_box_domain(const std::string& text, const std::string& parameter);

}  // namespace tessera
