// Colours of the classes: a type's own "color", else its name when that is a colour
// name, else the palette (tessera/render.hpp, type_colors).
#include <algorithm>
#include <cctype>
#include <cmath>

#include "render/class_colors.hpp"
#include "render/color_names.hpp"
#include "tessera/error.hpp"

namespace tessera {
namespace {

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
}

// "#rrggbb" or "#rgb" (each digit doubled, as in CSS).
std::optional<Color> parse_hex(const std::string& text) {
    if (text.size() != 7 && text.size() != 4) return std::nullopt;
    std::uint8_t parts[3];
    const bool short_form = text.size() == 4;
    for (int k = 0; k < 3; ++k) {
        const int hi = hex_digit(text[short_form ? 1 + k : 1 + 2 * k]);
        const int lo = hex_digit(text[short_form ? 1 + k : 2 + 2 * k]);
        if (hi < 0 || lo < 0) return std::nullopt;
        parts[k] = static_cast<std::uint8_t>(16 * hi + lo);
    }
    return Color{parts[0], parts[1], parts[2]};
}

Color from_rgb24(std::uint32_t rgb) {
    return {static_cast<std::uint8_t>(rgb >> 16), static_cast<std::uint8_t>(rgb >> 8), static_cast<std::uint8_t>(rgb)};
}

Color from_rgb(render::Rgb c) {
    return {static_cast<std::uint8_t>(render::to_byte(c.r)), static_cast<std::uint8_t>(render::to_byte(c.g)),
            static_cast<std::uint8_t>(render::to_byte(c.b))};
}

}  // namespace

std::optional<Color> parse_color(const std::string& text) {
    if (!text.empty() && text[0] == '#') return parse_hex(text);
    if (const auto rgb = render::named_color(text)) return from_rgb24(*rgb);
    return std::nullopt;
}

std::vector<Color> type_colors(const Exemplar& data) {
    const size_t n = data.types.size();
    std::vector<std::optional<Color>> chosen(n);
    for (size_t t = 0; t < n; ++t) {
        const ElementType& type = data.types[t];
        if (!type.color.empty()) {
            chosen[t] = parse_color(type.color);
            if (!chosen[t])
                throw Error(ErrorKind::input, "type '" + type.name + "': color '" + type.color +
                                                  "' is neither #rrggbb nor a colour name");
        } else if (const auto rgb = render::named_color(type.name)) {
            chosen[t] = from_rgb24(*rgb);
        }
    }
    // The other types take the palette in order, skipping entries that look like a
    // colour some type chose; when every entry does (or after all ten), it repeats.
    std::vector<size_t> palette;
    for (size_t k = 0; k < render::tableau10.size(); ++k) {
        const bool taken = std::any_of(chosen.begin(), chosen.end(), [&](const std::optional<Color>& c) {
            return c && render::looks_alike(render::to_rgb(*c), render::tableau10[k]);
        });
        if (!taken) palette.push_back(k);
    }
    if (palette.empty())
        for (size_t k = 0; k < render::tableau10.size(); ++k) palette.push_back(k);
    std::vector<Color> colors(n);
    size_t next = 0;
    for (size_t t = 0; t < n; ++t)
        colors[t] = chosen[t] ? *chosen[t] : from_rgb(render::tableau10[palette[next++ % palette.size()]]);
    return colors;
}

namespace render {

std::vector<Rgb> class_colors(const Exemplar& data) {
    std::vector<Rgb> out;
    for (const Color& c : type_colors(data)) out.push_back(to_rgb(c));
    return out;
}

bool looks_alike(Rgb a, Rgb b) {
    // Hue, saturation and value as HSV has them.
    struct Hsv {
        double h, s, v;
    };
    const auto hsv = [](Rgb c) {
        const double hi = std::max({c.r, c.g, c.b}), lo = std::min({c.r, c.g, c.b}), d = hi - lo;
        double h = 0.0;
        if (d > 0.0) {
            if (hi == c.r) h = 60.0 * std::fmod((c.g - c.b) / d + 6.0, 6.0);
            else if (hi == c.g) h = 60.0 * ((c.b - c.r) / d + 2.0);
            else h = 60.0 * ((c.r - c.g) / d + 4.0);
        }
        return Hsv{h, hi > 0.0 ? d / hi : 0.0, hi};
    };
    const Hsv p = hsv(a), q = hsv(b);
    constexpr double grey = 0.25;  // saturation below which a colour reads as a grey
    if (p.s < grey && q.s < grey) return std::abs(p.v - q.v) < 0.25;
    if (p.s < grey || q.s < grey) return false;
    const double dh = std::abs(p.h - q.h);
    return std::min(dh, 360.0 - dh) < 30.0;
}

}  // namespace render
}  // namespace tessera
