// Colour names (CSS and X11) as 0xRRGGBB values, for class names that are colours and
// for a type's "color" field (tessera/render.hpp, parse_color).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace tessera::render {

// `text` lower-cased without spaces, hyphens and underscores: "Light Blue",
// "light-blue" and "light_blue" all become "lightblue".
std::string normalized_color_name(const std::string& text);

// The colour named `text` (case-insensitive, spaces, hyphens and underscores ignored),
// or nullopt when it names none.
std::optional<std::uint32_t> named_color(const std::string& text);

}  // namespace tessera::render
