// core/domain_overlap.cpp — the set covariance g(d) = |W ∩ (W + d)| of a shaped
// domain, used by the translation edge correction of pair correlation estimates.
// No closed form exists for polygons with holes, masks or meshes, so the shape is
// rasterized once (256 cells along its longest side in 2D, 48 in 3D; cell centres
// tested with inside()), g is counted exactly for the raster at every shift that is
// a multiple of `stride` cells (rows as bit sets: AND + popcount), and queries
// interpolate (bi/tri)linearly. The error is that of the raster at the boundary
// (about a cell times the perimeter) plus linear interpolation over `stride` cells.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "core/domain_shape.hpp"
#include "core/parallel.hpp"

namespace tessera {
namespace {

// 64 bits of a row starting at bit `start` (bits outside the row are 0).
uint64_t bits_at(const uint64_t* row, int words, long start) {
    const long w = start >= 0 ? start / 64 : -((-start + 63) / 64);
    const int off = static_cast<int>(start - w * 64);
    const uint64_t lo = (w >= 0 && w < words) ? row[w] : 0;
    const uint64_t hi = (w + 1 >= 0 && w + 1 < words) ? row[w + 1] : 0;
    return off == 0 ? lo : (lo >> off) | (hi << (64 - off));
}

}  // namespace

void DomainShape::prepare_overlap(int threads) const {
    std::call_once(overlap_once_, [this, threads] { build_overlap_table(threads); });
}

void DomainShape::build_overlap_table(int requested_threads) const {
    const int cells = dimension == 2 ? 256 : 48;
    const Vec3 size = bounds.size();
    double longest = 0.0;
    for (int k = 0; k < dimension; ++k) longest = std::max(longest, size[k]);
    const double h = longest / cells;
    int n[3] = {1, 1, 1};
    for (int k = 0; k < dimension; ++k) n[k] = std::max(1, static_cast<int>(std::ceil(size[k] / h - 1e-9)));
    const int words = (n[0] + 63) / 64;
    const int rows = n[1] * n[2];
    std::vector<uint64_t> bits(static_cast<size_t>(rows) * words, 0);
    const int threads = core::resolve_threads(requested_threads);
    core::parallel_for(rows, threads, [&](int begin, int end, int) {
        for (int r = begin; r < end; ++r) {
            const int j = r % n[1], k = r / n[1];
            for (int i = 0; i < n[0]; ++i) {
                const Vec3 p{bounds.lo.x + (i + 0.5) * h, bounds.lo.y + (j + 0.5) * h,
                             dimension == 3 ? bounds.lo.z + (k + 0.5) * h : 0.0};
                if (inside(p)) bits[static_cast<size_t>(r) * words + i / 64] |= uint64_t(1) << (i % 64);
            }
        }
    });
    OverlapTable& t = overlap_;
    t.cell = h;
    t.stride = 2;
    int m[3] = {1, 1, 1};
    for (int k = 0; k < 3; ++k) {
        t.half[k] = n[k] > 1 ? (n[k] - 1 + t.stride - 1) / t.stride + 1 : 0;
        m[k] = 2 * t.half[k] + 1;
    }
    t.values.assign(static_cast<size_t>(m[0]) * m[1] * m[2], 0.0);
    const double cell_measure = std::pow(h, dimension);
    core::parallel_for(static_cast<int>(t.values.size()), threads, [&](int begin, int end, int) {
        for (int e = begin; e < end; ++e) {
            const int sx = (e % m[0] - t.half[0]) * t.stride;
            const int sy = (e / m[0] % m[1] - t.half[1]) * t.stride;
            const int sz = (e / (m[0] * m[1]) - t.half[2]) * t.stride;
            long count = 0;
            // cells c with c in W and c - s in W: rows (j, k) against rows (j - sy, k - sz).
            for (int k = std::max(0, sz); k < std::min(n[2], n[2] + sz); ++k)
                for (int j = std::max(0, sy); j < std::min(n[1], n[1] + sy); ++j) {
                    const uint64_t* a = &bits[static_cast<size_t>(j + n[1] * k) * words];
                    const uint64_t* b = &bits[static_cast<size_t>((j - sy) + n[1] * (k - sz)) * words];
                    for (int w = 0; w < words; ++w)
                        if (a[w]) count += std::popcount(a[w] & bits_at(b, words, long(w) * 64 - sx));
                }
            t.values[e] = count * cell_measure;
        }
    });
}

double DomainShape::translated_overlap(const Vec3& d) const {
    prepare_overlap(0);  // all threads unless a method prepared it with its own count
    const OverlapTable& t = overlap_;
    int m[3], base[3];
    double frac[3];
    for (int k = 0; k < 3; ++k) {
        m[k] = 2 * t.half[k] + 1;
        const double u = (k < dimension ? d[k] : 0.0) / (t.cell * t.stride) + t.half[k];
        if (!(u >= 0.0) || u > m[k] - 1) return 0.0;  // beyond the table: no overlap
        base[k] = std::min(static_cast<int>(u), std::max(0, m[k] - 2));
        frac[k] = m[k] > 1 ? u - base[k] : 0.0;
    }
    double sum = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        double w = 1.0;
        int idx[3];
        bool valid = true;
        for (int k = 0; k < 3; ++k) {
            const int bit = (corner >> k) & 1;
            if (m[k] == 1 && bit) valid = false;
            idx[k] = base[k] + bit;
            w *= bit ? frac[k] : 1.0 - frac[k];
        }
        if (!valid || w == 0.0) continue;
        sum += w * t.values[idx[0] + static_cast<size_t>(m[0]) * (idx[1] + static_cast<size_t>(m[1]) * idx[2])];
    }
    return sum;
}

}  // namespace tessera
