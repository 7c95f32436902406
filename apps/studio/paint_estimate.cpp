// apps/studio/paint_estimate.cpp — elements a paint stroke will make (paint_estimate.hpp).
#include "apps/studio/paint_estimate.hpp"

#include <cmath>

namespace tessera_studio {

double exemplar_density(const tessera::Exemplar& exemplar) {
    const double measure = exemplar.domain.measure();
    return measure > 0.0 ? static_cast<double>(exemplar.elements.size()) / measure : 0.0;
}

double expected_paint_elements(const tessera::Stroke& stroke, double density, int dimension,
                               double default_width_spacings) {
    if (density <= 0.0) return 0.0;
    double length = 0.0;
    for (size_t k = 1; k < stroke.points.size(); ++k) length += norm(stroke.points[k] - stroke.points[k - 1]);
    const double spacing = std::pow(density, -1.0 / dimension);
    const double width = stroke.width > 0.0 ? stroke.width : default_width_spacings * spacing;
    // The band has round caps: a point stroke still covers a disc (ball).
    const double cross = dimension == 2 ? width : M_PI * 0.25 * width * width;
    const double cap = dimension == 2 ? M_PI * 0.25 * width * width : M_PI / 6.0 * width * width * width;
    return density * (length * cross + cap);
}

}  // namespace tessera_studio
