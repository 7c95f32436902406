// The 3D preview scene shared by the PNG and SVG writers: a fixed orthographic
// camera (azimuth 35 deg from the -y axis toward +x, elevation 25 deg, z up, so
// x runs right, z up and the +x and top faces of the box are in view), the
// spheres that stand for elements (multi-sample elements become chains of small
// spheres: a tube with beads at the samples) and the picture frame.
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "render/palette.hpp"
#include "render/style.hpp"
#include "tessera/exemplar.hpp"

namespace tessera::render {

struct View3D {
    Vec3 right, up, toward;  // orthonormal; `toward` points from the scene to the viewer

    static View3D standard();
    double sx(const Vec3& p) const { return dot(p, right); }
    double sy(const Vec3& p) const { return dot(p, up); }
    double depth(const Vec3& p) const { return dot(p, toward); }  // larger = nearer
};

struct Sphere {
    Vec3 center;
    double radius = 0.0;  // data units
    int type = 0;
    bool marker = false;  // a sample bead of a multi-sample element (drawn darker)
};

// Spheres for every element, in element order. With `sheet_borders`, a sheet (a grid of
// samples) gets its border only, as a tube (the caller draws its surface: sheet_surface.hpp);
// otherwise each of its rows is a tube.
std::vector<Sphere> collect_spheres(const Exemplar& data, const Style& style, bool show_samples,
                                    bool sheet_borders = false);

// The 12 edges of a box.
std::array<std::pair<Vec3, Vec3>, 12> box_edges(const Box& box);

struct Frame3D {
    double x0 = 0.0, y1 = 0.0;  // screen-space left and top (data units)
    double scale = 1.0;         // pixels per data unit
    int width = 0, height = 0;
    double near = 0.0, far = 0.0;  // depth range of the scene (for depth fog)

    double px(const View3D& v, const Vec3& p) const { return (v.sx(p) - x0) * scale; }
    double py(const View3D& v, const Vec3& p) const { return (y1 - v.sy(p)) * scale; }
};

// Frame fitting the domain box and all spheres, `options.width` pixels wide.
// Throws Error(option) if the height would exceed 16384 pixels.
Frame3D make_frame_3d(const Exemplar& data, const std::vector<Sphere>& spheres, const View3D& view,
                      const RenderOptions& options);

// Lambert + ambient + a small Blinn highlight for a unit normal given in view
// coordinates (x right, y up, z toward the viewer), then depth fog toward white
// (`farness` in [0, 1]: 0 nearest). Shared so PNG pixels and SVG gradients match.
Rgb shade_sphere(Rgb base, const Vec3& normal_view, double farness);

}  // namespace tessera::render
