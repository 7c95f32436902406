// Layout and drawing of the legend strip (legend.hpp).
#include "render/legend.hpp"

#include <algorithm>
#include <cmath>

#include "render/svg_writer.hpp"
#include "render/text.hpp"

namespace tessera::render {
namespace {

// Sizes in units of the text scale: swatch radius, gaps, row height, strip padding.
constexpr double swatch_radius = 4.5, swatch_gap = 4.0, entry_gap = 14.0, row_height = 15.0, padding = 6.0;

bool unnamed_single_class(const Exemplar& data) {
    return data.types.size() == 1 && (data.types[0].name == "default" || data.types[0].name == "0");
}

// `label` cut to at most `room` pixels at `scale`, with "..." when cut.
std::string fit(std::string label, double room, double scale) {
    if (text_width(label, scale) <= room) return label;
    while (!label.empty() && text_width(label + "...", scale) > room) label.pop_back();
    return label + "...";
}

std::string xml_escaped(const std::string& text) {
    std::string out;
    for (const char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += (static_cast<unsigned char>(c) < 32) ? '?' : c;
        }
    }
    return out;
}

}  // namespace

Legend make_legend(const Exemplar& data, const std::vector<Rgb>& colors, int width, const RenderOptions& options) {
    Legend legend;
    if (!options.show_legend || width < legend_min_width || data.types.empty() || unnamed_single_class(data))
        return legend;
    // Text about 14 pixels tall at 800 pixels, growing with the picture.
    const double s = legend.scale = std::clamp(width / 400.0, 1.0, 4.0);
    legend.swatch_radius = swatch_radius * s;
    legend.text_offset = (swatch_radius + swatch_gap) * s;
    const double left = padding * s, right = width - padding * s;
    const double lead = legend.swatch_radius + legend.text_offset;  // from an entry's left edge to its label
    // Flow every entry left to right, wrapping to a new row when it would pass the edge.
    std::vector<double> ends;  // right edge of each entry
    double x = left;
    int row = 0;
    for (size_t t = 0; t < data.types.size(); ++t) {
        const std::string label = fit(data.types[t].name, right - left - lead, s);
        const double extent = lead + text_width(label, s);
        if (x > left && x + extent > right) x = left, ++row;
        legend.entries.push_back({label, colors[t], true, x + legend.swatch_radius, static_cast<double>(row)});
        ends.push_back(x + extent);
        x += extent + entry_gap * s;
    }
    if (row >= legend_max_rows) {
        // Keep the first rows; end the last kept row with "+K more", dropping entries until it fits.
        size_t kept = 0;
        while (kept < legend.entries.size() && legend.entries[kept].y < legend_max_rows) ++kept;
        const auto more = [&](size_t k) { return "+" + std::to_string(legend.entries.size() - k) + " more"; };
        // Where "+K more" goes after the first k entries: after the k-th on the last row, else at its start.
        const auto more_x = [&](size_t k) {
            return k > 0 && legend.entries[k - 1].y == legend_max_rows - 1 ? ends[k - 1] + entry_gap * s : left;
        };
        while (kept > 0 && more_x(kept) + text_width(more(kept), s) > right) --kept;
        LegendEntry tail{more(kept), {0.35f, 0.35f, 0.35f}, false, more_x(kept), legend_max_rows - 1.0};
        legend.entries.resize(kept);
        legend.entries.push_back(tail);
        row = legend_max_rows - 1;
    }
    // Rows were numbered in y while flowing: turn them into centre lines.
    for (LegendEntry& e : legend.entries) e.y = (padding + (e.y + 0.5) * row_height) * s;
    legend.height = std::ceil((2.0 * padding + (row + 1) * row_height) * s);
    return legend;
}

void draw_legend_png(Canvas& canvas, const Legend& legend) {
    if (legend.height <= 0.0) return;
    const int top = canvas.height();
    canvas.add_rows(static_cast<int>(legend.height), white);
    const Rgb ink{0.15f, 0.15f, 0.15f};
    const double cap = text_cap_height(legend.scale);
    for (const LegendEntry& e : legend.entries) {
        const double y = top + e.y;
        if (!e.swatch) {
            draw_text(canvas, e.label, e.x, y - 0.5 * cap, legend.scale, e.color);
            continue;
        }
        canvas.add_disk(e.x, y, legend.swatch_radius);
        canvas.composite(darker(e.color, 0.72f));
        canvas.add_disk(e.x, y, legend.swatch_radius - std::clamp(0.08 * legend.swatch_radius * 2.0, 0.8, 2.0));
        canvas.composite(e.color);
        draw_text(canvas, e.label, e.x + legend.text_offset, y - 0.5 * cap, legend.scale, ink);
    }
}

void write_legend_svg(std::ostream& out, const Legend& legend) {
    if (legend.height <= 0.0) return;
    const SvgNumbers num(1.0);
    const double font = 10.0 * legend.scale;
    out << "<g class=\"legend\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\" font-size=\"" << num(font)
        << "\">\n";
    for (const LegendEntry& e : legend.entries) {
        // dominant-baseline is not honoured everywhere: put the baseline a third of the
        // font size below the centre line, where capitals are centred on it.
        const double baseline = e.y + 0.35 * font;
        if (e.swatch)
            out << "<circle cx=\"" << num(e.x) << "\" cy=\"" << num(e.y) << "\" r=\"" << num(legend.swatch_radius)
                << "\" fill=\"" << to_hex(e.color) << "\" stroke=\"" << to_hex(darker(e.color, 0.72f))
                << "\" stroke-width=\"" << num(0.1 * legend.swatch_radius) << "\"/>\n";
        out << "<text x=\"" << num(e.swatch ? e.x + legend.text_offset : e.x) << "\" y=\"" << num(baseline)
            << "\" fill=\"" << (e.swatch ? "#262626" : to_hex(e.color)) << "\">" << xml_escaped(e.label)
            << "</text>\n";
    }
    out << "</g>\n";
}

}  // namespace tessera::render
