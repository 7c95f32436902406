// tessera/render.hpp — preview pictures of an exemplar or arrangement.
// 2D: elements as disks (radius, or a size derived from the spacing) or as
// polylines through their samples, coloured by class, with the domain outline.
// 3D: an orthographic view along a tilted axis with depth shading.
// Element meshes (tessera/geometry.hpp): the triangles of a Scene, shaded, in the
// same views. Each class is drawn in its colour (type_colors) and named in a legend
// strip below the picture.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tessera/exemplar.hpp"
#include "tessera/geometry.hpp"

namespace tessera {

struct RenderOptions {
    int width = 800;           // picture width in pixels; height follows the aspect ratio
    bool show_domain = true;   // draw the domain outline
    bool show_samples = true;  // mark the samples of multi-sample elements
    // A strip below the picture with a swatch and the name of every class; never drawn
    // for data with a single unnamed class (the loaders' "default").
    bool show_legend = true;
    // Element meshes (geometry.hpp) instead of disks / spheres: on = always (types
    // without a mesh file get default shapes), off = never, automatic = draw element
    // meshes when some type of the data has a mesh file (ElementType::mesh).
    enum class Meshes { automatic, on, off } meshes = Meshes::automatic;
    // Faint lines every `grid` units from the world origin across the domain's bounds (the
    // tile borders of a world, docs/worlds.md): in 2D the lines, in 3D the edges of every
    // grid cell. 0 = none; at most 4096 cells along an axis.
    double grid = 0.0;
    // The region the picture shows, instead of the domain's bounds grown to every element (the
    // frames of an animation share one view, so that they have one size; in 3D the view is
    // fitted to this box). Unset = that.
    std::optional<Box> view = {};
    // The spacing that sizes elements without a radius (disks of 0.4 x it) and polylines; 0 =
    // the data's mean nearest-neighbour distance. Fixed for the frames of an animation, whose
    // trails would otherwise count as neighbours.
    double spacing = 0.0;
};

// An sRGB colour, 8 bits per component.
struct Color {
    std::uint8_t r = 0, g = 0, b = 0;
    bool operator==(const Color&) const = default;
};

// Parses a colour as a type's "color" field holds it: "#rrggbb", "#rgb", or a CSS / X11
// colour name ("darkgreen", "Light Blue": case, spaces, hyphens and underscores do not
// matter). nullopt when `text` is none of these.
std::optional<Color> parse_color(const std::string& text);

// The colour every type of `data` is drawn in, by type index: its ElementType::color
// when set, else its name when that is a colour name ("cyan", "dark green"), else the
// next colour of a fixed qualitative palette (Tableau 10) that does not look like one
// already taken by the types before (so that an unnamed class is not drawn red beside
// a class named "red"). Throws Error(input) naming the type for a color that
// parse_color does not read.
std::vector<Color> type_colors(const Exemplar& data);

// Option errors of the functions below start with the name of the RenderOptions field
// at fault ("width: ...", "meshes: ..."), so that a front end can name its own
// spelling of it.

// Throws Error(option) when options.width is outside [16, 16384]: what can be checked
// before the data are known (their shape decides the picture's height).
void check_render_options(const RenderOptions& options);

// PNG bytes (8-bit RGB).
std::string render_png(const Exemplar& data, const RenderOptions& options = {});
// SVG text.
std::string render_svg(const Exemplar& data, const RenderOptions& options = {});
// PNG bytes (8-bit RGB) of the triangle meshes of `scene`, an arrangement of `data`
// (which supplies the domain outline and, with the meshes, the framing; Scene::dimension
// must equal data.dimension). 3D: the camera of the 3D preview, z-buffered and shaded,
// both sides of a surface lit; normals are smooth across gentle bends and split where
// faces meet at more than 40 degrees, so spheres and tubes look round and boxes keep
// flat faces with crisp edges. 2D: seen from above (x right, y up) at the pixel scale
// of render_png, lit from the upper left so the meshes read as relief; parts outside
// that frame are cut off. Colours by SceneInstance::type: the colour of that type of
// `data` (type_colors), the palette for types beyond data's. Throws Error(input) for data
// render_png cannot draw or an instance naming a mesh the scene does not have,
// Error(option) for a bad width.
std::string render_scene_png(const Exemplar& data, const Scene& scene, const RenderOptions& options = {});
// Writes .png or .svg by extension, atomically. A .png shows the element meshes
// (build_scene, render_scene_png) when options.meshes is on, or automatic and some type
// has a mesh; a .svg always draws disks and polylines (meshes = on is then an option
// error naming meshes). Throws Error(option) for another extension, and what
// build_scene throws.
void render_to_file(const Exemplar& data, const std::string& path, const RenderOptions& options = {});

}  // namespace tessera
