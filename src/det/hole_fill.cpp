// Filling the holes the patch copy leaves (section 4.1 mentions incremental add as
// an alternative initialization; here it completes the patch copy): seams between
// patches leave gaps where their elements did not line up, and duplicates there
// are not copied, so the output can hold fewer elements than the exemplar's
// density asks for. Until the count is reached, a copy of an exemplar element is
// placed at the point of the domain farthest from every element (farthest-point
// insertion over a lattice of candidate points, with lazy updates).
#include <algorithm>
#include <cmath>
#include <queue>

#include "core/rng.hpp"
#include "det/init.hpp"

namespace tessera::det {

namespace {

// A grid of element centroids that grows as elements are inserted.
class GrowingGrid {
public:
    GrowingGrid(const Box& box, double cell, int dim) : lo_(box.lo), cell_(cell), dim_(dim) {
        for (int k = 0; k < 3; ++k)
            dims_[k] = k < dim ? std::max(1, static_cast<int>(std::ceil((box.hi[k] - box.lo[k]) / cell)) + 1) : 1;
        cells_.resize(static_cast<size_t>(dims_[0]) * dims_[1] * dims_[2]);
    }
    void add(const Vec3& p) { cells_[index(p)].push_back(p); }
    // Squared distance to the nearest point, capped at cap2 (searches only that far).
    double nearest2(const Vec3& p, double cap2) const {
        const int reach = static_cast<int>(std::ceil(std::sqrt(cap2) / cell_));
        int c[3];
        coords(p, c);
        double best = cap2;
        for (int z = (dim_ == 3 ? c[2] - reach : 0); z <= (dim_ == 3 ? c[2] + reach : 0); ++z)
            for (int y = c[1] - reach; y <= c[1] + reach; ++y)
                for (int x = c[0] - reach; x <= c[0] + reach; ++x) {
                    if (x < 0 || y < 0 || z < 0 || x >= dims_[0] || y >= dims_[1] || z >= dims_[2]) continue;
                    for (const Vec3& q : cells_[(static_cast<size_t>(z) * dims_[1] + y) * dims_[0] + x]) {
                        Vec3 d = q - p;
                        if (dim_ == 2) d.z = 0.0;
                        best = std::min(best, squared_norm(d));
                    }
                }
        return best;
    }

private:
    void coords(const Vec3& p, int* c) const {
        for (int k = 0; k < 3; ++k)
            c[k] = k < dim_ ? std::clamp(static_cast<int>(std::floor((p[k] - lo_[k]) / cell_)), 0, dims_[k] - 1) : 0;
    }
    size_t index(const Vec3& p) const {
        int c[3];
        coords(p, c);
        return (static_cast<size_t>(c[2]) * dims_[1] + c[1]) * dims_[0] + c[0];
    }
    Vec3 lo_;
    double cell_;
    int dim_;
    int dims_[3] = {1, 1, 1};
    std::vector<std::vector<Vec3>> cells_;
};

}  // namespace

int fill_holes(InitResult& init, const Exemplar& exemplar, const Domain& domain, const Params& params,
               std::uint64_t seed) {
    Arrangement& out = init.arrangement;
    const int dim = params.dimension;
    const double density = static_cast<double>(exemplar.elements.size()) / exemplar.domain.measure();
    const long target = std::lround(density * domain.measure());
    long missing = target - static_cast<long>(out.elements.size());
    if (missing <= 0) return 0;

    const double spacing = params.spacing;
    const Box box = domain.bounds();
    GrowingGrid grid(box, spacing, dim);
    for (const auto& e : out.elements) grid.add(e.position);

    // Candidate points: a lattice of a third of the spacing, inside the domain.
    const double step = spacing / 3.0;
    int steps[3] = {1, 1, 1};
    for (int k = 0; k < dim; ++k) steps[k] = std::max(1, static_cast<int>(std::floor((box.hi[k] - box.lo[k]) / step)));
    std::vector<Vec3> candidates;
    for (int z = 0; z < steps[2]; ++z)
        for (int y = 0; y < steps[1]; ++y)
            for (int x = 0; x < steps[0]; ++x) {
                Vec3 p = box.lo + Vec3{(x + 0.5) * step, (y + 0.5) * step, dim == 3 ? (z + 0.5) * step : 0.0};
                if (dim == 2) p.z = 0.0;
                if (domain.inside(p)) candidates.push_back(p);
            }
    const double cap2 = 4.0 * spacing * spacing;  // holes wider than two spacings rank equal
    std::priority_queue<std::pair<double, int>> heap;  // (distance^2, -index): farthest first, ties by index
    for (size_t i = 0; i < candidates.size(); ++i) heap.emplace(grid.nearest2(candidates[i], cap2), -static_cast<int>(i));

    // An element placed nearer than half a spacing to another is not a hole filled but a new defect.
    const double min_gap2 = 0.25 * spacing * spacing;
    const core::KeyedRng rng(seed, core::Purpose::jitter);
    int added = 0;
    while (missing > 0 && !heap.empty()) {
        const auto [d2, neg] = heap.top();
        heap.pop();
        const Vec3& p = candidates[-neg];
        const double fresh = grid.nearest2(p, cap2);
        if (fresh < d2) {  // an insertion came near since: re-rank
            heap.emplace(fresh, neg);
            continue;
        }
        if (d2 < min_gap2) break;  // no hole left
        const int src_index = static_cast<int>(rng.below(static_cast<std::uint64_t>(added), exemplar.elements.size()));
        const Quat frame = params.field.frame(p, dim);
        append_copy(init, exemplar, src_index, frame, p - frame.rotate(exemplar.elements[src_index].position), dim);
        grid.add(p);
        --missing;
        ++added;
    }
    return added;
}

}  // namespace tessera::det
