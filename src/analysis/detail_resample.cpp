// Resampling an element's detail offsets onto another element's samples (detail_resample.hpp).
#include "analysis/detail_resample.hpp"

#include <algorithm>

namespace tessera::analysis {

namespace {

// Where index i of n falls on an axis of m indices, end to end: its cell and the weight of
// the cell's upper index.
struct AxisPoint {
    int lower = 0;
    double t = 0.0;
};

AxisPoint axis_point(int i, int n, int m) {
    if (m == 1 || n == 1) return {};
    const double x = static_cast<double>(i) * (m - 1) / (n - 1);
    const int lower = std::min(static_cast<int>(x), m - 2);
    return {lower, x - lower};
}

// Bilinear interpolation of the grid `first` (rows x columns) at (row point, column point).
Vec3 bilinear(const Vec3* first, const Layout& l, const AxisPoint& r, const AxisPoint& c) {
    const int r1 = std::min(r.lower + 1, l.rows - 1), c1 = std::min(c.lower + 1, l.columns - 1);
    const Vec3 low =
        first[r.lower * l.columns + c.lower] * (1.0 - c.t) + first[r.lower * l.columns + c1] * c.t;
    const Vec3 high = first[r1 * l.columns + c.lower] * (1.0 - c.t) + first[r1 * l.columns + c1] * c.t;
    return low * (1.0 - r.t) + high * r.t;
}

}  // namespace

void resampled_offsets(const Animation& detail, int from, const Layout& from_layout, int frame,
                       const Layout& to, Vec3* out) {
    const Element& e = detail.structure.elements[from];
    const Vec3* first = &detail.at(frame, e.first_sample);
    if (to.kind == Kind::particle) {
        for (int k = 0; k < to.columns; ++k) out[k] = first[k % e.sample_count];
        return;
    }
    for (int r = 0; r < to.rows; ++r) {
        const AxisPoint rp = axis_point(r, to.rows, from_layout.rows);
        for (int c = 0; c < to.columns; ++c)
            out[r * to.columns + c] =
                bilinear(first, from_layout, rp, axis_point(c, to.columns, from_layout.columns));
    }
}

}  // namespace tessera::analysis
