// dynamic sheets as shaded surfaces in the 3D preview (sheet_surface.hpp).
#include "render/sheet_surface.hpp"

#include <algorithm>
#include <cmath>

#include "tessera/animation.hpp"

namespace tessera::render {

namespace {

struct ScreenVertex {
    double x = 0.0, y = 0.0;  // supersampled pixels
    double depth = 0.0;       // larger = nearer
    Vec3 normal;              // view coordinates (x right, y up, z toward the viewer)
};

double edge(const ScreenVertex& a, const ScreenVertex& b, double x, double y) {
    return (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);
}

// Fills the pixels whose centres the triangle covers, nearest surface wins; the normal is
// interpolated, turned toward the viewer (a sheet has two sides) and shaded like a sphere.
void draw_triangle(HiResBuffer& buf, const Frame3D& frame, const ScreenVertex& a, const ScreenVertex& b,
                   const ScreenVertex& c, Rgb color) {
    const double area = edge(a, b, c.x, c.y);
    if (!(std::abs(area) > 1e-12)) return;  // degenerate or not finite
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x, b.x, c.x}))));
    const int x1 = std::min(buf.width - 1, static_cast<int>(std::ceil(std::max({a.x, b.x, c.x}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y, b.y, c.y}))));
    const int y1 = std::min(buf.height - 1, static_cast<int>(std::ceil(std::max({a.y, b.y, c.y}))));
    const double depth_range = std::max(frame.near - frame.far, 1e-300);
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const double px = x + 0.5, py = y + 0.5;
            const double wa = edge(b, c, px, py) / area, wb = edge(c, a, px, py) / area, wc = 1.0 - wa - wb;
            if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
            const double z = wa * a.depth + wb * b.depth + wc * c.depth;
            const size_t i = static_cast<size_t>(y) * buf.width + x;
            if (z <= buf.depth[i]) continue;
            Vec3 n = a.normal * wa + b.normal * wb + c.normal * wc;
            const double length = norm(n);
            n = length > 0.0 ? n / length : Vec3{0.0, 0.0, 1.0};
            if (n.z < 0.0) n = -n;
            buf.depth[i] = static_cast<float>(z);
            buf.color[i] = shade_sphere(color, n, (frame.near - z) / depth_range);
        }
}

// The grid normal at sample (r, c): the cross product of the differences along the rows and
// the columns (one-sided at the border).
Vec3 grid_normal(const Sample* s, int rows, int cols, int r, int c) {
    const auto at = [&](int rr, int cc) { return s[rr * cols + cc].p; };
    const Vec3 along_c = at(r, std::min(c + 1, cols - 1)) - at(r, std::max(c - 1, 0));
    const Vec3 along_r = at(std::min(r + 1, rows - 1), c) - at(std::max(r - 1, 0), c);
    return cross(along_c, along_r);
}

}  // namespace

bool is_sheet(const Exemplar& data, const Element& e) {
    const ElementType& type = data.types[e.type];
    return effective_topology(data, e.type) == ElementTopology::sheet && type.sheet_columns >= 2 &&
           e.sample_count >= 2 * type.sheet_columns && e.sample_count % type.sheet_columns == 0;
}

void draw_sheets(HiResBuffer& buf, const Exemplar& data, const View3D& view, const Frame3D& frame, double ss,
                 const std::vector<Rgb>& colors) {
    std::vector<ScreenVertex> grid;
    for (const Element& e : data.elements) {
        if (!is_sheet(data, e)) continue;
        const int cols = data.types[e.type].sheet_columns, rows = e.sample_count / cols;
        const Sample* s = &data.samples[e.first_sample];
        grid.resize(e.sample_count);
        for (int r = 0; r < rows; ++r)
            for (int c = 0; c < cols; ++c) {
                const Vec3 p = s[r * cols + c].p, n = grid_normal(s, rows, cols, r, c);
                grid[r * cols + c] = {frame.px(view, p) * ss, frame.py(view, p) * ss, view.depth(p),
                                      {dot(n, view.right), dot(n, view.up), dot(n, view.toward)}};
            }
        const Rgb color = colors[e.type];
        for (int r = 0; r + 1 < rows; ++r)
            for (int c = 0; c + 1 < cols; ++c) {
                const ScreenVertex &a = grid[r * cols + c], &b = grid[r * cols + c + 1];
                const ScreenVertex &d = grid[(r + 1) * cols + c], &e2 = grid[(r + 1) * cols + c + 1];
                draw_triangle(buf, frame, a, b, e2, color);
                draw_triangle(buf, frame, a, e2, d, color);
            }
    }
}

}  // namespace tessera::render
