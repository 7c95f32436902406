// core/domain_voxels.cpp — the grid shape shared by image masks, meshes and shells:
// (bi/tri)linear occupancy, and the two distance transforms that make
// closest_inside and distance_to_boundary fast (both are called per sample per
// iteration): the nearest inside cell of every cell, and every cell's distance to
// the nearest outside cell. Both come from one exact separable transform.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/domain_shape.hpp"
#include "core/parallel.hpp"

namespace tessera {

void distance_transform(const std::vector<uint8_t>& target, const int n[3], const Vec3& spacing, int threads,
                        std::vector<double>& sq, std::vector<int32_t>* feature) {
    const double inf = std::numeric_limits<double>::infinity();
    const int64_t total = int64_t(n[0]) * n[1] * n[2];
    sq.assign(total, inf);
    std::vector<int32_t> feat(total, -1);
    for (int64_t v = 0; v < total; ++v)
        if (target[v]) sq[v] = 0.0, feat[v] = static_cast<int32_t>(v);
    const int64_t stride[3] = {1, n[0], int64_t(n[0]) * n[1]};
    for (int axis = 0; axis < 3; ++axis) {
        const int len = n[axis];
        if (len == 1) continue;
        const int b = (axis + 1) % 3, c = (axis + 2) % 3;
        const double s2 = spacing[axis] * spacing[axis];
        core::parallel_for(n[b] * n[c], threads, [&](int begin, int end, int) {
            std::vector<double> f(len), out_d(len), z(len + 1);
            std::vector<int32_t> f_feat(len), out_f(len);
            std::vector<int> v(len);
            for (int line = begin; line < end; ++line) {
                const int64_t start = (line % n[b]) * stride[b] + (line / n[b]) * stride[c];
                for (int q = 0; q < len; ++q) f[q] = sq[start + q * stride[axis]], f_feat[q] = feat[start + q * stride[axis]];
                // Lower envelope of the parabolas s2 (q - p)^2 + f(p) over finite f(p).
                int k = -1;
                for (int q = 0; q < len; ++q) {
                    if (f[q] == inf) continue;
                    while (k >= 0) {
                        const int p = v[k];
                        const double s = ((f[q] + s2 * q * q) - (f[p] + s2 * p * p)) / (2.0 * s2 * (q - p));
                        if (s <= z[k]) { --k; continue; }
                        ++k, v[k] = q, z[k] = s, z[k + 1] = inf;
                        break;
                    }
                    if (k < 0) k = 0, v[0] = q, z[0] = -inf, z[1] = inf;
                }
                if (k < 0) continue;  // no finite value on this line
                int j = 0;
                for (int q = 0; q < len; ++q) {
                    while (z[j + 1] < q) ++j;
                    const double dq = q - v[j];
                    out_d[q] = s2 * dq * dq + f[v[j]];
                    out_f[q] = f_feat[v[j]];
                }
                for (int q = 0; q < len; ++q) sq[start + q * stride[axis]] = out_d[q], feat[start + q * stride[axis]] = out_f[q];
            }
        });
    }
    if (feature) *feature = std::move(feat);
}

Vec3 VoxelShape::centre(int64_t v) const {
    const int i = static_cast<int>(v % n[0]), j = static_cast<int>(v / n[0] % n[1]), k = static_cast<int>(v / (int64_t(n[0]) * n[1]));
    return {first.x + i * spacing.x, first.y + j * spacing.y, dimension == 3 ? first.z + k * spacing.z : 0.0};
}

bool VoxelShape::in_box(const Vec3& p) const {
    return p.x >= bounds.lo.x && p.x <= bounds.hi.x && p.y >= bounds.lo.y && p.y <= bounds.hi.y &&
           (dimension == 2 || (p.z >= bounds.lo.z && p.z <= bounds.hi.z));
}

// (Bi/tri)linear interpolation between cell centres; beyond the outermost centres
// the border value extends to the box.
double VoxelShape::interpolate(const Vec3& p) const {
    // Hot in the search's Eq. 6 term (one call per neighbour per candidate): explicit 2D and
    // 3D paths with no per-corner branching. A degenerate axis (one cell) has weight 0 on
    // its second corner, which is clamped to the same cell.
    int base[3] = {0, 0, 0}, step[3] = {0, 0, 0};
    double frac[3] = {0.0, 0.0, 0.0};
    for (int k = 0; k < dimension; ++k) {
        const double u = std::clamp((p[k] - first[k]) / spacing[k], 0.0, double(n[k] - 1));
        base[k] = std::min(static_cast<int>(u), std::max(0, n[k] - 2));
        frac[k] = n[k] > 1 ? u - base[k] : 0.0;
        step[k] = n[k] > 1 ? 1 : 0;
    }
    const int64_t sx = step[0], sy = step[1] * int64_t(n[0]), sz = step[2] * int64_t(n[0]) * n[1];
    const float* v = values.data() + index(base[0], base[1], base[2]);
    const double fx = frac[0], fy = frac[1];
    const double c00 = v[0] + fx * (v[sx] - v[0]), c10 = v[sy] + fx * (v[sy + sx] - v[sy]);
    const double c0 = c00 + fy * (c10 - c00);
    if (dimension == 2) return c0;
    const float* w = v + sz;
    const double d00 = w[0] + fx * (w[sx] - w[0]), d10 = w[sy] + fx * (w[sy + sx] - w[sy]);
    const double c1 = d00 + fy * (d10 - d00);
    return c0 + frac[2] * (c1 - c0);
}

bool VoxelShape::inside(const Vec3& p) const { return in_box(p) && interpolate(p) >= threshold; }

double VoxelShape::occupancy(const Vec3& p) const { return in_box(p) ? std::clamp(interpolate(p), 0.0, 1.0) : 0.0; }

double VoxelShape::measure() const {
    double cell = 1.0;
    for (int k = 0; k < dimension; ++k) cell *= spacing[k];
    return inside_cells_ * cell;
}

int64_t VoxelShape::nearest_cell(const Vec3& p) const {
    int idx[3] = {0, 0, 0};
    for (int k = 0; k < dimension; ++k)
        idx[k] = std::clamp(static_cast<int>(std::lround((p[k] - first[k]) / spacing[k])), 0, n[k] - 1);
    return index(idx[0], idx[1], idx[2]);
}

Vec3 VoxelShape::closest_inside(const Vec3& p) const {
    if (inside(p)) return p;
    // The nearest inside cell centre of the cell nearest to p is inside; bisect the
    // segment from p towards it to land just inside the boundary.
    Vec3 in = centre(nearest_inside_[nearest_cell(p)]);
    Vec3 out = p;
    for (int it = 0; it < 30; ++it) {
        const Vec3 mid = (in + out) * 0.5;
        (inside(mid) ? in : out) = mid;
    }
    return in;
}

double VoxelShape::distance_to_boundary(const Vec3& p) const {
    const int64_t v = nearest_cell(p);
    if (!inside(p)) return -norm(centre(nearest_inside_[v]) - p);
    // The boundary {c = threshold} lies in cells with a corner below the threshold,
    // so it is at least (distance to the nearest outside centre) - (a cell diagonal)
    // away; that centre is at least outside_distance(v) - |p - centre(v)| away.
    double diagonal = 0.0;
    for (int k = 0; k < dimension; ++k) diagonal += spacing[k] * spacing[k];
    diagonal = std::sqrt(diagonal);
    double d = static_cast<double>(outside_distance_[v]) * (1.0 - 1e-6) - norm(p - centre(v)) - diagonal;
    for (int k = 0; k < dimension; ++k) d = std::min({d, p[k] - bounds.lo[k], bounds.hi[k] - p[k]});
    return std::max(0.0, d);
}

int64_t VoxelShape::finish(int threads) {
    const int64_t total = cell_count();
    std::vector<uint8_t> in(total), out(total);
    inside_cells_ = 0;
    for (int64_t v = 0; v < total; ++v) {
        in[v] = values[v] >= threshold;
        out[v] = !in[v];
        inside_cells_ += in[v];
    }
    if (inside_cells_ == 0) return 0;
    std::vector<double> sq;
    distance_transform(in, n, spacing, threads, sq, &nearest_inside_);
    distance_transform(out, n, spacing, threads, sq, nullptr);
    outside_distance_.resize(total);
    for (int64_t v = 0; v < total; ++v)
        outside_distance_[v] = std::isinf(sq[v]) ? std::numeric_limits<float>::max() : static_cast<float>(std::sqrt(sq[v]));
    return inside_cells_;
}

}  // namespace tessera
