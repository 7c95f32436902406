// dynamic/probe_lattice.cpp — probes over a box, and disks stamped onto them.
#include "dynamic/probe_lattice.hpp"

#include <algorithm>
#include <cmath>

namespace tessera::dynamic {

ProbeLattice::ProbeLattice(const Domain& domain, double step, bool periodic)
    : lo_(domain.bounds().lo), dimension_(domain.dimension()), periodic_(periodic) {
    const Box& b = domain.bounds();
    for (int k = 0; k < dimension_; ++k) {
        const double extent = b.hi[k] - b.lo[k];
        count_[k] = std::max(1, static_cast<int>(std::ceil(extent / step)));
        step_[k] = extent / count_[k];
    }
    inside_.resize(static_cast<size_t>(count_[0]) * count_[1] * count_[2]);
    for (int i = 0; i < size(); ++i) inside_[i] = domain.inside(point(i));
    clear_stamps();
}

Vec3 ProbeLattice::point(int i) const {
    const int x = i % count_[0], y = (i / count_[0]) % count_[1], z = i / (count_[0] * count_[1]);
    Vec3 p{lo_.x + (x + 0.5) * step_[0], lo_.y + (y + 0.5) * step_[1], 0.0};
    if (dimension_ == 3) p.z = lo_.z + (z + 0.5) * step_[2];
    return p;
}

// Lattice index i along `axis`, folded across the faces when periodic; invalid outside.
int ProbeLattice::index_along(int axis, int i, bool& valid) const {
    const int n = count_[axis];
    if (periodic_) return ((i % n) + n) % n;
    valid = valid && i >= 0 && i < n;
    return i;
}

void ProbeLattice::stamp(const Vec3& p, double radius) {
    int from[3] = {0, 0, 0}, to[3] = {0, 0, 0};
    for (int k = 0; k < dimension_; ++k) {
        from[k] = static_cast<int>(std::ceil((p[k] - radius - lo_[k]) / step_[k] - 0.5));
        to[k] = static_cast<int>(std::floor((p[k] + radius - lo_[k]) / step_[k] - 0.5));
    }
    const double r2 = radius * radius;
    for (int z = from[2]; z <= to[2]; ++z) {
        const double dz = dimension_ == 3 ? lo_.z + (z + 0.5) * step_[2] - p.z : 0.0;
        for (int y = from[1]; y <= to[1]; ++y) {
            const double dy = lo_.y + (y + 0.5) * step_[1] - p.y;
            const double rest = r2 - dy * dy - dz * dz;
            if (rest < 0.0) continue;
            bool valid = true;
            const int zi = dimension_ == 3 ? index_along(2, z, valid) : 0, yi = index_along(1, y, valid);
            if (!valid) continue;
            // The run of probes along x within the disk on this row.
            const double half = std::sqrt(rest);
            const int x0 = std::max(from[0], static_cast<int>(std::ceil((p.x - half - lo_.x) / step_[0] - 0.5)));
            const int x1 = std::min(to[0], static_cast<int>(std::floor((p.x + half - lo_.x) / step_[0] - 0.5)));
            const size_t row = (static_cast<size_t>(zi) * count_[1] + yi) * count_[0];
            for (int x = x0; x <= x1; ++x) {
                bool ok = true;
                const int xi = index_along(0, x, ok);
                if (ok) covered_[row + xi] = 1;
            }
        }
    }
}

}  // namespace tessera::dynamic
