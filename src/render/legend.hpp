// The legend strip under a picture: a swatch in the class colour and the class name for
// every type, in type order, flowing left to right over as many rows as the names need
// (at most max_rows; the last entry then says how many more there are). Laid out once in
// pixels and drawn by the PNG canvas and the SVG writers alike, so both pictures agree.
// The strip lies outside the domain's picture, so it hides no element.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "render/palette.hpp"
#include "render/raster.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/render.hpp"

namespace tessera::render {

struct LegendEntry {
    std::string label;    // the class name (shortened with "..." to fit a row)
    Rgb color;
    bool swatch = true;   // false for the closing "+N more"
    double x = 0.0, y = 0.0;  // swatch centre's x, the row's centre line (pixels, y down)
};

struct Legend {
    std::vector<LegendEntry> entries;
    double height = 0.0;      // pixels; 0 = no legend
    double scale = 1.0;       // text scale (text.hpp); font size in SVG = 10 x scale
    double swatch_radius = 0.0;
    double text_offset = 0.0;  // from the swatch centre to the label's left edge
};

inline constexpr int legend_max_rows = 4;
inline constexpr int legend_min_width = 96;  // pixels: narrower pictures get no legend

// The legend of `data` for a picture `width` pixels wide, or an empty one when the
// options say so, the picture is narrower than legend_min_width, or the data have a
// single unnamed class (named "default" by the file readers, "0" by Python).
Legend make_legend(const Exemplar& data, const std::vector<Rgb>& colors, int width, const RenderOptions& options);

// Adds the legend's rows under `canvas` and draws it there.
void draw_legend_png(Canvas& canvas, const Legend& legend);

// Writes the legend as SVG in pixel units with its top edge at y = 0 (the caller places
// it with a transform).
void write_legend_svg(std::ostream& out, const Legend& legend);

}  // namespace tessera::render
