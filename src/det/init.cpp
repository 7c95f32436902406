#include "det/init.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/rng.hpp"
#include "det/layers.hpp"
#include "det/structure_range.hpp"
#include "tessera/error.hpp"

namespace tessera::det {

namespace {

// Iterations of the registration of a random window onto the band (translation only).
constexpr int kRegistrationSteps = 3;
// Seam duplicates are elements closer than this share of the exemplar's closest distance.
constexpr double kDuplicateShare = 0.75;

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

// Where a patch goes: the window around in_center is laid down around out_center,
// turned by the local frame of the orientation field there (Eq. 7).
struct PatchMap {
    Vec3 in_center, out_center;
    Quat rotation;
    Vec3 to_output(const Vec3& p) const { return out_center + rotation.rotate(p - in_center); }
    Vec3 to_input(const Vec3& q) const { return in_center + rotation.conjugate().rotate(q - out_center); }
};

// What a cell's candidate windows are judged against.
struct CellContext {
    int cell = 0;
    Vec3 lo;                          // the cell's lower corner
    std::vector<int> band_elements;   // output elements already placed in the band around it
    std::vector<Vec3> probes;         // boundary-occupancy probes (empty away from the boundary)
    double expected = 0.0;            // the exemplar's count for the cell
};

// The patch-copy initialization, one cell after the other in raster order.
class PatchCopier {
public:
    PatchCopier(const Exemplar& exemplar, const Domain& domain, const Params& params, const DetOptions& options,
                const InitTick& tick)
        : ex_(exemplar), domain_(domain), params_(params), options_(options), tick_(tick), dim_(params.dimension),
          in_box_(exemplar.domain.bounds()), out_box_(domain.bounds()),
          layer_(layer_axes(in_box_, dim_, params.radius)) {}

    InitResult run();

private:
    void choose_patch();
    void prepare();
    CellContext context_of(int c) const;
    std::vector<Vec3> candidate_centres(const CellContext& cell, int tries) const;
    Vec3 random_centre(const CellContext& cell, int j) const;
    core::KeyedRng cell_rng(int c) const;
    double score(const PatchMap& map, const CellContext& cell);
    void register_window(PatchMap& map, const CellContext& cell, double& best_score);
    void window_elements_in_cell(const PatchMap& m, const Vec3& clo, std::vector<int>& elements) const;
    double deficit(int t, double expected) const;
    void copy(const PatchMap& map, const CellContext& cell);

    const Exemplar& ex_;
    const Domain& domain_;
    const Params& params_;
    const DetOptions& options_;
    const InitTick& tick_;
    const int dim_;
    const Box in_box_, out_box_;
    const LayerAxes layer_;
    std::int64_t world_cell_[3] = {0, 0, 0};  // world lattice coordinates of cell 0

    double patch_ = 0.0, structure_ = 0.0, band_ = 0.0, window_reach_ = 0.0;
    Vec3 window_size_, window_half_;
    CellGrid cells_;
    std::vector<Vec3> in_centers_;
    core::SpatialGrid in_grid_;
    int types_ = 0;
    std::vector<double> min_gap_;  // seam-duplicate distance per type pair
    bool balance_count_ = false;
    double density_ = 0.0;
    std::vector<double> share_;    // per type: its share of the density

    InitResult result_;
    std::vector<std::vector<int>> placed_;  // output elements per cell (by centroid)
    std::vector<Vec3> chosen_;              // per cell: the centre of its window in the exemplar
    std::vector<char> has_chosen_;
    std::vector<int> placed_of_type_, window_counts_, window_;
    std::vector<char> dropped_;             // per output element: taken out again by a seam conflict
    double expected_so_far_ = 0.0;
};

void PatchCopier::choose_patch() {
    double min_extent = INFINITY;
    for (int k = 0; k < dim_; ++k)
        if (!layer_.thin[k]) min_extent = std::min(min_extent, in_box_.hi[k] - in_box_.lo[k]);
    if (!std::isfinite(min_extent)) min_extent = 2.0 * params_.radius;
    double patch = options_.patch_size;
    if (!(patch > 0.0)) {
        // The paper's patch is one neighbourhood (2r). An exemplar structured beyond it
        // (clusters, wide gaps, long rows, a lattice) gets patches twice its structure
        // range, so patches hold clusters whole and keep rows in phase: on clustered
        // and multi-class field data this halves the output's PCF error (docs/det.md).
        // Not with an orientation field or thin layers, where each patch is turned by
        // the frame at its cell's centre only.
        patch = 2.0 * params_.radius;
        if (!params_.field.active() && !layer_.any) {
            const double limit = std::min(0.25 * min_extent, 12.0 * params_.spacing);
            if (limit > params_.radius) structure_ = structure_range(ex_, params_.spacing, limit, options_.threads);
            patch = std::max(patch, 2.0 * structure_);
        }
        patch = std::min(patch, 0.5 * min_extent);
    }
    patch_ = std::min(patch, min_extent);
    // Window extent per axis: the patch, the whole layer along thin axes, and with thin
    // axes a diagonal's worth in-plane, since a turned layer crosses an axis-aligned
    // output cell along up to sqrt(dim) times its side.
    for (int k = 0; k < dim_; ++k) {
        const double extent = in_box_.hi[k] - in_box_.lo[k];
        window_size_[k] =
            layer_.thin[k] ? extent : std::min(extent, layer_.any ? patch_ * std::sqrt(double(dim_)) : patch_);
    }
    window_half_ = window_size_ * 0.5;
    window_reach_ = 0.5 * norm(window_size_);  // centre to corner
}

void PatchCopier::prepare() {
    choose_patch();
    // The cells are those of a lattice anchored at the world origin, and each cell's draws
    // are keyed by its lattice coordinates: the same seed gives the same cell the same
    // windows however large the domain around it is (DESIGN.md, randomness keyed by the world).
    cells_.lo = out_box_.lo;
    cells_.size = patch_;
    for (int k = 0; k < dim_; ++k) {
        const double first = std::floor(out_box_.lo[k] / patch_ + 1e-9);
        if (!(std::abs(first) < 4e18))
            throw Error(ErrorKind::domain, "the output domain " + domain_.describe() +
                                               " is too far from the origin for patches of " + std::to_string(patch_));
        world_cell_[k] = static_cast<std::int64_t>(first);
        cells_.lo[k] = first * patch_;
        cells_.dims[k] = std::max(1, static_cast<int>(std::ceil((out_box_.hi[k] - cells_.lo[k]) / patch_ - 1e-9)));
    }
    if (static_cast<double>(cells_.count()) > 5e7)
        throw Error(ErrorKind::option, "--patch-size is too small for this domain (more than 5e7 patches)");

    in_centers_ = element_centroids(ex_.elements, dim_);
    in_grid_.build(in_centers_, std::max(params_.spacing, patch_ / 4.0), dim_);
    // Seam duplicates: where two patches meet, both may fill the same place. An element
    // copied closer to an already placed one than 3/4 of the closest distance the exemplar
    // shows for that pair of types is such a duplicate and is not copied (exemplars with
    // overlapping elements have closest distance ~0 and lose nothing).
    types_ = static_cast<int>(ex_.types.size());
    min_gap_ = closest_type_pairs(ex_, in_centers_, in_grid_, patch_);
    for (double& g : min_gap_) g = std::isfinite(g) ? kDuplicateShare * g : 0.0;
    // Band around a cell in which the candidate windows are compared with placed elements.
    band_ = std::min(params_.spacing, 0.5 * patch_);

    // Count balance (error diffusion over the raster order). Windows of a clustered or
    // uneven exemplar hold very different counts; the hole filling tops up an output that
    // falls short but nothing takes away from one that overshoots, so random windows alone
    // left outputs up to 30% overfull (redwood at 4x). Each candidate therefore also pays
    // for how far the running count would stray from the exemplar's density over the cells
    // done so far, beyond one cell's worth, at the price of a missing element (cap2) per
    // element, class by class (each class against its own share of the density, so the
    // classes keep their proportions too). Not for layered exemplars, whose cells are not
    // patch-sized along thin axes.
    balance_count_ = !layer_.any;
    for (double d : params_.type_density) density_ += d;  // where the elements are (det/density.hpp)
    share_.assign(types_, 0.0);
    for (int t = 0; t < types_; ++t) share_[t] = density_ > 0.0 ? params_.type_density[t] / density_ : 0.0;
    placed_of_type_.assign(types_, 0);
    window_counts_.assign(types_, 0);

    result_.patch_size = patch_;
    result_.structure_range = structure_;
    Arrangement& out = result_.arrangement;
    out.dimension = dim_;
    out.types = ex_.types;
    out.attribute_names = ex_.attribute_names;
    out.domain = domain_;
    placed_.assign(cells_.count(), {});
    chosen_.assign(cells_.count(), Vec3{});
    has_chosen_.assign(cells_.count(), 0);
}

CellContext PatchCopier::context_of(int c) const {
    CellContext cell;
    cell.cell = c;
    cell.lo = cells_.cell_lo(c);
    const Vec3& clo = cell.lo;
    // The exemplar's count for this cell: density x the cell's measure inside the domain
    // (from a 4^d lattice of probes).
    if (balance_count_) {
        constexpr int per_axis = 4;
        int inside = 0, total = 0;
        for (int z = 0; z < (dim_ == 3 ? per_axis : 1); ++z)
            for (int y = 0; y < per_axis; ++y)
                for (int x = 0; x < per_axis; ++x, ++total)
                    inside += domain_.inside(clo + Vec3{(x + 0.5), (y + 0.5), dim_ == 3 ? (z + 0.5) : 0.0} *
                                                       (patch_ / per_axis));
        cell.expected = density_ * std::pow(patch_, dim_) * inside / total;
    }
    const Arrangement& out = result_.arrangement;
    for_each_earlier_neighbor(cells_, c, dim_, [&](int nb) {
        for (int e : placed_[nb]) {
            if (dropped_[e]) continue;
            const Vec3& p = out.elements[e].position;
            bool near = true;
            for (int k = 0; k < dim_; ++k) near = near && p[k] >= clo[k] - band_ && p[k] <= clo[k] + patch_ + band_;
            if (near) cell.band_elements.push_back(e);
        }
    });
    // Probes of the cell and its band for boundary-occupancy similarity: only cells that
    // touch the output boundary need them (elsewhere every window agrees).
    constexpr int per_axis = 5;
    const double step = (patch_ + 2.0 * band_) / (per_axis - 1);
    bool touches_boundary = false;
    for (int z = 0; z < (dim_ == 3 ? per_axis : 1); ++z)
        for (int y = 0; y < per_axis; ++y)
            for (int x = 0; x < per_axis; ++x) {
                const Vec3 q = clo - Vec3{band_, band_, dim_ == 3 ? band_ : 0.0} +
                               Vec3{x * step, y * step, dim_ == 3 ? z * step : 0.0};
                cell.probes.push_back(q);
                touches_boundary = touches_boundary || !domain_.inside(q);
            }
    if (!touches_boundary) cell.probes.clear();
    return cell;
}

core::KeyedRng PatchCopier::cell_rng(int c) const {
    const std::int64_t x = world_cell_[0] + c % cells_.dims[0];
    const std::int64_t y = world_cell_[1] + (c / cells_.dims[0]) % cells_.dims[1];
    const std::int64_t z = world_cell_[2] + c / (cells_.dims[0] * cells_.dims[1]);
    return core::KeyedRng(options_.seed, core::Purpose::patch_choice,
                          core::mix64(static_cast<std::uint64_t>(x)) ^ static_cast<std::uint64_t>(y),
                          static_cast<std::uint64_t>(z));
}

Vec3 PatchCopier::random_centre(const CellContext& cell, int j) const {
    Vec3 origin = in_box_.lo;
    for (int k = 0; k < dim_; ++k) {
        const double span = (in_box_.hi[k] - in_box_.lo[k]) - window_size_[k];
        origin[k] += span > 0.0 ? span * cell_rng(cell.cell).uniform(static_cast<std::uint64_t>(j) * 3 + k) : 0.0;
        // With floor constraints the exemplar's sides are physical (a floor, walls): a
        // cell on a side of the output's bounds takes its window flush with the same
        // side of the exemplar, so boundary layers line up. (Without them the exemplar
        // is a window cut from a larger pattern and any window is as good.)
        if (params_.field.active() || !params_.floor_constraints) continue;
        if (cell.lo[k] <= out_box_.lo[k]) {
            origin[k] = in_box_.lo[k];
        } else if (cell.lo[k] + patch_ >= out_box_.hi[k]) {
            const double flush = in_box_.hi[k] - (out_box_.hi[k] - cell.lo[k]);
            if (flush >= in_box_.lo[k]) origin[k] = flush;
        }
    }
    return origin + window_half_;
}

// The candidate windows of a cell: first the continuations of its placed neighbours'
// windows (the exemplar region next to the one a neighbour copied, where it fits in the
// exemplar: a seam there is no seam at all, which keeps lattices and rows in phase and
// random patterns' statistics intact), then `tries` random windows.
std::vector<Vec3> PatchCopier::candidate_centres(const CellContext& cell, int tries) const {
    std::vector<Vec3> centres;
    if (!params_.field.active() && !layer_.any)
        for_each_earlier_neighbor(cells_, cell.cell, dim_, [&](int nb) {
            if (!has_chosen_[nb]) return;
            const Vec3 centre = chosen_[nb] + (cell.lo - cells_.cell_lo(nb));
            bool fits = true;
            for (int k = 0; k < dim_; ++k)
                fits = fits && centre[k] - window_half_[k] >= in_box_.lo[k] - 1e-9 &&
                       centre[k] + window_half_[k] <= in_box_.hi[k] + 1e-9;
            if (fits) centres.push_back(centre);
        });
    for (int j = 0; j < tries; ++j) centres.push_back(random_centre(cell, j));
    return centres;
}

// How badly a window agrees with what is placed around the cell (lower is better).
double PatchCopier::score(const PatchMap& map, const CellContext& cell) {
    const Arrangement& out = result_.arrangement;
    const double cap2 = params_.cap2;
    const Vec3& clo = cell.lo;
    double score = 0.0;
    // Placed output elements should find an input element of their type where they sit.
    for (int e : cell.band_elements) {
        const Vec3 q = map.to_input(out.elements[e].position);
        const int type = out.elements[e].type;
        const int hit = in_grid_.nearest(q, params_.spacing, [&](int i) { return ex_.elements[i].type == type; });
        score += hit >= 0 ? std::min(cap2, squared_norm(in_centers_[hit] - q)) : cap2;
    }
    // Input elements that would land in already placed cells should find a placed element.
    in_grid_.for_each_within(map.in_center, window_reach_ + band_ * std::sqrt(static_cast<double>(dim_)), [&](int i, double) {
        const Vec3 q = map.to_output(in_centers_[i]);
        bool in_band = true, in_cell = true;
        for (int k = 0; k < dim_; ++k) {
            in_band = in_band && q[k] >= clo[k] - band_ && q[k] <= clo[k] + patch_ + band_;
            in_cell = in_cell && q[k] >= clo[k] && q[k] < clo[k] + patch_;
        }
        if (!in_band || in_cell) return;
        const int placed_cell = cells_.index_of(q, dim_);
        if (placed_cell < 0 || placed_cell >= cell.cell) return;  // lands outside, or on a cell not placed yet
        double d2 = cap2;
        for (int e : cell.band_elements)
            if (out.elements[e].type == ex_.elements[i].type) d2 = std::min(d2, squared_norm(out.elements[e].position - q));
        score += d2;
    });
    // Section 4.1: prefer input patches whose boundary occupancy resembles the output's
    // here (a probe inside one domain but outside the other costs like a missing element).
    for (const Vec3& q : cell.probes)
        if (domain_.inside(q) != ex_.domain.inside(map.to_input(q))) score += cap2;
    if (balance_count_) {
        window_elements_in_cell(map, clo, window_);
        std::fill(window_counts_.begin(), window_counts_.end(), 0);
        for (int i : window_) ++window_counts_[ex_.elements[i].type];
        for (int t = 0; t < types_; ++t) {
            const double straying = static_cast<double>(placed_of_type_[t] + window_counts_[t]) -
                                    share_[t] * (expected_so_far_ + cell.expected);
            score += cap2 * std::max(0.0, std::abs(straying) - std::max(1.0, share_[t] * cell.expected));
        }
    }
    return score;
}

// Registration of a window onto the band (translation only, a few closest-point steps):
// a random window of a lattice or of rows is rarely in phase with what is placed; shifted
// by the mean offset between the placed elements and their nearest window elements of the
// same type, it is. Kept when it scores better.
void PatchCopier::register_window(PatchMap& map, const CellContext& cell, double& best_score) {
    const Arrangement& out = result_.arrangement;
    PatchMap trial = map;
    for (int step = 0; step < kRegistrationSteps; ++step) {
        Vec3 shift;
        int matched = 0;
        for (int e : cell.band_elements) {
            const Vec3 q = trial.to_input(out.elements[e].position);
            const int type = out.elements[e].type;
            const int hit = in_grid_.nearest(q, 0.5 * params_.spacing, [&](int i) { return ex_.elements[i].type == type; });
            if (hit < 0) continue;
            shift += in_centers_[hit] - q;
            ++matched;
        }
        if (matched < 3) return;
        // With floor constraints, windows are laid flush with the floor (random_centre), and
        // a shift along gravity would lift or sink a floor row off the exemplar's height.
        if (params_.floor_constraints && !params_.field.active()) shift[params_.gravity.axis] = 0.0;
        trial.in_center += shift * (1.0 / matched);
        for (int k = 0; k < dim_; ++k)  // the window stays inside the exemplar
            trial.in_center[k] = std::clamp(trial.in_center[k], in_box_.lo[k] + window_half_[k],
                                            std::max(in_box_.lo[k] + window_half_[k], in_box_.hi[k] - window_half_[k]));
    }
    const double registered = score(trial, cell);
    if (registered < best_score) best_score = registered, map = trial;
}

// The exemplar elements (ascending) whose centroids lie in the window (a box, not the
// ball around it) and land in the cell and the domain: what a window puts in a cell.
void PatchCopier::window_elements_in_cell(const PatchMap& m, const Vec3& clo, std::vector<int>& elements) const {
    elements.clear();
    in_grid_.for_each_within(m.in_center, window_reach_ + 1e-12, [&](int i, double) {
        bool in_window = true;
        for (int k = 0; k < dim_; ++k)
            in_window = in_window && std::abs(in_centers_[i][k] - m.in_center[k]) <= window_half_[k] + 1e-12;
        if (!in_window) return;
        const Vec3 q = m.to_output(in_centers_[i]);
        bool in_cell = true;
        for (int k = 0; k < dim_; ++k) in_cell = in_cell && q[k] >= clo[k] && q[k] < clo[k] + patch_;
        if (in_cell && domain_.inside(q)) elements.push_back(i);
    });
    std::sort(elements.begin(), elements.end());
}

// How far type t is below its share of the count over the cells done so far (relative;
// negative above it).
double PatchCopier::deficit(int t, double expected) const {
    const double want = share_[t] * expected;
    return (want - static_cast<double>(placed_of_type_[t])) / std::max(1.0, want);
}

// Copies the whole elements whose centroid lies in the chosen window (and in the domain).
// A seam conflict (an element closer to a placed one than their duplicate distance) keeps
// the element of the type that is further below its count: the placed ones go when every
// one of them is of a type better served, the new one is not copied otherwise. Without
// this, large elements lose every conflict with the small ones around them (two-class
// outputs kept two thirds of their stones) and the hole filling cannot put them back where
// only small ones fit.
void PatchCopier::copy(const PatchMap& map, const CellContext& cell) {
    Arrangement& out = result_.arrangement;
    const double expected = expected_so_far_ + cell.expected;
    window_elements_in_cell(map, cell.lo, window_);
    std::vector<int> conflicts;
    for (int i : window_) {
        const Vec3 q = map.to_output(in_centers_[i]);
        const Element& src = ex_.elements[i];
        conflicts.clear();
        for_each_earlier_neighbor(cells_, cell.cell, dim_, [&](int nb) {
            for (int e : placed_[nb]) {
                const double gap = min_gap_[src.type * types_ + out.elements[e].type];
                if (!dropped_[e] && gap > 0.0 && squared_norm(out.elements[e].position - q) < gap * gap)
                    conflicts.push_back(e);
            }
        });
        bool replace = !conflicts.empty() && balance_count_;
        for (int e : conflicts) replace = replace && deficit(out.elements[e].type, expected) < deficit(src.type, expected);
        if (!conflicts.empty() && !replace) continue;
        for (int e : conflicts) dropped_[e] = 1, --placed_of_type_[out.elements[e].type];
        const int index_out = append_copy(result_.provenance(), ex_, i, map.rotation,
                                          map.out_center - map.rotation.rotate(map.in_center), dim_);
        dropped_.push_back(0);
        const int placed_cell = cells_.index_of(out.elements.back().position, dim_);
        placed_[placed_cell >= 0 ? placed_cell : cell.cell].push_back(index_out);
        ++placed_of_type_[src.type];
    }
    chosen_[cell.cell] = map.in_center;
    has_chosen_[cell.cell] = 1;
    expected_so_far_ += cell.expected;
}

InitResult PatchCopier::run() {
    prepare();
    const Vec3 half = Vec3{patch_, patch_, dim_ == 3 ? patch_ : 0.0} * 0.5;
    auto last_tick = std::chrono::steady_clock::now();
    for (int c = 0; c < cells_.count(); ++c) {
        // The caller's tick (progress, cancellation) about every 50 ms.
        if (tick_ && std::chrono::steady_clock::now() - last_tick > std::chrono::milliseconds(50)) {
            tick_(c, cells_.count());
            last_tick = std::chrono::steady_clock::now();
        }
        const CellContext cell = context_of(c);
        PatchMap map;
        map.out_center = cell.lo + half;
        map.rotation = params_.field.frame(map.out_center, dim_);
        if (layer_.any) map.out_center = onto_layer(map.out_center, map.rotation, layer_, in_box_, domain_, patch_, dim_);
        // Choose among the candidate windows the one most consistent with the band; the
        // best random one may improve by registration.
        const bool free_choice = cell.band_elements.empty() && cell.probes.empty() && !balance_count_;
        const std::vector<Vec3> centres = candidate_centres(cell, free_choice ? 1 : options_.patch_candidates);
        const int continuations = static_cast<int>(centres.size()) - (free_choice ? 1 : options_.patch_candidates);
        double best_score = INFINITY, best_random = INFINITY;
        PatchMap best = map, random_best = map;
        for (size_t j = 0; j < centres.size(); ++j) {
            map.in_center = centres[j];
            const double s = score(map, cell);
            if (s < best_score) best_score = s, best = map;
            if (static_cast<int>(j) >= continuations && s < best_random) best_random = s, random_best = map;
        }
        if (!cell.band_elements.empty() && best_random < INFINITY) {
            register_window(random_best, cell, best_random);
            if (best_random < best_score) best_score = best_random, best = random_best;
        }
        copy(best, cell);
    }
    std::vector<char> keep(dropped_.size());
    for (size_t e = 0; e < keep.size(); ++e) keep[e] = !dropped_[e];
    keep_only(result_.provenance(), keep);
    if (result_.arrangement.elements.empty())
        throw Error(ErrorKind::domain, "the output domain " + domain_.describe() + " is too small to hold one element");
    return std::move(result_);
}

}  // namespace

InitResult initialize_patches(const Exemplar& exemplar, const InputIndex& /*index*/, const Domain& domain,
                              const Params& params, const DetOptions& options, const InitTick& tick) {
    return PatchCopier(exemplar, domain, params, options, tick).run();
}

}  // namespace tessera::det
