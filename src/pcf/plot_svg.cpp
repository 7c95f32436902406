// The PCF model picture as SVG (tessera/pcf_plot.hpp), drawn from plot_layout: per panel
// a frame, the envelope as a translucent polygon (upper forward, lower back), the mean
// as a line, guides at PCF = 1 and at the salient disk distances, ticks and a title.
#include <string>

#include "pcf/plot_layout.hpp"
#include "render/svg_writer.hpp"

namespace tessera {
namespace {

std::string escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '&') out += "&amp;";
        else if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '"') out += "&quot;";
        else out += c;
    }
    return out;
}

}  // namespace

std::string pcf_plot_svg(const PcfModel& model, const PcfPlotOptions& options) {
    const pcf::PlotLayout layout = pcf::plot_layout(model, options);
    const render::SvgNumbers num(1.0);
    const auto points = [&](const std::vector<pcf::PlotPoint>& v) {
        std::string s;
        for (const auto& p : v) s += (s.empty() ? "" : " ") + num(p.x) + "," + num(p.y);
        return s;
    };
    const auto line = [&](double x1, double y1, double x2, double y2, const std::string& style) {
        return "<line x1=\"" + num(x1) + "\" y1=\"" + num(y1) + "\" x2=\"" + num(x2) + "\" y2=\"" + num(y2) + "\" " +
               style + "/>\n";
    };
    std::string out = render::svg_header(layout.width, layout.height,
                                         "0 0 " + std::to_string(layout.width) + " " + std::to_string(layout.height));
    out += "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
    out += "<g font-family=\"sans-serif\" font-size=\"10\" fill=\"#333333\">\n";
    for (const pcf::PlotPanel& p : layout.panels) {
        const std::string color = render::to_hex(p.color);
        out += "<g>\n";
        out += "<rect x=\"" + num(p.left) + "\" y=\"" + num(p.top) + "\" width=\"" + num(p.right - p.left) +
               "\" height=\"" + num(p.bottom - p.top) + "\" fill=\"none\" stroke=\"#9e9e9e\"/>\n";
        for (double x : p.salient_x) out += line(x, p.top, x, p.bottom, "stroke=\"#d0d0d0\" stroke-dasharray=\"2,3\"");
        if (p.one_y >= 0) out += line(p.left, p.one_y, p.right, p.one_y, "stroke=\"#b0b0b0\" stroke-dasharray=\"4,3\"");
        std::vector<pcf::PlotPoint> band = p.upper;
        band.insert(band.end(), p.lower.rbegin(), p.lower.rend());
        out += "<polygon points=\"" + points(band) + "\" fill=\"" + color + "\" fill-opacity=\"0.3\" stroke=\"none\"/>\n";
        out += "<polyline points=\"" + points(p.mean) + "\" fill=\"none\" stroke=\"" + render::to_hex(render::darker(p.color, 0.8f)) +
               "\" stroke-width=\"2\" stroke-linejoin=\"round\"/>\n";
        if (!p.measured.empty())
            out += "<polyline points=\"" + points(p.measured) +
                   "\" fill=\"none\" stroke=\"#222222\" stroke-width=\"1.2\" stroke-linejoin=\"round\"/>\n";
        for (const auto& t : p.x_ticks) {
            out += line(t.at, p.bottom, t.at, p.bottom + 3, "stroke=\"#9e9e9e\"");
            out += "<text x=\"" + num(t.at) + "\" y=\"" + num(p.bottom + 14) + "\" text-anchor=\"middle\">" + t.label + "</text>\n";
        }
        for (const auto& t : p.y_ticks) {
            out += line(p.left - 3, t.at, p.left, t.at, "stroke=\"#9e9e9e\"");
            out += "<text x=\"" + num(p.left - 5) + "\" y=\"" + num(t.at + 3.5) + "\" text-anchor=\"end\">" + t.label + "</text>\n";
        }
        out += "<text x=\"" + num(0.5 * (p.left + p.right)) + "\" y=\"" + num(p.top - 7) +
               "\" text-anchor=\"middle\" font-size=\"12\" font-weight=\"bold\" fill=\"" +
               render::to_hex(render::darker(p.color, 0.7f)) + "\">" + escape(p.title) + "</text>\n";
        out += "</g>\n";
    }
    for (size_t l = 0; l < layout.footer.size(); ++l)
        out += "<text x=\"8\" y=\"" + num(layout.footer_y + 14 + layout.footer_line * l) + "\" fill=\"#666666\">" +
               escape(layout.footer[l]) + "</text>\n";
    out += "</g>\n</svg>\n";
    return out;
}

}  // namespace tessera
