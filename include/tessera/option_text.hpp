// tessera/option_text.hpp — the text forms of options that every front end shares (the
// `tessera` CLI, the Python module), so that `--domain box:40,40` and
// `tessera.synthesize(..., domain="box:40,40")` mean the same and fail the same way.
// Each parser takes `parameter`, the name the caller knows the option by ("--domain",
// "domain"), and names it in its one-line Error(option) messages.
#pragma once

#include <string>
#include <vector>

#include "tessera/det.hpp"
#include "tessera/domain.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/geometry.hpp"
#include "tessera/render.hpp"

namespace tessera {

// The output domain forms (docs/cli.md, --domain):
//   box:W,H | box:W,H,D                      a box of that size from the exemplar domain's lower corner
//   box:xmin,ymin,xmax,ymax[,zmin,zmax]      explicit corners
//   polygon:FILE.json | polygon:x1,y1,...    2D polygon (holes in the file form)
//   mask:FILE.png[@xmin,ymin,xmax,ymax]      2D image mask (default box: the exemplar domain x scale)
//   mesh:FILE[,resolution]                   3D closed OBJ/PLY mesh
//   shell:FILE,thickness[,resolution]        3D band under a mesh surface
// Throws Error(option) for malformed text, Error(domain) when the domain's dimension is not
// the exemplar's, Error(io) / Error(domain) from the files it names.
Domain parse_output_domain(const std::string& spec, const Exemplar& exemplar, double scale = 2.0,
                           const std::string& parameter = "--domain");
// Only the syntax of `spec` (no files read), so a front end can fail before loading inputs.
void check_domain_spec(const std::string& spec, const std::string& parameter = "--domain");

// An axis with its sign: "-x", "+y", "z" (= +z) -> a unit vector. For --gravity.
Vec3 parse_axis_direction(const std::string& text, const std::string& parameter);
// A comma-separated list of sides, "-x,+x,+y" -> DetOptions::boundary_sides.
std::vector<DetOptions::BoundarySide> parse_boundary_sides(const std::string& text, const std::string& parameter);
// "kcoherence" | "exhaustive"; "greedy" | "hungarian".
SearchMode parse_search_mode(const std::string& text, const std::string& parameter);
Matching parse_matching(const std::string& text, const std::string& parameter);
// "auto" | "on" | "off" (RenderOptions::meshes); "gpu" | "nodes" (SaveOptions::gltf_instancing).
RenderOptions::Meshes parse_render_meshes(const std::string& text, const std::string& parameter);
GltfInstancing parse_gltf_instancing(const std::string& text, const std::string& parameter);
const char* to_string(SearchMode mode);
const char* to_string(Matching matching);

}  // namespace tessera
