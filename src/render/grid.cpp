#include "render/grid.hpp"

#include <cmath>
#include <string>

#include "tessera/error.hpp"

namespace tessera::render {
namespace {

constexpr double max_cells = 4096;

// The multiples of spacing in [lo, hi] (inclusive) or (lo, hi) (exclusive).
std::vector<double> multiples(double lo, double hi, double spacing, bool inclusive) {
    if ((hi - lo) / spacing > max_cells)
        throw Error(ErrorKind::option, "grid: a spacing of " + std::to_string(spacing) + " draws more than 4096 cells");
    std::vector<double> out;
    for (double k = std::ceil(lo / spacing); k * spacing <= hi; k += 1.0) {
        const double v = k * spacing;
        if (inclusive || (v > lo && v < hi)) out.push_back(v);
    }
    return out;
}

}  // namespace

std::vector<std::pair<Vec3, Vec3>> grid_lines(const Box& b, double spacing, int dimension) {
    std::vector<std::pair<Vec3, Vec3>> lines;
    if (!(spacing > 0.0)) return lines;
    const bool on_box = dimension == 3;  // 3D: the cells' edges on the box faces show the tiling
    const int axes = dimension == 3 ? 3 : 2;
    std::vector<std::vector<double>> at(3);
    for (int k = 0; k < axes; ++k) at[k] = multiples(b.lo[k], b.hi[k], spacing, on_box);
    if (dimension == 2) {
        for (double x : at[0]) lines.push_back({{x, b.lo.y, 0.0}, {x, b.hi.y, 0.0}});
        for (double y : at[1]) lines.push_back({{b.lo.x, y, 0.0}, {b.hi.x, y, 0.0}});
        return lines;
    }
    for (int k = 0; k < 3; ++k) {  // lines along axis k through grid points of the other two
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        for (double u : at[i])
            for (double v : at[j]) {
                Vec3 a, c;
                a[i] = c[i] = u, a[j] = c[j] = v;
                a[k] = b.lo[k], c[k] = b.hi[k];
                lines.push_back({a, c});
            }
    }
    return lines;
}

}  // namespace tessera::render
