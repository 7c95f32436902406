// brush/strokes.hpp — geometry of brush strokes: the nearest stroke point and its direction
// (O(p) of Eq. 5), and the band a stroke sweeps on the canvas.
#pragma once

#include <string>
#include <vector>

#include "tessera/brush.hpp"

namespace tessera::brush {

struct StrokePoint {
    double distance = 0.0;  // from the query point; infinity when there is no stroke
    Vec3 tangent;           // unit direction of the stroke there (the way it was drawn)
};

// The closest point of any of the strokes (each of >= 2 points) to p.
StrokePoint closest_stroke_point(const std::vector<Stroke>& strokes, const Vec3& p);
// Distance from p to the polyline (a single point: to that point).
double distance_to_stroke(const Stroke& stroke, const Vec3& p);
// The part of the canvas within half_width of the stroke, on cells of about a fifth of the
// half width (at most 2^24 cells; coarser when the canvas is large).
Domain stroke_band(const Domain& canvas, const Stroke& stroke, double half_width);
// Error(input) naming `where` for a stroke without points, with non-finite points, or with
// fewer than `min_points` points; z must be 0 on a 2D canvas.
void check_stroke(const Stroke& stroke, int dimension, int min_points, const std::string& where);

}  // namespace tessera::brush
