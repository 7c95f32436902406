// Colours of the preview pictures: a fixed qualitative palette (Tableau 10) so
// that a class keeps its colour across every picture of a run, plus the few
// neutral tones of the frame. Colours are sRGB components in [0, 1].
#pragma once

#include <array>
#include <cstdio>
#include <string>

namespace tessera::render {

struct Rgb {
    float r = 1.0f, g = 1.0f, b = 1.0f;
};

// Tableau 10 (2016 revision): distinguishable, colour-blind tolerant, not garish.
inline constexpr std::array<Rgb, 10> tableau10 = {{
    {0x4e / 255.0f, 0x79 / 255.0f, 0xa7 / 255.0f},  // blue
    {0xf2 / 255.0f, 0x8e / 255.0f, 0x2b / 255.0f},  // orange
    {0xe1 / 255.0f, 0x57 / 255.0f, 0x59 / 255.0f},  // red
    {0x76 / 255.0f, 0xb7 / 255.0f, 0xb2 / 255.0f},  // teal
    {0x59 / 255.0f, 0xa1 / 255.0f, 0x4f / 255.0f},  // green
    {0xed / 255.0f, 0xc9 / 255.0f, 0x48 / 255.0f},  // yellow
    {0xb0 / 255.0f, 0x7a / 255.0f, 0xa1 / 255.0f},  // purple
    {0xff / 255.0f, 0x9d / 255.0f, 0xa7 / 255.0f},  // pink
    {0x9c / 255.0f, 0x75 / 255.0f, 0x5f / 255.0f},  // brown
    {0xba / 255.0f, 0xb0 / 255.0f, 0xac / 255.0f},  // grey
}};

inline constexpr Rgb white{1.0f, 1.0f, 1.0f};
inline constexpr Rgb outline_grey{0.62f, 0.62f, 0.62f};  // domain outline
inline constexpr Rgb grid_line{0.70f, 0.78f, 0.90f};     // a world's tile borders (light blue), behind the elements

// Colour of class (element type) `type`; the palette repeats after 10 classes.
inline Rgb class_color(int type) { return tableau10[static_cast<size_t>(type < 0 ? 0 : type) % tableau10.size()]; }

// The colour scaled toward black (factor < 1): rims, ticks, sample dots.
inline Rgb darker(Rgb c, float factor) { return {c.r * factor, c.g * factor, c.b * factor}; }
// The colour mixed toward white by t in [0, 1]: highlights, depth fog.
inline Rgb toward_white(Rgb c, float t) { return {c.r + (1 - c.r) * t, c.g + (1 - c.g) * t, c.b + (1 - c.b) * t}; }

inline int to_byte(float v) {
    const float c = v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v);
    return static_cast<int>(c * 255.0f + 0.5f);
}

// "#rrggbb" for SVG.
inline std::string to_hex(Rgb c) {
    char s[8];
    std::snprintf(s, sizeof s, "#%02x%02x%02x", to_byte(c.r), to_byte(c.g), to_byte(c.b));
    return s;
}

}  // namespace tessera::render
