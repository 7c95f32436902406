// Z-buffered triangle rasterizer for the element-mesh pictures. It does not shade:
// each pixel keeps the depth, the interpolated normal and a tag (which triangle
// group won) of the nearest triangle, and the picture is shaded afterwards, once
// per visible pixel (deferred shading), so hidden surfaces cost no lighting.
//
// Pixel coordinates are continuous, x right and y down, pixel (i, j) centred at
// (i + 0.5, j + 0.5); a pixel belongs to a triangle when its centre does. Vertices
// are snapped to 1/256 pixel and the edge functions evaluated in integers, so the
// top-left fill rule is exact: two triangles sharing an edge never both draw, nor
// both skip, a pixel centre on that edge (no cracks, no double blending), and the
// result does not depend on floating-point rounding of the edge tests.
#pragma once

#include <cstddef>
#include <vector>

namespace tessera::render {

// A triangle corner in picture space: position in pixels, depth (larger = nearer)
// and the normal to interpolate (any length; the shader normalizes).
struct RasterVertex {
    double x = 0.0, y = 0.0;
    float depth = 0.0f;
    float nx = 0.0f, ny = 0.0f, nz = 0.0f;
};

class MeshRaster {
public:
    MeshRaster(int width, int height);

    static constexpr int bytes_per_pixel = 4 * sizeof(float) + sizeof(int);  // depth, normal, tag

    int width() const { return width_; }
    int height() const { return height_; }

    // Draws the triangle where it is strictly nearer than what is there (so of two
    // coincident surfaces the first drawn stays). Either winding; zero-area and
    // non-finite triangles draw nothing. Parts outside the picture are clipped.
    // `tag` >= 0 names what the pixel shows (the caller's instance index).
    void draw_triangle(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c, int tag);

    // Per pixel, index y * width + x.
    int tag(std::size_t i) const { return tag_[i]; }  // -1 = nothing drawn
    float depth(std::size_t i) const { return depth_[i]; }
    const float* normal(std::size_t i) const { return &normal_[3 * i]; }
    const std::vector<float>& depths() const { return depth_; }  // -inf = nothing drawn

    // Pixel centres found inside triangles so far, before the depth test: a test
    // hook for the fill rule (a mesh without overlaps covers each pixel once).
    std::size_t fragments() const { return fragments_; }

private:
    void fill(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c, int tag);

    int width_ = 0, height_ = 0;
    std::vector<float> depth_;
    std::vector<float> normal_;  // 3 per pixel
    std::vector<int> tag_;
    std::size_t fragments_ = 0;
};

}  // namespace tessera::render
