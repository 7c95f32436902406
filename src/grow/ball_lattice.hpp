// Points of a regular lattice inside the unit disk (2D) or ball (3D), `per_axis` points along
// each axis of the enclosing square (cube): the share of a disk that lies inside a window or a
// region is the share of these points, scaled and moved, that do. Private to growth.
#pragma once

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

}  // namespace tessera::grow
