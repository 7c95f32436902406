// Glyphs of single-sample elements in 2D pictures (ElementGlyph): shapes made of disks and
// round-capped segments, in the element's frame (x = heading, units of its radius), so that
// the PNG raster (add_disk / add_capsule) and the SVG (circles and round-capped lines) draw
// the same silhouette from one description.
#pragma once

#include <span>

namespace tessera::render {

struct GlyphPart {
    double ax, ay, bx, by;  // a segment from a to b; a disk when a == b
    double radius;          // half-width of the segment, radius of the disk
};

// A fish heading +x, about three radii long and one wide (a fish is longer than a disk of
// the same spacing is wide): a body tapered towards the tail, a forked tail.
inline std::span<const GlyphPart> fish_glyph() {
    static constexpr GlyphPart parts[] = {
        {0.78, 0.0, 0.45, 0.0, 0.26},     // snout
        {0.40, 0.0, -0.20, 0.0, 0.40},    // head and belly
        {-0.20, 0.0, -0.62, 0.0, 0.25},   // the body narrowing
        {-0.62, 0.0, -0.85, 0.0, 0.13},   // the tail's stem
        {-0.88, 0.0, -1.28, 0.44, 0.09},  // the tail fin, a fan of strokes
        {-0.88, 0.0, -1.22, 0.20, 0.12},
        {-0.88, 0.0, -1.22, -0.20, 0.12},
        {-0.88, 0.0, -1.28, -0.44, 0.09},
    };
    return parts;
}

}  // namespace tessera::render
