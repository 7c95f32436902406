// Small helpers for writing SVG text: numbers with just enough decimals for the
// picture's resolution (keeps 100,000-element files small) and the document
// header every SVG preview starts with.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace tessera::render {

class SvgNumbers {
public:
    // `units_per_pixel`: size of one pixel in the coordinates being written;
    // numbers are rounded to about a tenth of a pixel.
    explicit SvgNumbers(double units_per_pixel)
        : decimals_(std::clamp(static_cast<int>(std::ceil(-std::log10(units_per_pixel * 0.1))), 0, 12)) {}

    std::string operator()(double v) const {
        char s[64];
        std::snprintf(s, sizeof s, "%.*f", decimals_, v);
        std::string out = s;
        if (out.find('.') != std::string::npos) {
            while (out.back() == '0') out.pop_back();
            if (out.back() == '.') out.pop_back();
        }
        if (out == "-0") out = "0";
        return out;
    }

private:
    int decimals_;
};

inline std::string svg_header(int width, int height, const std::string& view_box) {
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) + "\" height=\"" +
           std::to_string(height) + "\" viewBox=\"" + view_box + "\">\n";
}

}  // namespace tessera::render
