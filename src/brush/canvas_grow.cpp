// Growth of palette entries on a brush canvas (brush/canvas_grow.hpp).
#include "brush/canvas_grow.hpp"

#include "brush/canvas_surface.hpp"
#include "brush/positions.hpp"
#include "brush/surface.hpp"
#include "core/rng.hpp"
#include "core/spatial_grid.hpp"

#include <cmath>
#include <cstdint>

namespace tessera::brush {

namespace {

// Share of the summed weights under which two samples of different elements conflict when a
// grown element is added (Eq. 3 resolves smaller overlaps in the solve): of one palette
// entry, whose exemplar's own closest pairs may come closer than its weights, and of two
// entries, whose exemplars never showed them together. Between entries the whole weights:
// the solve after the fill moves elements, and with 0.8 there it pushed a few pairs where
// two entries' parts meet under 0.8 of their summed weights.
constexpr double kConflictShare = 0.8;
constexpr double kConflictShareBetweenEntries = 1.0;

// The canvas's elements of entry kappa within `reach` of the region's bounds, in the entry's
// own types, as the grower's existing arrangement.
Arrangement existing_of_entry(const BrushCanvas::Impl& st, int kappa, const Domain& region, double reach) {
    const PaletteEntry& entry = st.palette[kappa];
    Arrangement out;
    out.dimension = st.dimension;
    out.types = entry.exemplar.types;
    out.domain = st.domain;
    const Box b = region.bounds();
    const Arrangement& arr = st.arrangement;
    for (const Element& e : arr.elements) {
        const OutType& ot = st.out_types[e.type];
        if (ot.kappa != kappa) continue;
        bool near = true;
        for (int a = 0; a < st.dimension; ++a)
            near = near && e.position[a] >= b.lo[a] - reach && e.position[a] <= b.hi[a] + reach;
        if (!near) continue;
        std::vector<Vec3> points;
        for (int k = 0; k < e.sample_count; ++k) points.push_back(arr.samples[e.first_sample + k].p);
        const int i = out.add_element(ot.type, points, e.radius);
        out.elements[i].orientation = e.orientation;
        out.elements[i].id = e.id;
    }
    return out;
}

// True when a sample of `candidate` (positions, weights; of palette entry kappa) comes closer
// to a canvas sample of another element than kConflictShare (of its entry) or
// kConflictShareBetweenEntries of their summed weights.
bool conflicts(const BrushCanvas::Impl& st, const core::SpatialGrid& grid, double reach, const std::vector<Vec3>& points,
               const std::vector<double>& weights, int kappa) {
    bool hit = false;
    for (size_t k = 0; k < points.size() && !hit; ++k)
        grid.for_each_within(points[k], weights[k] + reach, [&](int o, double d2) {
            const bool same_entry = st.kappa_of_element(st.arrangement.samples[o].element) == kappa;
            const double share = same_entry ? kConflictShare : kConflictShareBetweenEntries;
            const double summed = share * (weights[k] + st.weight_of_sample(o));
            if (d2 < summed * summed) hit = true;
        });
    return hit;
}


// The field's direction at p tilted by up to `tilt` radians. A field interpolated between
// opposite strokes flips by exactly half a turn along a line, where the orientation solve's
// gradient vanishes (a saddle of Eq. 6); the tilt lets it turn the flip into a smooth bend.
Vec3 tilted_direction(const BrushCanvas::Impl& st, const OrientationField& field, const Vec3& p, double tilt) {
    Vec3 u = field.active() ? field.direction(p) : Vec3{1, 0, 0};
    if (!(norm(u) > 0.0)) u = Vec3{1, 0, 0};
    if (tilt <= 0.0) return u;
    const double cell = 0.25 * st.palette.front().spacing;  // a lattice anchored at the world origin
    auto key = [&](double x) { return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(x / cell))); };
    const core::KeyedRng rng(st.options.seed, core::Purpose::brush_field, key(p.x), key(p.y) * 0x9e3779b1ULL ^ key(p.z));
    Vec3 off{rng.uniform(0) - 0.5, rng.uniform(1) - 0.5, st.dimension == 3 ? rng.uniform(2) - 0.5 : 0.0};
    off -= u * dot(off, u);
    return (u + off * (2.0 * tilt)) / norm(u + off * (2.0 * tilt));
}

}  // namespace

std::pair<int, int> grow_entry(BrushCanvas::Impl& st, int kappa, const Domain& region, const OrientationField& field,
                               const Vec3& seed_at, double tilt, RegionEdge edge) {
    PaletteEntry& entry = st.palette[kappa];
    GrowOptions options;
    options.seed = st.options.seed;
    options.threads = st.options.threads;
    options.field = field;
    Grower grower(entry.exemplar, options);
    grower.set_progress(st.progress);
    const Arrangement existing = existing_of_entry(st, kappa, region, 3.0 * entry.radius);
    if (!existing.elements.empty()) grower.set_arrangement(existing);
    else grower.seed(region.closest_inside(seed_at));
    grower.grow(region, edge);
    const Arrangement& grown = grower.arrangement();

    // Samples of the canvas, against which new elements are checked (those of the same entry
    // were the grower's own neighbours already, but a far one may still be near).
    std::vector<Vec3> points;
    for (const Sample& s : st.arrangement.samples) points.push_back(s.p);
    double reach = 0.0;
    for (int s = 0; s < static_cast<int>(points.size()); ++s) reach = std::max(reach, st.weight_of_sample(s));
    core::SpatialGrid grid;
    grid.build(points, std::max(reach * 2.0, 1e-6), st.dimension);

    int added = 0, dropped = 0;
    const int first_new = static_cast<int>(st.arrangement.elements.size());
    for (const Element& e : grown.elements) {
        if (e.locked) continue;
        std::vector<Vec3> sample_points;
        for (int k = 0; k < e.sample_count; ++k) sample_points.push_back(grown.samples[e.first_sample + k].p);
        if (st.surface)  // grown in the band: the element sits on the surface, not in its thickness
            for (Vec3& q : sample_points) q = st.surface->closest(q).p;
        const std::vector<double>& w = entry.weights[e.type];
        bool inside = true;  // an open region's edge lets samples reach beyond it, never the canvas's
        for (const Vec3& q : sample_points) inside = inside && st.space().inside(q);
        if (!inside || conflicts(st, grid, reach, sample_points, w, kappa)) {
            ++dropped;
            continue;
        }
        Vec3 centre;  // the centroid (the grower's pose position need not be it)
        for (const Vec3& q : sample_points) centre += q;
        centre = centre / static_cast<double>(sample_points.size());
        const Vec3 u = tilted_direction(st, field, centre, tilt);
        const Quat frame = frame_at(st, u, centre);  // on a surface: z = the normal, u made tangent
        const int i = st.arrangement.add_element(entry.out_type[e.type], sample_points, e.radius);
        Element& out = st.arrangement.elements[i];
        out.id = st.next_id++;
        out.attributes.clear();
        for (int k = 0; k < e.sample_count; ++k) {
            st.direction.push_back(frame.rotate(Vec3{1, 0, 0}));
            st.reference.push_back(frame.conjugate().rotate(sample_points[k] - centre));
        }
        st.relative.push_back(frame.conjugate() * e.orientation);
        ++added;
    }
    snap_elements(st, first_new, static_cast<int>(st.arrangement.elements.size()));  // o(s) tangent per sample
    update_element_poses(st, first_new);
    return {added, dropped};
}

}  // namespace tessera::brush
