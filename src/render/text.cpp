// Legend text on the canvas (text.hpp).
#include "render/text.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <stb_easy_font.h>

namespace tessera::render {
namespace {

// The font indexes its table with the (signed) char, so a byte >= 128 would read
// before the table: every character outside printable ASCII becomes '?'.
std::string printable(std::string text) {
    for (char& c : text)
        if (c < 32 || c > 126) c = '?';
    return text;
}

void blend(Canvas& canvas, int x, int y, Rgb color, double alpha) {
    if (x < 0 || y < 0 || x >= canvas.width() || y >= canvas.height() || !(alpha > 0.0)) return;
    const Rgb p = canvas.pixel(x, y);
    const float a = static_cast<float>(std::min(alpha, 1.0));
    canvas.set_pixel(x, y, {p.r + (color.r - p.r) * a, p.g + (color.g - p.g) * a, p.b + (color.b - p.b) * a});
}

}  // namespace

double text_width(const std::string& text, double scale) {
    std::string copy = printable(text);
    return scale * stb_easy_font_width(copy.data());
}

void fill_rect(Canvas& canvas, double x0, double y0, double x1, double y1, Rgb color, double opacity) {
    for (int y = static_cast<int>(std::floor(y0)); y < std::ceil(y1); ++y) {
        const double cy = std::min(y1, y + 1.0) - std::max(y0, static_cast<double>(y));
        for (int x = static_cast<int>(std::floor(x0)); x < std::ceil(x1); ++x) {
            const double cx = std::min(x1, x + 1.0) - std::max(x0, static_cast<double>(x));
            blend(canvas, x, y, color, opacity * cx * cy);
        }
    }
}

void draw_text(Canvas& canvas, const std::string& text, double x, double y, double scale, Rgb color) {
    std::string copy = printable(text);
    // At most about 64 quads of 64 bytes (4 vertices of x, y, z, colour) per glyph.
    std::vector<char> buffer(copy.size() * 64 * 16 + 64);
    const int quads =
        stb_easy_font_print(0.0f, 0.0f, copy.data(), nullptr, buffer.data(), static_cast<int>(buffer.size()));
    for (int q = 0; q < quads; ++q) {
        // Vertices 0 and 2 of a quad are opposite corners.
        float v0[2], v2[2];
        std::copy_n(reinterpret_cast<const float*>(buffer.data() + q * 64), 2, v0);
        std::copy_n(reinterpret_cast<const float*>(buffer.data() + q * 64 + 32), 2, v2);
        fill_rect(canvas, x + scale * std::min(v0[0], v2[0]), y + scale * std::min(v0[1], v2[1]),
                  x + scale * std::max(v0[0], v2[0]), y + scale * std::max(v0[1], v2[1]), color);
    }
}

}  // namespace tessera::render
