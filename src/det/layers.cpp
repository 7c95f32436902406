#include "det/layers.hpp"

#include <cmath>

namespace tessera::det {

LayerAxes layer_axes(const Box& in_box, int dim, double radius) {
    LayerAxes layer;
    int thin_count = 0;
    for (int k = 0; k < dim; ++k) {
        layer.thin[k] = in_box.hi[k] - in_box.lo[k] < 2.0 * radius;
        thin_count += layer.thin[k];
    }
    if (thin_count == dim) return {};  // a tiny exemplar, not a layer: the usual windows
    layer.any = thin_count > 0;
    return layer;
}

// Slides a cell's window centre along each thin axis (turned by the local frame) to the
// middle of the nearest run of domain inside that line, within +-patch: the layer then
// lands in the domain (a shell under a surface) instead of wherever the cell's centre is.
Vec3 onto_layer(const Vec3& center, const Quat& rotation, const LayerAxes& layer, const Box& in_box,
                const Domain& domain, double patch, int dim) {
    Vec3 out = center;
    for (int k = 0; k < dim; ++k) {
        if (!layer.thin[k]) continue;
        Vec3 axis;
        axis[k] = 1.0;
        const Vec3 dir = rotation.rotate(axis);
        const double step = std::max(0.25 * (in_box.hi[k] - in_box.lo[k]), patch / 64.0);
        const int steps = static_cast<int>(std::ceil(patch / step));  // bounded: <= 64 each way
        // The inside run nearest to t = 0, searched outward.
        int first = 1, last = 0;  // empty
        for (int r = 0; r <= steps && first > last; ++r)
            for (int sign : {1, -1}) {
                const int t = sign * r;
                if (domain.inside(out + dir * (t * step))) {
                    first = last = t;
                    break;
                }
            }
        if (first > last) continue;  // no domain on this line: leave the centre
        while (first - 1 >= -steps && domain.inside(out + dir * ((first - 1) * step))) --first;
        while (last + 1 <= steps && domain.inside(out + dir * ((last + 1) * step))) ++last;
        out = out + dir * (0.5 * (first + last) * step);
    }
    return out;
}

}  // namespace tessera::det
