// The PCF model picture as PNG (tessera/pcf_plot.hpp), drawn from plot_layout on the
// preview pictures' raster canvas: lines as anti-aliased capsules, the envelope filled
// column by column with exact vertical coverage, and text and rectangles from the
// legends' text module (render/text.hpp).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "pcf/plot_layout.hpp"
#include "render/raster.hpp"
#include "render/text.hpp"

namespace tessera {
namespace {

using render::Canvas;
using render::Rgb;
using render::draw_text;
using render::fill_rect;
using render::text_width;

void draw_polyline(Canvas& canvas, const std::vector<pcf::PlotPoint>& v, double half_width, Rgb color) {
    for (size_t k = 1; k < v.size(); ++k) canvas.add_capsule(v[k - 1].x, v[k - 1].y, v[k].x, v[k].y, half_width);
    canvas.composite(color);
}

void draw_dashed(Canvas& canvas, double x0, double y0, double x1, double y1, double dash, Rgb color) {
    const double length = std::hypot(x1 - x0, y1 - y0);
    for (double s = 0.0; s < length; s += 2.0 * dash) {
        const double e = std::min(length, s + dash);
        canvas.add_capsule(x0 + (x1 - x0) * s / length, y0 + (y1 - y0) * s / length, x0 + (x1 - x0) * e / length,
                           y0 + (y1 - y0) * e / length, 0.5);
    }
    canvas.composite(color);
}

// The band between two curves sampled at the same x values, filled per pixel column.
void fill_band(Canvas& canvas, const std::vector<pcf::PlotPoint>& upper, const std::vector<pcf::PlotPoint>& lower,
               Rgb color, double opacity) {
    if (upper.size() < 2) return;
    const auto at = [](const std::vector<pcf::PlotPoint>& v, double x) {
        size_t k = 1;
        while (k + 1 < v.size() && v[k].x < x) ++k;
        const double t = std::clamp((x - v[k - 1].x) / (v[k].x - v[k - 1].x), 0.0, 1.0);
        return v[k - 1].y + t * (v[k].y - v[k - 1].y);
    };
    for (int x = static_cast<int>(std::floor(upper.front().x)); x < std::ceil(upper.back().x); ++x) {
        const double cx = x + 0.5;
        const double top = at(upper, cx), bottom = at(lower, cx);
        const double x0 = std::max(static_cast<double>(x), upper.front().x), x1 = std::min(x + 1.0, upper.back().x);
        fill_rect(canvas, x0, top, x1, std::max(top, bottom), color, opacity);
    }
}

}  // namespace

std::string pcf_plot_png(const PcfModel& model, const PcfPlotOptions& options) {
    const pcf::PlotLayout layout = pcf::plot_layout(model, options);
    Canvas canvas(layout.width, layout.height, render::white);
    const Rgb frame{0.62f, 0.62f, 0.62f}, guide{0.8f, 0.8f, 0.8f}, ink{0.2f, 0.2f, 0.2f};
    for (const pcf::PlotPanel& p : layout.panels) {
        for (double x : p.salient_x) draw_dashed(canvas, x, p.top, x, p.bottom, 2.0, guide);
        if (p.one_y >= 0) draw_dashed(canvas, p.left, p.one_y, p.right, p.one_y, 4.0, {0.7f, 0.7f, 0.7f});
        fill_band(canvas, p.upper, p.lower, p.color, 0.3);
        draw_polyline(canvas, p.mean, 1.0, render::darker(p.color, 0.8f));
        if (!p.measured.empty()) draw_polyline(canvas, p.measured, 0.6, {0.13f, 0.13f, 0.13f});
        fill_rect(canvas, p.left - 0.5, p.top - 0.5, p.right + 0.5, p.top + 0.5, frame);
        fill_rect(canvas, p.left - 0.5, p.bottom - 0.5, p.right + 0.5, p.bottom + 0.5, frame);
        fill_rect(canvas, p.left - 0.5, p.top - 0.5, p.left + 0.5, p.bottom + 0.5, frame);
        fill_rect(canvas, p.right - 0.5, p.top - 0.5, p.right + 0.5, p.bottom + 0.5, frame);
        for (const auto& t : p.x_ticks) {
            fill_rect(canvas, t.at - 0.5, p.bottom, t.at + 0.5, p.bottom + 3, frame);
            draw_text(canvas, t.label, t.at - 0.5 * text_width(t.label, 1.0), p.bottom + 5, 1.0, ink);
        }
        for (const auto& t : p.y_ticks) {
            fill_rect(canvas, p.left - 3, t.at - 0.5, p.left, t.at + 0.5, frame);
            draw_text(canvas, t.label, p.left - 5 - text_width(t.label, 1.0), t.at - 3.5, 1.0, ink);
        }
        // Titles at 1.5x; shortened with "..." when wider than the panel.
        std::string title = p.title;
        const double room = p.right - p.left + 20;
        while (title.size() > 4 && text_width(title, 1.5) > room) title = title.substr(0, title.size() - 4) + "...";
        draw_text(canvas, title, 0.5 * (p.left + p.right) - 0.5 * text_width(title, 1.5), p.top - 16,
                  1.5, render::darker(p.color, 0.7f));
    }
    for (size_t l = 0; l < layout.footer.size(); ++l)
        draw_text(canvas, layout.footer[l], 8, layout.footer_y + 6 + layout.footer_line * l, 1.0, {0.4f, 0.4f, 0.4f});
    return canvas.encode_png();
}

}  // namespace tessera
