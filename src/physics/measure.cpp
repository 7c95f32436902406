// measure_physics: interpenetration and support of element shapes (the two artifacts
// Figure 15 of Discrete Element Textures shows the interleaved physics solver removing).
// Exact distances between capsule chains; candidate pairs by a sort-and-sweep of the
// shapes' bounding boxes along the domain's longest axis.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "physics/hulls.hpp"
#include "physics/shapes.hpp"
#include "tessera/error.hpp"
#include "tessera/physics.hpp"

namespace tessera {
namespace {

using physics::ElementShape;

struct PairContact {
    double gap = 0;  // distance between the surfaces; negative = overlap depth
    Vec3 on_a, on_b;  // closest points of the two axes
};

// The closest approach of two capsule chains (a one-sample chain is a point).
PairContact contact(const Exemplar& data, const ElementShape& a, const ElementShape& b) {
    PairContact best;
    double best_d2 = -1;
    const int na = std::max(a.count - 1, 1), nb = std::max(b.count - 1, 1);
    for (int i = 0; i < na; ++i) {
        const Vec3& a0 = data.samples[a.first + i].p;
        const Vec3& a1 = data.samples[a.first + std::min(i + 1, a.count - 1)].p;
        for (int j = 0; j < nb; ++j) {
            const Vec3& b0 = data.samples[b.first + j].p;
            const Vec3& b1 = data.samples[b.first + std::min(j + 1, b.count - 1)].p;
            Vec3 pa, pb;
            const double d2 = physics::closest_points_segments(a0, a1, b0, b1, pa, pb);
            if (best_d2 < 0 || d2 < best_d2) {
                best_d2 = d2;
                best.on_a = pa;
                best.on_b = pb;
            }
        }
    }
    best.gap = std::sqrt(std::max(best_d2, 0.0)) - a.radius - b.radius;
    return best;
}

bool boxes_overlap(const ElementShape& a, const ElementShape& b, double slack) {
    for (int k = 0; k < 3; ++k)
        if (a.lo[k] > b.hi[k] + slack || b.lo[k] > a.hi[k] + slack) return false;
    return true;
}

// The element's deepest point along the unit gravity direction g.
Vec3 lowest_point(const Exemplar& data, const ElementShape& s, const Vec3& g) {
    int best = s.first;
    for (int k = 1; k < s.count; ++k)
        if (dot(data.samples[s.first + k].p, g) > dot(data.samples[best].p, g)) best = s.first + k;
    return data.samples[best].p + g * s.radius;
}

}  // namespace

PhysicsReport measure_physics(const Exemplar& data, const Domain& domain, const Vec3& gravity, double tolerance) {
    if (!(tolerance >= 0) || !std::isfinite(tolerance))
        throw Error(ErrorKind::option, "physics tolerance must be finite and >= 0, got " + std::to_string(tolerance));
    PhysicsReport report;
    const int n = static_cast<int>(data.elements.size());
    report.elements = n;
    if (n == 0) return report;
    std::vector<ElementShape> shapes = physics::element_shapes(data);
    const Vec3 g = physics::gravity_direction(gravity, data.dimension);
    // Types with meshes are measured as the convex hulls the simulation uses (hulls.hpp).
    const physics::TypeHulls hulls(data);
    std::vector<std::vector<Vec3>> hull(n);
    if (hulls.any)
        for (int i = 0; i < n; ++i)
            if (hulls.has(data.elements[i])) {
                hull[i] = physics::world_hull(hulls, data.elements[i], shapes[i].centroid);
                physics::cover_hull(shapes[i], hull[i]);
            }

    std::vector<char> supported(n, 0);
    for (int i = 0; i < n; ++i) {
        const ElementShape& s = shapes[i];
        if (!is_finite(s.centroid) || !domain.inside(s.centroid)) ++report.lost;
        Vec3 lowest = lowest_point(data, s, g);
        if (!hull[i].empty())
            lowest = *std::max_element(hull[i].begin(), hull[i].end(),
                                       [&](const Vec3& a, const Vec3& b) { return dot(a, g) < dot(b, g); });
        supported[i] = !domain.inside(lowest + g * (tolerance * s.radius));
    }

    // Sort-and-sweep along the domain's longest axis.
    const Vec3 size = domain.bounds().size();
    int axis = size.x >= size.y ? 0 : 1;
    if (data.dimension == 3 && size.z > size[axis]) axis = 2;
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return shapes[a].lo[axis] < shapes[b].lo[axis]; });
    double max_radius = 0;
    for (const ElementShape& s : shapes) max_radius = std::max(max_radius, s.radius);
    const double slack = tolerance * max_radius;

    for (int oi = 0; oi < n; ++oi) {
        const int a = order[oi];
        const ElementShape& sa = shapes[a];
        for (int oj = oi + 1; oj < n; ++oj) {  // bounded by n
            const int b = order[oj];
            const ElementShape& sb = shapes[b];
            if (sb.lo[axis] > sa.hi[axis] + slack) break;
            if (!boxes_overlap(sa, sb, slack)) continue;
            PairContact c;
            if (hull[a].empty() && hull[b].empty()) {
                c = contact(data, sa, sb);
            } else {
                const physics::HullContact h = physics::hull_contact(
                    hull[a], &data.samples[sa.first], sa.count, sa.radius, hull[b], &data.samples[sb.first],
                    sb.count, sb.radius);
                c = {h.gap, h.on_a, h.on_b};
            }
            const double depth = -c.gap;
            if (depth > 0) report.max_depth = std::max(report.max_depth, depth);
            if (depth > tolerance * std::min(sa.radius, sb.radius)) ++report.interpenetrating_pairs;
            // Support: a touching neighbour whose contact lies below the element's centroid.
            const Vec3 at = (c.on_a + c.on_b) * 0.5;
            if (c.gap <= tolerance * sa.radius && dot(at - sa.centroid, g) > 0.1 * sa.radius) supported[a] = 1;
            if (c.gap <= tolerance * sb.radius && dot(at - sb.centroid, g) > 0.1 * sb.radius) supported[b] = 1;
        }
    }
    for (int i = 0; i < n; ++i)
        if (!supported[i]) ++report.floating;
    return report;
}

}  // namespace tessera
