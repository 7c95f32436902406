#include "det/density.hpp"

#include <algorithm>
#include <cmath>

#include "core/spatial_grid.hpp"
#include "det/provenance.hpp"

namespace tessera::det {

namespace {

// Nearest-neighbour distances of a regular pattern vary by less than this share of their mean.
constexpr double kRegularVariation = 0.25;
// A side is a margin when its nearest element lies more than this many spacings in.
constexpr double kMarginGap = 0.75;

struct NearestNeighborSpread {
    double mean = 0.0, deviation = 0.0;
};

NearestNeighborSpread nearest_neighbor_spread(const std::vector<Vec3>& p, int dim) {
    core::SpatialGrid grid;
    Vec3 lo = p[0], hi = p[0];
    for (const Vec3& q : p)
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], q[k]), hi[k] = std::max(hi[k], q[k]);
    const double extent = norm(hi - lo) + 1e-300;
    grid.build(p, extent / std::sqrt(static_cast<double>(p.size())), dim);
    std::vector<double> d;
    for (size_t i = 0; i < p.size(); ++i) {
        const int j = grid.nearest(p[i], extent, [i](int k) { return k != static_cast<int>(i); });
        if (j >= 0) d.push_back(norm(p[j] - p[i]));
    }
    NearestNeighborSpread s;
    for (double v : d) s.mean += v / d.size();
    for (double v : d) s.deviation += (v - s.mean) * (v - s.mean) / d.size();
    s.deviation = std::sqrt(s.deviation);
    return s;
}

// Measure of the part of the domain at least `depth` inside it, from a lattice of probes
// (exact for boxes).
double eroded_measure(const Domain& domain, int dimension, double depth) {
    const Box b = domain.bounds();
    if (domain.kind() == Domain::Kind::box) {
        double m = 1.0;
        for (int k = 0; k < dimension; ++k) m *= std::max(0.0, b.hi[k] - b.lo[k] - 2.0 * depth);
        return m;
    }
    const int per_axis = dimension == 2 ? 128 : 40;
    long inside = 0, total = 0;
    for (int z = 0; z < (dimension == 3 ? per_axis : 1); ++z)
        for (int y = 0; y < per_axis; ++y)
            for (int x = 0; x < per_axis; ++x, ++total) {
                const Vec3 p = b.lo + Vec3{(x + 0.5) * b.size().x / per_axis, (y + 0.5) * b.size().y / per_axis,
                                           dimension == 3 ? (z + 0.5) * b.size().z / per_axis : 0.0};
                inside += domain.distance_to_boundary(p) >= depth;
            }
    double box = 1.0;
    for (int k = 0; k < dimension; ++k) box *= b.hi[k] - b.lo[k];
    return box * static_cast<double>(inside) / static_cast<double>(total);
}

}  // namespace

// A box window's measure without the empty margins of a regular pattern: a side whose
// nearest element lies more than `margin_gap` spacings in is moved in to half a spacing
// before that element (a regular pattern's elements own half a spacing around them). Only
// for regular patterns (nearest-neighbour distances varying by less than
// kRegularVariation): a random or clustered pattern cut from a larger one has no margin,
// and an empty side there is chance, not design.
double occupied_box_measure(const Exemplar& exemplar, double spacing) {
    const Box b = exemplar.domain.bounds();
    const int dim = exemplar.dimension;
    const std::vector<Vec3> p = element_centroids(exemplar.elements, dim);
    if (p.size() < 8) return exemplar.domain.measure();
    const NearestNeighborSpread spread = nearest_neighbor_spread(p, dim);
    if (!(spread.mean > 0.0) || spread.deviation > kRegularVariation * spread.mean) return exemplar.domain.measure();
    double measure = 1.0;
    for (int k = 0; k < dim; ++k) {
        double lo = b.hi[k], hi = b.lo[k];
        for (const Vec3& q : p) lo = std::min(lo, q[k]), hi = std::max(hi, q[k]);
        if (lo - b.lo[k] > kMarginGap * spacing) lo -= 0.5 * spacing; else lo = b.lo[k];
        if (b.hi[k] - hi > kMarginGap * spacing) hi += 0.5 * spacing; else hi = b.hi[k];
        measure *= hi - lo >= spacing ? hi - lo : b.hi[k] - b.lo[k];  // a layer keeps its thickness
    }
    return measure;
}

std::vector<double> exemplar_type_density(const Exemplar& exemplar, double spacing) {
    const int types = static_cast<int>(exemplar.types.size());
    const int dim = exemplar.dimension;
    const double measure = exemplar.domain.measure();
    std::vector<double> count(types, 0.0);
    for (const Element& e : exemplar.elements) count[e.type] += 1.0;
    double area = measure;
    if (spacing > 0.0 && exemplar.domain.kind() == Domain::Kind::box) {
        area = occupied_box_measure(exemplar, spacing);
    } else if (spacing > 0.0) {
        for (int layers = 1; layers <= 2; ++layers) {
            const double depth = layers * spacing;
            const double inner = eroded_measure(exemplar.domain, dim, depth);
            if (!(inner > 0.25 * measure)) break;
            std::vector<double> inner_count(types, 0.0);
            double n_inner = 0.0, n_all = 0.0;
            for (const Element& e : exemplar.elements) {
                n_all += 1.0;
                if (exemplar.domain.distance_to_boundary(e.position) >= depth) inner_count[e.type] += 1.0, n_inner += 1.0;
            }
            // The band's expected count at the interior's density, and its Poisson spread.
            const double expected = n_inner / inner * (measure - inner);
            if (!(n_all - n_inner < expected - 3.0 * std::sqrt(expected))) break;
            count = inner_count;
            area = inner;
        }
    }
    std::vector<double> density(types, 0.0);
    for (int t = 0; t < types; ++t) density[t] = count[t] / area;
    return density;
}

}  // namespace tessera::det
