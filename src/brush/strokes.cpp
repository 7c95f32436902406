// Brush stroke geometry (brush/strokes.hpp).
#include "brush/strokes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tessera/error.hpp"

namespace tessera::brush {

namespace {

// The closest point of segment [a, b] to p, as the parameter t in [0, 1].
double segment_parameter(const Vec3& a, const Vec3& b, const Vec3& p) {
    const Vec3 ab = b - a;
    const double len2 = squared_norm(ab);
    if (len2 <= 0.0) return 0.0;
    return std::clamp(dot(p - a, ab) / len2, 0.0, 1.0);
}

}  // namespace

StrokePoint closest_stroke_point(const std::vector<Stroke>& strokes, const Vec3& p) {
    StrokePoint best{std::numeric_limits<double>::infinity(), Vec3{1, 0, 0}};
    double best2 = best.distance;
    for (const Stroke& s : strokes)
        for (size_t i = 0; i + 1 < s.points.size(); ++i) {
            const Vec3 a = s.points[i], b = s.points[i + 1];
            const Vec3 ab = b - a;
            const double len = norm(ab);
            if (len <= 0.0) continue;
            const Vec3 q = a + ab * segment_parameter(a, b, p);
            const double d2 = squared_norm(p - q);
            if (d2 < best2) {
                best2 = d2;
                best.tangent = ab / len;
            }
        }
    if (std::isfinite(best2)) best.distance = std::sqrt(best2);
    return best;
}

double distance_to_stroke(const Stroke& stroke, const Vec3& p) {
    if (stroke.points.size() == 1) return norm(p - stroke.points[0]);
    double best2 = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i + 1 < stroke.points.size(); ++i) {
        const Vec3 a = stroke.points[i], b = stroke.points[i + 1];
        best2 = std::min(best2, squared_norm(p - (a + (b - a) * segment_parameter(a, b, p))));
    }
    return std::sqrt(best2);
}

Domain stroke_band(const Domain& canvas, const Stroke& stroke, double half_width) {
    const int dim = canvas.dimension();
    const Vec3 size = canvas.bounds().size();
    const double volume = dim == 2 ? size.x * size.y : size.x * size.y * size.z;
    const double limit_cell = std::pow(volume / 8.0e6, 1.0 / dim);  // keep well under 2^24 cells
    const double cell = std::max(0.2 * half_width, limit_cell);
    return Domain::region(
        canvas, [&](const Vec3& p) { return distance_to_stroke(stroke, p) <= half_width; }, cell, "stroke band");
}

void check_stroke(const Stroke& stroke, int dimension, int min_points, const std::string& where) {
    if (static_cast<int>(stroke.points.size()) < min_points)
        throw Error(ErrorKind::input, where + ": a stroke needs at least " + std::to_string(min_points) +
                                          " point" + (min_points == 1 ? "" : "s") + ", got " +
                                          std::to_string(stroke.points.size()));
    for (const Vec3& p : stroke.points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw Error(ErrorKind::input, where + ": a stroke point is not finite");
        if (dimension == 2 && p.z != 0.0) throw Error(ErrorKind::input, where + ": a 2D stroke point has z != 0");
    }
    if (!(stroke.width >= 0.0) || !std::isfinite(stroke.width))
        throw Error(ErrorKind::input, where + ": the stroke width must be a number >= 0");
}

}  // namespace tessera::brush
