#include "det/init.hpp"

#include <algorithm>
#include <cmath>

#include "core/rng.hpp"
#include "det/structure_range.hpp"
#include "tessera/error.hpp"

namespace tessera::det {

namespace {

struct CellGrid {
    int dims[3] = {1, 1, 1};
    Vec3 lo;
    double size = 1.0;
    int count() const { return dims[0] * dims[1] * dims[2]; }
    int index_of(const Vec3& p, int dimension) const {
        int c[3] = {0, 0, 0};
        for (int k = 0; k < dimension; ++k) {
            c[k] = static_cast<int>(std::floor((p[k] - lo[k]) / size));
            if (c[k] < 0 || c[k] >= dims[k]) return -1;
        }
        return (c[2] * dims[1] + c[1]) * dims[0] + c[0];
    }
    Vec3 cell_lo(int index) const {
        const int x = index % dims[0], y = (index / dims[0]) % dims[1], z = index / (dims[0] * dims[1]);
        return lo + Vec3{x * size, y * size, z * size};
    }
};

// Calls fn(cell) for the cells around `c` (3^d block) that come before it in raster order.
template <class Fn>
void for_each_earlier_neighbor(const CellGrid& cells, int c, int dim, Fn&& fn) {
    const int cx = c % cells.dims[0], cy = (c / cells.dims[0]) % cells.dims[1], cz = c / (cells.dims[0] * cells.dims[1]);
    for (int dz = (dim == 3 ? -1 : 0); dz <= (dim == 3 ? 1 : 0); ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int x = cx + dx, y = cy + dy, z = cz + dz;
                if (x < 0 || y < 0 || z < 0 || x >= cells.dims[0] || y >= cells.dims[1] || z >= cells.dims[2]) continue;
                const int nb = (z * cells.dims[1] + y) * cells.dims[0] + x;
                if (nb < c) fn(nb);
            }
}

// Closest distance between element centroids of each pair of types in the
// exemplar (infinity when a type pair never occurs).
std::vector<double> closest_type_pairs(const Exemplar& exemplar, const std::vector<Vec3>& centers,
                                       const core::SpatialGrid& grid, double max_distance) {
    const int types = static_cast<int>(exemplar.types.size());
    std::vector<double> closest(types * types, INFINITY);
    for (size_t i = 0; i < centers.size(); ++i) {
        const int a = exemplar.elements[i].type;
        for (int b = 0; b < types; ++b) {
            const int j = grid.nearest(centers[i], max_distance, [&](int k) {
                return k != static_cast<int>(i) && exemplar.elements[k].type == b;
            });
            if (j < 0) continue;
            const double d = norm(centers[j] - centers[i]);
            closest[a * types + b] = std::min(closest[a * types + b], d);
            closest[b * types + a] = std::min(closest[b * types + a], d);
        }
    }
    return closest;
}

// Axes along which the exemplar is a thin layer: thinner than one neighbourhood
// diameter (2 x radius). Such an exemplar cannot offer a cubic window of patch size.
struct LayerAxes {
    bool thin[3] = {false, false, false};
    bool any = false;
};

LayerAxes layer_axes(const Box& in_box, int dim, double radius) {
    LayerAxes layer;
    int thin_count = 0;
    for (int k = 0; k < dim; ++k) {
        layer.thin[k] = in_box.hi[k] - in_box.lo[k] < 2.0 * radius;
        thin_count += layer.thin[k];
    }
    if (thin_count == dim) return {};  // a tiny exemplar, not a layer: the usual windows
    layer.any = thin_count > 0;
    return layer;
}

// Slides a cell's window centre along each thin axis (turned by the local frame) to the
// middle of the nearest run of domain inside that line, within +-patch: the layer then
// lands in the domain (a shell under a surface) instead of wherever the cell's centre is.
Vec3 onto_layer(const Vec3& center, const Quat& rotation, const LayerAxes& layer, const Box& in_box,
                const Domain& domain, double patch, int dim) {
    Vec3 out = center;
    for (int k = 0; k < dim; ++k) {
        if (!layer.thin[k]) continue;
        Vec3 axis;
        axis[k] = 1.0;
        const Vec3 dir = rotation.rotate(axis);
        const double step = std::max(0.25 * (in_box.hi[k] - in_box.lo[k]), patch / 64.0);
        const int steps = static_cast<int>(std::ceil(patch / step));  // bounded: <= 64 each way
        // The inside run nearest to t = 0, searched outward.
        int first = 1, last = 0;  // empty
        for (int r = 0; r <= steps && first > last; ++r)
            for (int sign : {1, -1}) {
                const int t = sign * r;
                if (domain.inside(out + dir * (t * step))) {
                    first = last = t;
                    break;
                }
            }
        if (first > last) continue;  // no domain on this line: leave the centre
        while (first - 1 >= -steps && domain.inside(out + dir * ((first - 1) * step))) --first;
        while (last + 1 <= steps && domain.inside(out + dir * ((last + 1) * step))) ++last;
        out = out + dir * (0.5 * (first + last) * step);
    }
    return out;
}

// Where a patch goes: the window around in_center is laid down around out_center,
// turned by the local frame of the orientation field there (Eq. 7).
struct PatchMap {
    Vec3 in_center, out_center;
    Quat rotation;
    Vec3 to_output(const Vec3& p) const { return out_center + rotation.rotate(p - in_center); }
    Vec3 to_input(const Vec3& q) const { return in_center + rotation.conjugate().rotate(q - out_center); }
};

}  // namespace

std::vector<Vec3> element_centroids(const std::vector<Element>& elements, int dimension) {
    std::vector<Vec3> p;
    p.reserve(elements.size());
    for (const Element& e : elements) {
        Vec3 q = e.position;
        if (dimension == 2) q.z = 0.0;
        p.push_back(q);
    }
    return p;
}

int append_copy(InitResult& init, const Exemplar& exemplar, int source, const Quat& rotation, const Vec3& shift,
                int dimension) {
    Arrangement& out = init.arrangement;
    const Element& src = exemplar.elements[source];
    Element e = src;
    e.first_sample = static_cast<int>(out.samples.size());
    e.id = out.elements.size();
    e.locked = false;
    const int index_out = static_cast<int>(out.elements.size());
    for (int s = 0; s < src.sample_count; ++s) {
        Sample smp = exemplar.samples[src.first_sample + s];
        smp.p = rotation.rotate(smp.p) + shift;
        if (dimension == 2) smp.p.z = 0.0;
        smp.element = index_out;
        out.samples.push_back(smp);
        init.source_sample.push_back(src.first_sample + s);
    }
    e.position = rotation.rotate(src.position) + shift;
    e.orientation = rotation * src.orientation;
    if (dimension == 2) e.position.z = 0.0;
    out.elements.push_back(std::move(e));
    init.source_element.push_back(source);
    return index_out;
}

InitResult initialize_patches(const Exemplar& exemplar, const InputIndex& /*index*/, const Domain& domain,
                              const Params& params, const DetOptions& options) {
    const int dim = params.dimension;
    const Box in_box = exemplar.domain.bounds();
    const Box out_box = domain.bounds();
    // A layered exemplar (a wall one brick thick, a sheet) is thinner than a neighbourhood
    // along some axis. Such thin axes do not limit the patch size: the window spans the
    // whole layer along them, and each output cell's window is slid along the (field-
    // turned) thin axis onto the domain, so a shell under a surface receives one layer.
    const LayerAxes layer = layer_axes(in_box, dim, params.radius);
    double min_extent = INFINITY;
    for (int k = 0; k < dim; ++k)
        if (!layer.thin[k]) min_extent = std::min(min_extent, in_box.hi[k] - in_box.lo[k]);
    if (!std::isfinite(min_extent)) min_extent = 2.0 * params.radius;
    double patch = options.patch_size;
    double structure = 0.0;
    if (!(patch > 0.0)) {
        // The paper's patch is one neighbourhood (2r). An exemplar structured beyond it
        // (clusters, wide gaps, long rows, a lattice) gets patches twice its structure
        // range, so patches hold clusters whole and keep rows in phase: on clustered
        // and multi-class field data this halves the output's PCF error (docs/det.md).
        // Not with an orientation field or thin layers, where each patch is turned by
        // the frame at its cell's centre only.
        patch = 2.0 * params.radius;
        if (!params.field.active() && !layer.any) {
            const double limit = std::min(0.25 * min_extent, 12.0 * params.spacing);
            if (limit > params.radius) structure = structure_range(exemplar, params.spacing, limit);
            patch = std::max(patch, 2.0 * structure);
        }
        patch = std::min(patch, 0.5 * min_extent);
    }
    patch = std::min(patch, min_extent);
    // Window extent per axis: the patch, the whole layer along thin axes, and with thin
    // axes a diagonal's worth in-plane, since a turned layer crosses an axis-aligned
    // output cell along up to sqrt(dim) times its side.
    Vec3 window_size;
    for (int k = 0; k < dim; ++k) {
        const double extent = in_box.hi[k] - in_box.lo[k];
        window_size[k] = layer.thin[k] ? extent : std::min(extent, layer.any ? patch * std::sqrt(double(dim)) : patch);
    }
    const double window_reach = 0.5 * norm(window_size);  // centre to corner

    CellGrid cells;
    cells.lo = out_box.lo;
    cells.size = patch;
    for (int k = 0; k < dim; ++k)
        cells.dims[k] = std::max(1, static_cast<int>(std::ceil((out_box.hi[k] - out_box.lo[k]) / patch - 1e-9)));
    if (static_cast<double>(cells.count()) > 5e7)
        throw Error(ErrorKind::option, "--patch-size is too small for this domain (more than 5e7 patches)");

    // Input elements by centroid for window queries.
    const int n_in = static_cast<int>(exemplar.elements.size());
    const std::vector<Vec3> in_centers = element_centroids(exemplar.elements, dim);
    core::SpatialGrid in_grid;
    in_grid.build(in_centers, std::max(params.spacing, patch / 4.0), dim);

    // Seam duplicates: where two patches meet, both may fill the same place. An
    // element copied closer to an already placed one than 3/4 of the closest
    // distance the exemplar shows for that pair of types is such a duplicate and is
    // not copied (exemplars with overlapping elements have closest distance ~0 and
    // lose nothing).
    const int n_types = static_cast<int>(exemplar.types.size());
    std::vector<double> min_gap = closest_type_pairs(exemplar, in_centers, in_grid, patch);
    for (double& g : min_gap) g = std::isfinite(g) ? 0.75 * g : 0.0;

    // Band around a cell in which the candidate windows are compared with placed elements.
    const double band = std::min(params.spacing, 0.5 * patch);
    const double cap2 = params.cap2;

    InitResult result;
    result.patch_size = patch;
    result.structure_range = structure;
    Arrangement& out = result.arrangement;
    out.dimension = dim;
    out.types = exemplar.types;
    out.attribute_names = exemplar.attribute_names;
    out.domain = domain;

    std::vector<std::vector<int>> placed(cells.count());  // output elements per cell (by centroid)
    std::vector<int> window;                               // scratch: input elements in a window
    const core::KeyedRng rng(options.seed, core::Purpose::patch_choice);

    const Vec3 half = Vec3{patch, patch, dim == 3 ? patch : 0.0} * 0.5;
    const Vec3 window_half = window_size * 0.5;

    // Count balance (error diffusion over the raster order). Windows of a clustered or
    // uneven exemplar hold very different counts; fill_holes tops up an output that falls
    // short but nothing takes away from one that overshoots, so random windows alone left
    // outputs up to 30% overfull (redwood at 4x). Each candidate therefore also pays for
    // how far the running count would stray from the exemplar's density over the cells
    // done so far, beyond one cell's worth, at the price of a missing element (cap2) per
    // element, class by class (each class against its own share of the density, so the
    // classes keep their proportions too). Not for layered exemplars, whose cells are not
    // patch-sized along thin axes.
    const bool balance_count = !layer.any;
    const double density = static_cast<double>(exemplar.elements.size()) / exemplar.domain.measure();
    std::vector<double> share(n_types, 0.0);
    for (const Element& e : exemplar.elements) share[e.type] += 1.0 / static_cast<double>(n_in);
    std::vector<int> placed_of_type(n_types, 0), window_counts(n_types, 0);
    double expected_so_far = 0.0;
    // The exemplar elements (ascending) whose centroids lie in the window (a box, not the
    // ball around it) and land in the cell and the domain: what a window puts in a cell.
    auto window_elements_in_cell = [&](const PatchMap& m, const Vec3& clo, std::vector<int>& elements) {
        elements.clear();
        in_grid.for_each_within(m.in_center, window_reach + 1e-12, [&](int i, double) {
            bool in_window = true;
            for (int k = 0; k < dim; ++k)
                in_window = in_window && std::abs(in_centers[i][k] - m.in_center[k]) <= window_half[k] + 1e-12;
            if (!in_window) return;
            const Vec3 q = m.to_output(in_centers[i]);
            bool in_cell = true;
            for (int k = 0; k < dim; ++k) in_cell = in_cell && q[k] >= clo[k] && q[k] < clo[k] + patch;
            if (in_cell && domain.inside(q)) elements.push_back(i);
        });
        std::sort(elements.begin(), elements.end());
    };

    for (int c = 0; c < cells.count(); ++c) {
        const Vec3 clo = cells.cell_lo(c);
        PatchMap map;
        map.out_center = clo + half;
        map.rotation = params.field.frame(map.out_center, dim);
        // The exemplar's count for this cell: density x the cell's measure inside the domain
        // (from a 4^d lattice of probes).
        double expected_cell = 0.0;
        if (balance_count) {
            constexpr int per_axis = 4;
            int inside = 0, total = 0;
            for (int z = 0; z < (dim == 3 ? per_axis : 1); ++z)
                for (int y = 0; y < per_axis; ++y)
                    for (int x = 0; x < per_axis; ++x, ++total)
                        inside += domain.inside(clo + Vec3{(x + 0.5), (y + 0.5), dim == 3 ? (z + 0.5) : 0.0} *
                                                          (patch / per_axis));
            expected_cell = density * std::pow(patch, dim) * inside / total;
        }
        if (layer.any) map.out_center = onto_layer(map.out_center, map.rotation, layer, in_box, domain, patch, dim);
        // Output elements already placed in the band around this cell.
        std::vector<int> band_elements;
        for_each_earlier_neighbor(cells, c, dim, [&](int nb) {
            for (int e : placed[nb]) {
                const Vec3& p = out.elements[e].position;
                bool near = true;
                for (int k = 0; k < dim; ++k) near = near && p[k] >= clo[k] - band && p[k] <= clo[k] + patch + band;
                if (near) band_elements.push_back(e);
            }
        });

        // Probes of the cell and its band for boundary-occupancy similarity: only cells
        // that touch the output boundary need them (elsewhere every window agrees).
        std::vector<Vec3> probes;
        {
            constexpr int per_axis = 5;
            const double step = (patch + 2.0 * band) / (per_axis - 1);
            bool touches_boundary = false;
            for (int z = 0; z < (dim == 3 ? per_axis : 1); ++z)
                for (int y = 0; y < per_axis; ++y)
                    for (int x = 0; x < per_axis; ++x) {
                        const Vec3 q = clo - Vec3{band, band, dim == 3 ? band : 0.0} +
                                       Vec3{x * step, y * step, dim == 3 ? z * step : 0.0};
                        probes.push_back(q);
                        touches_boundary = touches_boundary || !domain.inside(q);
                    }
            if (!touches_boundary) probes.clear();
        }

        // Choose among random windows the one most consistent with the band.
        Vec3 best_center;
        double best_score = INFINITY;
        const int tries =
            band_elements.empty() && probes.empty() && !balance_count ? 1 : options.patch_candidates;
        for (int j = 0; j < tries; ++j) {
            Vec3 origin = in_box.lo;
            for (int k = 0; k < dim; ++k) {
                const double span = (in_box.hi[k] - in_box.lo[k]) - window_size[k];
                origin[k] += span > 0.0 ? span * rng.uniform(static_cast<std::uint64_t>(c) * 64 * 3 + j * 3 + k) : 0.0;
                // With floor constraints the exemplar's sides are physical (a floor, walls): a
                // cell on a side of the output's bounds takes its window flush with the same
                // side of the exemplar, so boundary layers line up. (Without them the exemplar
                // is a window cut from a larger pattern and any window is as good.)
                if (params.field.active() || !params.floor_constraints) continue;
                if (clo[k] <= out_box.lo[k]) {
                    origin[k] = in_box.lo[k];
                } else if (clo[k] + patch >= out_box.hi[k]) {
                    const double flush = in_box.hi[k] - (out_box.hi[k] - clo[k]);
                    if (flush >= in_box.lo[k]) origin[k] = flush;
                }
            }
            map.in_center = origin + window_half;
            double score = 0.0;
            // Placed output elements should find an input element of their type where they sit.
            for (int e : band_elements) {
                const Vec3 q = map.to_input(out.elements[e].position);
                const int type = out.elements[e].type;
                const int hit = in_grid.nearest(q, params.spacing, [&](int i) { return exemplar.elements[i].type == type; });
                double d2 = cap2;
                if (hit >= 0) d2 = std::min(cap2, squared_norm(in_centers[hit] - q));
                score += d2;
            }
            // Input elements that would land in already placed cells should find a placed element.
            in_grid.for_each_within(map.in_center, window_reach + band * std::sqrt(static_cast<double>(dim)),
                                    [&](int i, double) {
                const Vec3 q = map.to_output(in_centers[i]);
                bool in_band = true, in_cell = true;
                for (int k = 0; k < dim; ++k) {
                    in_band = in_band && q[k] >= clo[k] - band && q[k] <= clo[k] + patch + band;
                    in_cell = in_cell && q[k] >= clo[k] && q[k] < clo[k] + patch;
                }
                if (!in_band || in_cell) return;
                const int cell = cells.index_of(q, dim);
                if (cell < 0 || cell >= c) return;  // lands outside, or on a cell not placed yet
                double d2 = cap2;
                for (int e : band_elements)
                    if (out.elements[e].type == exemplar.elements[i].type)
                        d2 = std::min(d2, squared_norm(out.elements[e].position - q));
                score += d2;
            });
            // Section 4.1: prefer input patches whose boundary occupancy resembles the output's
            // here (a probe inside one domain but outside the other costs like a missing element).
            for (const Vec3& q : probes)
                if (domain.inside(q) != exemplar.domain.inside(map.to_input(q))) score += cap2;
            if (balance_count) {
                window_elements_in_cell(map, clo, window);
                std::fill(window_counts.begin(), window_counts.end(), 0);
                for (int i : window) ++window_counts[exemplar.elements[i].type];
                for (int t = 0; t < n_types; ++t) {
                    const double straying = static_cast<double>(placed_of_type[t] + window_counts[t]) -
                                            share[t] * (expected_so_far + expected_cell);
                    score += cap2 * std::max(0.0, std::abs(straying) - std::max(1.0, share[t] * expected_cell));
                }
            }
            if (score < best_score) best_score = score, best_center = map.in_center;
        }

        // Copy whole elements whose centroid lies in the chosen window (and in the domain).
        map.in_center = best_center;
        window_elements_in_cell(map, clo, window);
        for (int i : window) {
            const Vec3 q = map.to_output(in_centers[i]);
            const Element& src = exemplar.elements[i];
            bool duplicate = false;
            for_each_earlier_neighbor(cells, c, dim, [&](int nb) {
                for (int e : placed[nb]) {
                    const double gap = min_gap[src.type * n_types + out.elements[e].type];
                    if (gap > 0.0 && squared_norm(out.elements[e].position - q) < gap * gap) duplicate = true;
                }
            });
            if (duplicate) continue;
            const int index_out = append_copy(result, exemplar, i, map.rotation,
                                              map.out_center - map.rotation.rotate(map.in_center), dim);
            const int cell = cells.index_of(out.elements.back().position, dim);
            placed[cell >= 0 ? cell : c].push_back(index_out);
            ++placed_of_type[src.type];
        }
        expected_so_far += expected_cell;
    }
    if (out.elements.empty())
        throw Error(ErrorKind::domain, "the output domain " + domain.describe() + " is too small to hold one element");
    return result;
}

}  // namespace tessera::det
