// tessera/animation_io.hpp — reading and writing animations (tessera/animation.hpp), chosen
// by file extension. The formats are documented in docs/format.md, "Animations (frames)":
//   .json: the native document plus a top-level "frames" array; its "elements" define the
//          elements (type, id, pose, attributes) and each frame gives their positions by id;
//   .csv:  one row per sample per frame, with a frame column (and the frame's time stamp in
//          the time column) or a t column (the time stamp);
// and written only, as animated scenes for 3D tools (each frame's elements as build_scene
// poses them, SaveOptions::geometry):
//   .usda: a USD layer: particles and rigid elements on a PointInstancer, threads as
//          BasisCurves, sheets as a Mesh, all with time samples, one per frame;
//   .gltf/.glb: glTF 2.0: a node per element with translation (and rotation) channels,
//          threads and sheets as meshes whose frames are morph targets with a weights channel.
// A file without frames reads as a one-frame animation, and load() (tessera/io.hpp) of an
// animated file gives its frame 0, so that every command reading an exemplar takes either.
// Writers write atomically, as save() does. Errors are one line naming the file and the
// line (CSV) or JSON path.
#pragma once

#include <string>

#include "tessera/animation.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/io.hpp"

namespace tessera {

// Loads an animation from .json or .csv; a file without frames gives a one-frame animation
// (animation_from_exemplar). Type mesh paths are resolved as load() resolves them.
// Throws Error(io) when the file cannot be read or has another extension, Error(input)
// when its content is invalid (validated with Animation::validate).
Animation load_animation(const std::string& path, const LoadOptions& options = {});

// Writes by extension (case-insensitive): .json, .csv, .usda, .gltf, .glb. Throws
// Error(option) for another extension, Error(io) when the file cannot be written, and for
// the scene formats Error(input) naming the file for elements they cannot draw (deformed
// meshes, ids of 2^63 or more in .usda) and build_scene's errors.
void save_animation(const Animation& data, const std::string& path, const SaveOptions& options = {});
// The same, recording the run statistics in .json (as save() does for an Arrangement).
void save_animation(const Animation& data, const RunStats& stats, const std::string& path,
                    const SaveOptions& options = {});

// True when the file at `path` holds frames: a .json file with a top-level "frames" key,
// or a .csv file whose header has a frame or t column. Reads only as far as it needs to;
// false for other extensions and for files that cannot be read or parsed (loading them
// then says why).
bool has_frames(const std::string& path);

// Parsing/serialising in memory (used by the file functions and by tests). `source` names
// the origin in error messages. The parsers accept files without frames too.
Animation parse_animation_json(const std::string& text, const std::string& source);
Animation parse_animation_csv(const std::string& text, const std::string& source,
                              const LoadOptions& options = {});
std::string animation_to_json(const Animation& data, const RunStats* stats = nullptr);
// Rows frame,time,element,sample,x,y[,z],class,... ; type flags, topology and the domain are
// not carried (as for to_csv).
std::string animation_to_csv(const Animation& data);

}  // namespace tessera
