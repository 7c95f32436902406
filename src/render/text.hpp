// Text on the raster canvas for legends: stb_easy_font's glyphs (libstb-dev), which are
// axis-aligned rectangles, so no font file is needed and scaled text stays smooth when
// each rectangle is filled by its exact pixel coverage. Printable ASCII only: other
// characters are drawn as '?'.
#pragma once

#include <string>

#include "render/raster.hpp"

namespace tessera::render {

// Width and cap height in pixels of `text` drawn at `scale` (1 = the font's own size,
// capitals 7 pixels tall).
double text_width(const std::string& text, double scale);
inline double text_cap_height(double scale) { return 7.0 * scale; }

// Draws `text` with the top-left corner of its first capital at (x, y).
void draw_text(Canvas& canvas, const std::string& text, double x, double y, double scale, Rgb color);

// Fills [x0, x1] x [y0, y1] (pixel coordinates) with exact area coverage, mixed in by
// `opacity`.
void fill_rect(Canvas& canvas, double x0, double y0, double x1, double y1, Rgb color, double opacity = 1.0);

}  // namespace tessera::render
