// Points of a regular lattice inside the unit disk (2D) or ball (3D), `per_axis` points along
// each axis of the enclosing square (cube): the share of a disk that lies inside a window or a
// region is the share of these points, scaled and moved, that do. Private to growth.
#pragma once

#include <cmath>
#include <vector>

#include "tessera/vec.hpp"

namespace tessera::grow {

inline std::vector<Vec3> unit_ball_lattice(int dimension, int per_axis) {
    std::vector<Vec3> points;
    const int nz = dimension == 3 ? per_axis : 1;
    for (int i = 0; i < per_axis; ++i)
        for (int j = 0; j < per_axis; ++j)
            for (int k = 0; k < nz; ++k) {
                const Vec3 p{(i + 0.5) / per_axis * 2 - 1, (j + 0.5) / per_axis * 2 - 1,
                             dimension == 3 ? (k + 0.5) / per_axis * 2 - 1 : 0.0};
                if (dot(p, p) <= 1.0) points.push_back(p);
            }
    return points;
}

// Unit directions probed around an element: 12 in 2D (30 degrees apart), the 26 of the
// cube's neighbours in 3D.
inline std::vector<Vec3> probe_directions(int dimension) {
    std::vector<Vec3> dirs;
    if (dimension == 2) {
        for (int k = 0; k < 12; ++k) dirs.push_back({std::cos(k * M_PI / 6), std::sin(k * M_PI / 6), 0.0});
        return dirs;
    }
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y)
            for (int z = -1; z <= 1; ++z)
                if (x || y || z)
                    dirs.push_back(Vec3{double(x), double(y), double(z)} *
                                   (1.0 / std::sqrt(double(x * x + y * y + z * z))));
    return dirs;
}

}  // namespace tessera::grow
