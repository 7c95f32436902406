// The supersampled 3D pictures (spheres, element meshes): drawn at 2x2 samples per
// pixel and box-filtered down, which anti-aliases silhouettes without the coverage
// bookkeeping a z-buffer would otherwise need. Shared so that both pictures agree on
// the sampling and on how the domain box edges look.
#pragma once

#include <vector>

#include "render/palette.hpp"
#include "render/raster.hpp"
#include "render/scene_3d.hpp"

namespace tessera::render {

// Samples per pixel side for a width x height picture: 2, or 1 when 2x2 samples of
// `bytes_per_sample` each would take more than 1 GiB (bounded memory for very large
// pictures, which need no anti-aliasing to speak of).
int supersampling(int width, int height, int bytes_per_sample);

// A thin grey edge a-b of the domain box drawn into `color` (the samples, `width`
// per row, `ss` per pixel side), with coverage anti-aliasing, hidden where `depth`
// (larger = nearer, one per sample) holds something in front of it.
void draw_hidden_edge(std::vector<Rgb>& color, const std::vector<float>& depth, int width, const View3D& view,
                      const Frame3D& frame, int ss, const Vec3& a, const Vec3& b);

// The mean of each ss x ss block of samples (`width` samples per row): the picture.
Canvas box_filter(const std::vector<Rgb>& color, int width, int ss);

}  // namespace tessera::render
