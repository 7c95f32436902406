// MeshRaster: half-space rasterization with integer edge functions (mesh_raster.hpp).
#include "render/mesh_raster.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace tessera::render {
namespace {

using i64 = std::int64_t;

constexpr int sub_bits = 8;  // 1/256 pixel: finer than any visible error, small enough for i64
constexpr i64 sub = i64{1} << sub_bits;
constexpr i64 half = sub / 2;  // a pixel centre, in sub-pixel units

// Vertices farther than this outside the picture are clipped geometrically first;
// within it the integer edge functions cannot overflow (|coordinate| < 2^17 pixels
// = 2^25 sub-pixel units, so products stay below 2^52). Large, so clipping stays rare.
constexpr double guard = 65536.0;  // pixels

i64 floor_div(i64 a, i64 b) {
    return a >= 0 ? a / b : -((-a + b - 1) / b);
}
i64 ceil_div(i64 a, i64 b) {
    return -floor_div(-a, b);
}

bool finite(const RasterVertex& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.depth) && std::isfinite(v.nx) &&
           std::isfinite(v.ny) && std::isfinite(v.nz);
}

RasterVertex lerp(const RasterVertex& a, const RasterVertex& b, double t) {
    const float s = static_cast<float>(t);
    return {a.x + (b.x - a.x) * t,    a.y + (b.y - a.y) * t,    a.depth + (b.depth - a.depth) * s,
            a.nx + (b.nx - a.nx) * s, a.ny + (b.ny - a.ny) * s, a.nz + (b.nz - a.nz) * s};
}

// A triangle clipped by four half-planes has at most 7 corners.
using Polygon = std::array<RasterVertex, 8>;

// One Sutherland-Hodgman step: keeps the part of `in` where sign * (coordinate - limit) <= 0.
int clip(const Polygon& in, int n, Polygon& out, bool along_x, double limit, double sign) {
    auto outside = [&](const RasterVertex& v) { return sign * ((along_x ? v.x : v.y) - limit); };
    int m = 0;
    for (int k = 0; k < n; ++k) {
        const RasterVertex& a = in[k];
        const RasterVertex& b = in[(k + 1) % n];
        const double da = outside(a), db = outside(b);
        if (da <= 0.0) out[m++] = a;
        if ((da <= 0.0) != (db <= 0.0)) out[m++] = lerp(a, b, da / (da - db));
    }
    return m;
}

// Top-left rule for an edge with direction (dx, dy) of a triangle whose interior is
// where the edge functions are positive (y down): a top edge is horizontal with the
// interior below, a left edge runs upward. Centres exactly on these edges are inside.
bool top_left(i64 dx, i64 dy) {
    return (dy == 0 && dx > 0) || dy < 0;
}

}  // namespace

MeshRaster::MeshRaster(int width, int height)
    : width_(width),
      height_(height),
      depth_(static_cast<size_t>(width) * height, -std::numeric_limits<float>::infinity()),
      normal_(static_cast<size_t>(width) * height * 3, 0.0f),
      tag_(static_cast<size_t>(width) * height, -1) {}

void MeshRaster::draw_triangle(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c, int tag) {
    if (!finite(a) || !finite(b) || !finite(c)) return;
    const double lo_x = -guard, hi_x = width_ + guard, lo_y = -guard, hi_y = height_ + guard;
    auto inside = [&](const RasterVertex& v) {
        return v.x >= lo_x && v.x <= hi_x && v.y >= lo_y && v.y <= hi_y;
    };
    if (inside(a) && inside(b) && inside(c)) return fill(a, b, c, tag);
    // Rare: a corner far outside the picture. Clip to the guard band, then fan.
    Polygon p{a, b, c}, q;
    int n = 3;
    n = clip(p, n, q, true, lo_x, -1.0);
    n = clip(q, n, p, true, hi_x, 1.0);
    n = clip(p, n, q, false, lo_y, -1.0);
    n = clip(q, n, p, false, hi_y, 1.0);
    for (int k = 1; k + 1 < n; ++k) fill(p[0], p[k], p[k + 1], tag);
}

void MeshRaster::fill(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c, int tag) {
    const RasterVertex* v[3] = {&a, &b, &c};
    i64 x[3], y[3];
    for (int k = 0; k < 3; ++k) x[k] = std::llround(v[k]->x * sub), y[k] = std::llround(v[k]->y * sub);
    i64 area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
    if (area == 0) return;  // degenerate once snapped: covers no pixel centre
    if (area < 0) {         // make the interior the positive side of every edge
        std::swap(v[1], v[2]), std::swap(x[1], x[2]), std::swap(y[1], y[2]);
        area = -area;
    }
    // Pixels whose centres (i * sub + half) fall inside the bounding box, within the picture.
    const i64 min_x = std::min({x[0], x[1], x[2]}), max_x = std::max({x[0], x[1], x[2]});
    const i64 min_y = std::min({y[0], y[1], y[2]}), max_y = std::max({y[0], y[1], y[2]});
    const int i0 = static_cast<int>(std::max<i64>(0, ceil_div(min_x - half, sub)));
    const int i1 = static_cast<int>(std::min<i64>(width_ - 1, floor_div(max_x - half, sub)));
    const int j0 = static_cast<int>(std::max<i64>(0, ceil_div(min_y - half, sub)));
    const int j1 = static_cast<int>(std::min<i64>(height_ - 1, floor_div(max_y - half, sub)));
    if (i0 > i1 || j0 > j1) return;

    // Edge k runs from corner k+1 to corner k+2; its function, divided by the area,
    // is the barycentric weight of corner k. bias = 1 excludes centres exactly on
    // edges that are not top-left.
    i64 row[3], step_x[3], step_y[3], bias[3];
    const i64 px = i0 * sub + half, py = j0 * sub + half;
    for (int k = 0; k < 3; ++k) {
        const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        const i64 dx = x[k2] - x[k1], dy = y[k2] - y[k1];
        row[k] = dx * (py - y[k1]) - dy * (px - x[k1]);
        step_x[k] = -dy * sub;
        step_y[k] = dx * sub;
        bias[k] = top_left(dx, dy) ? 0 : 1;
    }
    // Attributes as planes over the barycentric weights of corners 1 and 2.
    const double inv_area = 1.0 / static_cast<double>(area);
    const RasterVertex& v0 = *v[0];
    const double d0 = v0.depth, dd1 = v[1]->depth - d0, dd2 = v[2]->depth - d0;
    const float n0[3] = {v0.nx, v0.ny, v0.nz};
    const float dn1[3] = {v[1]->nx - v0.nx, v[1]->ny - v0.ny, v[1]->nz - v0.nz};
    const float dn2[3] = {v[2]->nx - v0.nx, v[2]->ny - v0.ny, v[2]->nz - v0.nz};

    for (int j = j0; j <= j1; ++j, row[0] += step_y[0], row[1] += step_y[1], row[2] += step_y[2]) {
        // The row's span, solved per edge from w + t * step_x >= bias (t = column - i0),
        // so long thin triangles do not pay for their whole bounding box.
        i64 t0 = 0, t1 = i1 - i0;
        for (int k = 0; k < 3 && t0 <= t1; ++k) {
            const i64 need = bias[k] - row[k];  // w must grow by this much
            if (step_x[k] > 0)
                t0 = std::max(t0, ceil_div(need, step_x[k]));
            else if (step_x[k] < 0)
                t1 = std::min(t1, floor_div(-need, -step_x[k]));
            else if (need > 0)
                t1 = -1;
        }
        if (t0 > t1) continue;
        i64 w1 = row[1] + t0 * step_x[1], w2 = row[2] + t0 * step_x[2];
        size_t i = static_cast<size_t>(j) * width_ + i0 + t0;
        fragments_ += static_cast<size_t>(t1 - t0 + 1);
        for (i64 t = t0; t <= t1; ++t, ++i, w1 += step_x[1], w2 += step_x[2]) {
            const double l1 = static_cast<double>(w1) * inv_area, l2 = static_cast<double>(w2) * inv_area;
            const float z = static_cast<float>(d0 + l1 * dd1 + l2 * dd2);
            if (!(z > depth_[i])) continue;
            depth_[i] = z;
            const float f1 = static_cast<float>(l1), f2 = static_cast<float>(l2);
            float* n = &normal_[3 * i];
            for (int k = 0; k < 3; ++k) n[k] = n0[k] + f1 * dn1[k] + f2 * dn2[k];
            tag_[i] = tag;
        }
    }
}

}  // namespace tessera::render
