// render_png / render_svg: check the data and options once, then hand over to
// the writer for the data's dimension.
#include "render/render_internal.hpp"
#include "render/style.hpp"
#include "tessera/render.hpp"

namespace tessera {

void check_render_options(const RenderOptions& options) { render::check_options(options); }

std::string render_png(const Exemplar& data, const RenderOptions& options) {
    render::check_options(options);
    render::check_drawable(data);
    return data.dimension == 2 ? render::render_png_2d(data, options) : render::render_png_3d(data, options);
}

std::string render_svg(const Exemplar& data, const RenderOptions& options) {
    render::check_options(options);
    render::check_drawable(data);
    return data.dimension == 2 ? render::render_svg_2d(data, options) : render::render_svg_3d(data, options);
}

}  // namespace tessera
