// A small anti-aliased raster canvas for the preview pictures. A shape is built
// from primitives (disks, capsules) whose per-pixel coverage is combined by max
// into a scratch buffer, then composited once in one colour: a polyline's joints
// are therefore not darkened by double blending. Every primitive only visits the
// pixels of its bounding box, so 100,000 small shapes render quickly. Pixel
// coordinates are continuous, x right and y down, pixel (i, j) centred at
// (i + 0.5, j + 0.5).
#pragma once

#include <string>
#include <vector>

#include "render/palette.hpp"

namespace tessera::render {

class Canvas {
public:
    Canvas(int width, int height, Rgb background);

    int width() const { return width_; }
    int height() const { return height_; }
    // Adds `rows` rows of `background` at the bottom (a legend strip under the picture).
    void add_rows(int rows, Rgb background);

    // Coverage of the shape being built (see composite).
    void add_disk(double cx, double cy, double radius);
    // Segment a-b widened by half_width, with round caps (capsule distance).
    void add_capsule(double ax, double ay, double bx, double by, double half_width);
    // Blends the accumulated coverage in `color` (times `opacity`) and clears it.
    void composite(Rgb color, float opacity = 1.0f);

    Rgb pixel(int x, int y) const;
    void set_pixel(int x, int y, Rgb c);

    // 8-bit RGB PNG bytes (stb_image_write).
    std::string encode_png() const;

private:
    void cover(int index, float coverage);

    int width_ = 0, height_ = 0;
    std::vector<float> rgb_;       // width * height * 3, sRGB in [0, 1]
    std::vector<float> coverage_;  // scratch of the shape being built
    std::vector<int> touched_;     // pixels with coverage > 0, to composite and clear
};

}  // namespace tessera::render
