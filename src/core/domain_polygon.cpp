// core/domain_polygon.cpp — the 2D polygon domain with holes (Domain::polygon).
// Inside is the even-odd rule over every ring (a point in a hole crosses the outer
// ring and the hole's ring: outside). Rings are validated on construction, since
// a self-intersecting ring would make the even-odd answer and the shoelace measure
// disagree silently; the O(n^2) segment test is fine for hand-typed polygons.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/domain_shape.hpp"
#include "tessera/error.hpp"

namespace tessera {
namespace {

using Ring = std::vector<Vec3>;

double cross2(const Vec3& a, const Vec3& b) { return a.x * b.y - a.y * b.x; }

double signed_area(const Ring& r) {  // shoelace
    double a = 0.0;
    for (size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) a += cross2(r[j], r[i]);
    return 0.5 * a;
}

// Orientation of (a, b, c) with a tolerance relative to the polygon's size.
int orient(const Vec3& a, const Vec3& b, const Vec3& c, double eps) {
    const double v = cross2(b - a, c - a);
    return v > eps ? 1 : (v < -eps ? -1 : 0);
}

bool on_segment(const Vec3& a, const Vec3& b, const Vec3& p) {
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y);
}

// Whether segments ab and cd share any point (touching and collinear overlap included).
bool segments_meet(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, double eps) {
    const int o1 = orient(a, b, c, eps), o2 = orient(a, b, d, eps);
    const int o3 = orient(c, d, a, eps), o4 = orient(c, d, b, eps);
    if (o1 != o2 && o3 != o4 && o1 * o2 <= 0 && o3 * o4 <= 0 && (o1 || o2) && (o3 || o4)) return true;
    if (o1 == 0 && on_segment(a, b, c)) return true;
    if (o2 == 0 && on_segment(a, b, d)) return true;
    if (o3 == 0 && on_segment(c, d, a)) return true;
    if (o4 == 0 && on_segment(c, d, b)) return true;
    return false;
}

Vec3 nearest_on_segment(const Vec3& a, const Vec3& b, const Vec3& p) {
    const Vec3 ab = b - a;
    const double len2 = squared_norm(ab);
    const double t = len2 > 0.0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return a + ab * t;
}

bool crosses_ray(const Ring& r, const Vec3& p) {  // even-odd test of one ring
    bool in = false;
    for (size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) {
        const Vec3& a = r[i];
        const Vec3& b = r[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
    }
    return in;
}

class PolygonShape final : public DomainShape {
public:
    std::vector<Ring> rings;  // rings[0] = outer

    bool inside(const Vec3& p) const override {
        if (p.x < bounds.lo.x || p.x > bounds.hi.x || p.y < bounds.lo.y || p.y > bounds.hi.y) return false;
        bool in = false;
        for (const Ring& r : rings) in ^= crosses_ray(r, p);
        return in;
    }
    double occupancy(const Vec3& p) const override { return inside(p) ? 1.0 : 0.0; }
    double measure() const override { return area_; }

    // Nearest point of the boundary (exact), with the segment it lies on.
    Vec3 nearest_boundary(const Vec3& p, Vec3* edge_dir) const {
        double best = INFINITY;
        Vec3 q = p;
        for (const Ring& r : rings)
            for (size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) {
                const Vec3 c = nearest_on_segment(r[j], r[i], p);
                const double d2 = squared_norm(c - p);
                if (d2 < best) best = d2, q = c, *edge_dir = r[i] - r[j];
            }
        return q;
    }
    Vec3 closest_inside(const Vec3& p) const override {
        Vec3 dir;
        Vec3 q = nearest_boundary(Vec3(p.x, p.y, 0.0), &dir);
        // The nearest boundary point may test outside by rounding: step inward along
        // the edge normal by a tiny, growing amount until the even-odd test agrees.
        const double len = norm(dir);
        const Vec3 normal = len > 0.0 ? Vec3(-dir.y / len, dir.x / len, 0.0) : Vec3();
        const double base = 1e-12 * (norm(bounds.size()) + norm(bounds.lo) + 1.0);
        // At a vertex the edge normal may run along the other edge; the direction from
        // p to q points into the domain there.
        const double away = norm(q - Vec3(p.x, p.y, 0.0));
        const Vec3 toward = away > 0.0 ? (q - Vec3(p.x, p.y, 0.0)) * (1.0 / away) : normal;
        for (double step = base; step < 1e-3 * norm(bounds.size()); step *= 4.0) {
            if (inside(q)) return q;
            for (const Vec3& dir : {toward, normal, -normal, (toward + normal) * 0.5, (toward - normal) * 0.5})
                if (inside(q + dir * step)) return q + dir * step;
        }
        return q;
    }
    double distance_to_boundary(const Vec3& p) const override {
        Vec3 dir;
        const Vec3 flat{p.x, p.y, 0.0};
        const double d = norm(nearest_boundary(flat, &dir) - flat);
        return inside(flat) ? d : -d;
    }
    std::string describe() const override {
        std::ostringstream s;
        s << "polygon with " << rings[0].size() << " vertices";
        if (rings.size() > 1) s << " and " << rings.size() - 1 << (rings.size() == 2 ? " hole" : " holes");
        s << " in [" << bounds.lo.x << "," << bounds.hi.x << "]x[" << bounds.lo.y << "," << bounds.hi.y << "]";
        return s.str();
    }

    double area_ = 0.0;
};

[[noreturn]] void fail(const std::string& what) { throw Error(ErrorKind::domain, "polygon: " + what); }

std::string ring_name(size_t r) { return r == 0 ? "the outer ring" : "hole " + std::to_string(r); }

void check_ring_simple(const Ring& ring, size_t index, double eps) {
    const size_t n = ring.size();
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j) {
            if (j == i + 1 || (i == 0 && j == n - 1)) continue;  // adjacent edges share a vertex
            if (segments_meet(ring[i], ring[(i + 1) % n], ring[j], ring[(j + 1) % n], eps)) {
                std::ostringstream s;
                s << ring_name(index) << " intersects itself (edge " << i << " meets edge " << j << ")";
                fail(s.str());
            }
        }
}

bool rings_meet(const Ring& a, const Ring& b, double eps) {
    for (size_t i = 0; i < a.size(); ++i)
        for (size_t j = 0; j < b.size(); ++j)
            if (segments_meet(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()], eps)) return true;
    return false;
}

}  // namespace

Domain Domain::polygon(const std::vector<Vec3>& outer, const std::vector<std::vector<Vec3>>& holes) {
    auto shape = std::make_shared<PolygonShape>();
    shape->rings.push_back(outer);
    for (const auto& h : holes) shape->rings.push_back(h);
    Box box{{INFINITY, INFINITY, 0.0}, {-INFINITY, -INFINITY, 0.0}};
    for (size_t r = 0; r < shape->rings.size(); ++r) {
        Ring& ring = shape->rings[r];
        // A closing vertex equal to the first is a common way to write a ring: drop it.
        if (ring.size() > 1 && ring.front().x == ring.back().x && ring.front().y == ring.back().y) ring.pop_back();
        if (ring.size() < 3)
            fail(ring_name(r) + " has " + std::to_string(ring.size()) + " vertices; at least 3 are needed");
        for (Vec3& v : ring) {
            if (!std::isfinite(v.x) || !std::isfinite(v.y)) fail(ring_name(r) + " has a non-finite coordinate");
            v.z = 0.0;
            if (r == 0) {
                box.lo.x = std::min(box.lo.x, v.x), box.lo.y = std::min(box.lo.y, v.y);
                box.hi.x = std::max(box.hi.x, v.x), box.hi.y = std::max(box.hi.y, v.y);
            }
        }
    }
    const double size = std::max(box.hi.x - box.lo.x, box.hi.y - box.lo.y);
    const double eps = 1e-12 * size * size;  // for orientation tests, in area units
    double area = 0.0;
    for (size_t r = 0; r < shape->rings.size(); ++r) {
        const double a = std::abs(signed_area(shape->rings[r]));
        if (!(a > 1e-12 * size * size)) fail(ring_name(r) + " has zero area");
        check_ring_simple(shape->rings[r], r, eps);
        area += r == 0 ? a : -a;
    }
    for (size_t r = 1; r < shape->rings.size(); ++r) {
        const Ring& hole = shape->rings[r];
        if (rings_meet(hole, shape->rings[0], eps)) fail(ring_name(r) + " crosses or touches the outer ring");
        if (!crosses_ray(shape->rings[0], hole[0])) fail(ring_name(r) + " lies outside the outer ring");
        for (size_t o = 1; o < r; ++o)
            if (rings_meet(hole, shape->rings[o], eps) || crosses_ray(shape->rings[o], hole[0]) ||
                crosses_ray(hole, shape->rings[o][0]))
                fail(ring_name(r) + " overlaps " + ring_name(o));
    }
    shape->dimension = 2;
    shape->bounds = box;
    shape->area_ = area;
    shape->source.outer = shape->rings[0];
    shape->source.holes.assign(shape->rings.begin() + 1, shape->rings.end());
    return from_shape(std::move(shape), Kind::polygon);
}

}  // namespace tessera
