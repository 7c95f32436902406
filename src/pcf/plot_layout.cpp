// Lays out a PCF model picture: panels in rows, each with a y range that shows the mean
// PCF whole and the envelope up to twice the mean's peak (individual PCFs of elements
// with a close neighbour spike far above it near x = 0 and would flatten every curve),
// ticks at round values, and curves mapped to pixels and clipped to the panel.
#include "pcf/plot_layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tessera/error.hpp"

namespace tessera::pcf {
namespace {

// Margins inside a panel: room for the title above and tick labels left and below.
constexpr double margin_left = 38, margin_right = 10, margin_top = 22, margin_bottom = 24;
constexpr double footer_line = 14, footer_pad = 8;
constexpr double char_width = 6.2;  // average glyph advance of the notes (PNG font: 6; SVG 10 px sans: ~5.5)

// The smallest of 1, 1.5, 2, 2.5, 3, 4, 5, 6, 8 times a power of ten that is >= v.
double nice_ceiling(double v) {
    if (!(v > 0.0)) return 1.0;
    const double unit = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0})
        if (m * unit >= v * (1 - 1e-12)) return m * unit;
    return 10.0 * unit;
}

// A tick spacing giving 3 to 6 ticks over [0, top].
double tick_step(double top) {
    const double unit = std::pow(10.0, std::floor(std::log10(top)));
    for (double m : {0.1, 0.2, 0.25, 0.5, 1.0, 2.0, 2.5, 5.0})
        if (top / (m * unit) <= 6.0 + 1e-9) return m * unit;
    return 10.0 * unit;
}

std::string label(double v) {
    char s[32];
    std::snprintf(s, sizeof s, "%g", std::abs(v) < 1e-12 ? 0.0 : v);
    return s;
}

double peak(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }

}  // namespace

PlotLayout plot_layout(const PcfModel& model, const PcfPlotOptions& o) {
    if (o.panel_width < 120 || o.panel_width > 2000 || o.panel_height < 90 || o.panel_height > 2000)
        throw Error(ErrorKind::option, "PCF plot: panels must be 120 to 2000 pixels wide and 90 to 2000 high, got " +
                                           std::to_string(o.panel_width) + " x " + std::to_string(o.panel_height));
    if (o.columns < 0 || o.columns > 64)
        throw Error(ErrorKind::option, "PCF plot: columns must be 0 (automatic) to 64, got " + std::to_string(o.columns));
    const int n = static_cast<int>(model.pcfs.size());
    if (n == 0) throw Error(ErrorKind::option, "PCF plot: the model has no PCFs");
    if (!o.measured.empty() && static_cast<int>(o.measured.size()) != n)
        throw Error(ErrorKind::option, "PCF plot: " + std::to_string(o.measured.size()) +
                                           " measured PCFs for a model with " + std::to_string(n));
    for (const PcfEnvelope& e : o.measured)
        if (e.mean.size() != model.x.size())
            throw Error(ErrorKind::option, "PCF plot: a measured PCF has another number of values than the model's axis");

    const int columns = o.columns > 0 ? std::min(o.columns, n)
                                      : (n <= 4 ? n : std::min(8, static_cast<int>(std::ceil(std::sqrt(n - 1e-9)))));
    const int rows = (n + columns - 1) / columns;
    PlotLayout layout;
    layout.width = columns * o.panel_width;
    // Notes under the panels, as many per line as fit the width.
    std::vector<std::string> notes = {model.disks ? "x: normalised disk distance (1 inner border, 2 centre on border, "
                                                    "3 tangent, then 3 + gap / r_max)"
                                                  : "x: distance / r_max",
                                      "band: envelope of individual PCFs"};
    if (!o.measured.empty()) notes.push_back("dark line: measured");
    const size_t room = static_cast<size_t>(std::max(10.0, (layout.width - 16) / char_width));
    std::string text;
    for (const std::string& note : notes) text += (text.empty() ? "" : "; ") + note;
    std::string word;
    for (size_t i = 0; i <= text.size(); ++i) {  // greedy word wrap
        if (i < text.size() && text[i] != ' ') {
            word += text[i];
            continue;
        }
        if (layout.footer.empty() || layout.footer.back().size() + 1 + word.size() > room)
            layout.footer.push_back(word);
        else
            layout.footer.back() += " " + word;
        word.clear();
    }
    layout.footer_line = footer_line;
    layout.footer_y = rows * o.panel_height;
    layout.height = static_cast<int>(layout.footer_y + footer_pad + footer_line * layout.footer.size());

    const double x_top = model.x.empty() ? 1.0 : model.x.back();
    for (int q = 0; q < n; ++q) {
        const PcfEnvelope& e = model.pcfs[q];
        PlotPanel p;
        const double ox = (q % columns) * o.panel_width, oy = (q / columns) * o.panel_height;
        p.left = ox + margin_left;
        p.right = ox + o.panel_width - margin_right;
        p.top = oy + margin_top;
        p.bottom = oy + o.panel_height - margin_bottom;
        const std::string& child = model.classes.at(e.child);
        p.title = e.parent == e.child ? child : child + " | " + model.classes.at(e.parent);
        p.color = render::class_color(e.child);

        const double mean_peak = std::max(peak(e.mean), o.measured.empty() ? 0.0 : peak(o.measured[q].mean));
        const double y_top = nice_ceiling(std::max({1.5, 1.1 * mean_peak, std::min(peak(e.upper), 2.0 * mean_peak)}));
        const auto px = [&](double x) { return p.left + (p.right - p.left) * x / x_top; };
        const auto py = [&](double y) { return p.bottom - (p.bottom - p.top) * std::clamp(y, 0.0, y_top) / y_top; };
        const auto curve = [&](const std::vector<double>& v) {
            std::vector<PlotPoint> out;
            for (size_t k = 0; k < v.size() && k < model.x.size(); ++k) out.push_back({px(model.x[k]), py(v[k])});
            return out;
        };
        p.mean = curve(e.mean);
        p.lower = curve(e.lower);
        p.upper = curve(e.upper);
        if (!o.measured.empty()) p.measured = curve(o.measured[q].mean);

        const double xs = x_top > 10.0 ? 2.0 : 1.0;
        for (double x = 0.0; x <= x_top + 1e-9; x += xs) p.x_ticks.push_back({px(x), label(x)});
        const double ys = tick_step(y_top);
        for (double y = 0.0; y <= y_top * (1 + 1e-9); y += ys) p.y_ticks.push_back({py(y), label(y)});
        if (y_top >= 1.0) p.one_y = py(1.0);
        if (model.disks)
            for (double x : {1.0, 2.0, 3.0})
                if (x <= x_top) p.salient_x.push_back(px(x));
        layout.panels.push_back(std::move(p));
    }
    return layout;
}

}  // namespace tessera::pcf
