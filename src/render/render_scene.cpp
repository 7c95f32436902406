// render_scene_png: pictures of element meshes. The meshes are rasterized once at
// 2x2 samples per pixel (scene_raster.hpp), every visible sample is then shaded from
// its interpolated normal (deferred: hidden surfaces cost no lighting), and the samples
// are box-filtered into the picture (supersample.hpp). The cameras and frames are those
// of the previews, so a mesh picture can be set beside render_png's.
#include <algorithm>
#include <cmath>
#include <vector>

#include "render/class_colors.hpp"
#include "render/legend.hpp"
#include "render/mesh_raster.hpp"
#include "render/palette.hpp"
#include "render/raster.hpp"
#include "render/render_internal.hpp"
#include "render/scene_3d.hpp"
#include "render/scene_raster.hpp"
#include "render/style.hpp"
#include "render/supersample.hpp"
#include "tessera/render.hpp"

namespace tessera {
namespace render {
namespace {

// The sample's normal, unit length. Interpolation can shrink it to nothing where the
// normals of a thin fold oppose; such a sample is shaded as facing the viewer.
Vec3 sample_normal(const MeshRaster& raster, size_t i) {
    const float* n = raster.normal(i);
    const Vec3 v{n[0], n[1], n[2]};
    const double length = norm(v);
    return length > 1e-6 ? v / length : Vec3{0, 0, 1};
}

// 2D relief: light from the upper left and above. Scaled so that a face looking
// straight up keeps the class colour (as the disk preview shows it); faces tilted
// toward the light lighten toward white, faces tilted away darken.
Rgb shade_relief(Rgb base, const Vec3& n) {
    static const Vec3 light = Vec3{-1.0, 1.0, 1.6} / norm(Vec3{-1.0, 1.0, 1.6});
    constexpr double ambient = 0.3;
    const double lit = ambient + (1.0 - ambient) * std::max(0.0, dot(n, light)) / light.z;
    if (lit <= 1.0) return darker(base, static_cast<float>(lit));
    return toward_white(base, static_cast<float>(std::min(1.0, lit - 1.0)));
}

// The colour of every type an instance names: the data's type colours (type_colors), and
// the palette for scene types beyond the data's.
std::vector<Rgb> scene_colors(const Exemplar& data, const Scene& scene) {
    std::vector<Rgb> colors = class_colors(data);
    for (const SceneInstance& instance : scene.instances)
        while (instance.type >= static_cast<int>(colors.size())) colors.push_back(class_color(static_cast<int>(colors.size())));
    return colors;
}

std::string render_scene_3d(const Exemplar& data, const Scene& scene, const RenderOptions& options) {
    const View3D view = View3D::standard();
    // Framed like the sphere preview, with the corners of the meshes' bounds standing
    // in for the spheres.
    std::vector<Sphere> extent;
    const Box bounds = scene_bounds(scene);
    if (bounds.lo.x <= bounds.hi.x)
        for (const auto& [a, b] : box_edges(bounds))
            for (const Vec3& corner : {a, b}) extent.push_back({corner, 0.0, 0, false});
    const Frame3D frame = make_frame_3d(data, extent, view, options);
    const std::vector<Rgb> colors = scene_colors(data, scene);
    const Legend legend = make_legend(data, colors, frame.width, options);
    check_picture_size(frame.width, frame.height + static_cast<int>(legend.height));
    const int ss = supersampling(frame.width, frame.height, MeshRaster::bytes_per_pixel + sizeof(Rgb));
    const int width = frame.width * ss;
    MeshRaster raster(width, frame.height * ss);
    rasterize_scene(scene, {view.right, view.up, view.toward, frame.x0, frame.y1, frame.scale * ss}, raster);

    std::vector<Rgb> color(static_cast<size_t>(width) * raster.height(), white);
    const double depth_range = std::max(frame.near - frame.far, 1e-300);
    for (size_t i = 0; i < color.size(); ++i) {
        const int tag = raster.tag(i);
        if (tag < 0) continue;
        color[i] = shade_sphere(colors[std::max(0, scene.instances[tag].type)], sample_normal(raster, i),
                                (frame.near - raster.depth(i)) / depth_range);
    }
    if (options.show_domain)
        for (const auto& [a, b] : box_edges(data.domain.bounds()))
            draw_hidden_edge(color, raster.depths(), width, view, frame, ss, a, b);
    Canvas canvas = box_filter(color, width, ss);
    draw_legend_png(canvas, legend);
    return canvas.encode_png();
}

std::string render_scene_2d(const Exemplar& data, const Scene& scene, const RenderOptions& options) {
    const Frame2D frame = make_frame_2d(data, make_style(data, options), options);
    const std::vector<Rgb> colors = scene_colors(data, scene);
    const Legend legend = make_legend(data, colors, frame.width, options);
    check_picture_size(frame.width, frame.height + static_cast<int>(legend.height));
    Canvas canvas(frame.width, frame.height, white);
    if (options.show_domain) draw_domain_outline(canvas, frame, data.domain);
    const int ss = supersampling(frame.width, frame.height, MeshRaster::bytes_per_pixel);
    const int width = frame.width * ss;
    MeshRaster raster(width, frame.height * ss);
    ScreenMap top_down;  // x right, y up, z toward the viewer above
    top_down.x0 = frame.lo.x, top_down.y1 = frame.hi.y, top_down.scale = frame.scale * ss;
    rasterize_scene(scene, top_down, raster);

    // Meshes over the outline: each pixel blends the mean of its samples' colours by
    // the fraction of samples a mesh covers, which anti-aliases the silhouettes.
    const float weight = 1.0f / static_cast<float>(ss * ss);
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x) {
            Rgb sum{0, 0, 0};
            int covered = 0;
            for (int j = 0; j < ss; ++j)
                for (int i = 0; i < ss; ++i) {
                    const size_t k = static_cast<size_t>(y * ss + j) * width + (x * ss + i);
                    const int tag = raster.tag(k);
                    if (tag < 0) continue;
                    const Rgb c =
                        shade_relief(colors[std::max(0, scene.instances[tag].type)], sample_normal(raster, k));
                    sum.r += c.r, sum.g += c.g, sum.b += c.b;
                    ++covered;
                }
            if (covered == 0) continue;
            const Rgb under = canvas.pixel(x, y);
            const float keep = 1.0f - covered * weight;
            canvas.set_pixel(x, y,
                             {under.r * keep + sum.r * weight, under.g * keep + sum.g * weight,
                              under.b * keep + sum.b * weight});
        }
    draw_legend_png(canvas, legend);
    return canvas.encode_png();
}

}  // namespace
}  // namespace render

std::string render_scene_png(const Exemplar& data, const Scene& scene, const RenderOptions& options) {
    render::check_options(options);
    render::check_drawable(data);
    render::check_scene(scene, data.dimension);
    return data.dimension == 2 ? render::render_scene_2d(data, scene, options)
                               : render::render_scene_3d(data, scene, options);
}

}  // namespace tessera
