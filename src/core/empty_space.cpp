#include "core/empty_space.hpp"

#include <limits>

#include "core/parallel.hpp"
#include "tessera/error.hpp"

namespace tessera::core {

ObstacleGrid::ObstacleGrid(const Box& box, double cell, int dimension) : lo_(box.lo), cell_(cell), dim_(dimension) {
    for (int k = 0; k < 3; ++k)
        dims_[k] = k < dimension ? std::max(1, static_cast<int>(std::ceil((box.hi[k] - box.lo[k]) / cell)) + 1) : 1;
    cells_.resize(static_cast<size_t>(dims_[0]) * dims_[1] * dims_[2]);
}

void ObstacleGrid::coords(const Vec3& p, int* c) const {
    for (int k = 0; k < 3; ++k)
        c[k] = k < dim_ ? std::clamp(static_cast<int>(std::floor((p[k] - lo_[k]) / cell_)), 0, dims_[k] - 1) : 0;
}

void ObstacleGrid::add(const Vec3& p, double rim, int tag) {
    int c[3];
    coords(p, c);
    Vec3 q = p;
    if (dim_ == 2) q.z = 0.0;
    cells_[(static_cast<size_t>(c[2]) * dims_[1] + c[1]) * dims_[0] + c[0]].push_back({q, rim, tag});
    max_rim_ = std::max(max_rim_, rim);
}

template <class Fn>
void ObstacleGrid::for_each_near(const Vec3& at, double reach, Fn&& fn) const {
    const int r = static_cast<int>(std::ceil(reach / cell_));
    int c[3];
    coords(at, c);
    for (int z = (dim_ == 3 ? std::max(0, c[2] - r) : 0); z <= (dim_ == 3 ? std::min(dims_[2] - 1, c[2] + r) : 0); ++z)
        for (int y = std::max(0, c[1] - r); y <= std::min(dims_[1] - 1, c[1] + r); ++y)
            for (int x = std::max(0, c[0] - r); x <= std::min(dims_[0] - 1, c[0] + r); ++x)
                for (const Obstacle& o : cells_[(static_cast<size_t>(z) * dims_[1] + y) * dims_[0] + x]) {
                    Vec3 d = o.p - at;
                    if (dim_ == 2) d.z = 0.0;
                    fn(o, norm(d));
                }
}

double ObstacleGrid::clearance(const Vec3& at, double cap) const {
    double best = cap;
    for_each_near(at, cap + max_rim_, [&](const Obstacle& o, double d) { best = std::min(best, d - o.rim); });
    return best;
}

void ObstacleGrid::nearest_by_tag(const Vec3& at, int tags, double cap, std::vector<double>& out) const {
    out.assign(tags, cap);
    for_each_near(at, cap, [&](const Obstacle& o, double d) {
        if (o.tag >= 0 && o.tag < tags) out[o.tag] = std::min(out[o.tag], d);
    });
}

namespace {

// The best lattice point (ties: lowest index) refined by a pattern search, with every
// clearance searched up to `cap`.
EmptyBall largest_within(const ObstacleGrid& grid, const Domain& domain, int dimension, double step, const int* n,
                         double cap, int threads) {
    const Box box = domain.bounds();
    const auto centre = [&](long i) {
        const long row = i / n[0];
        return box.lo + Vec3{(i % n[0] + 0.5) * step, (row % n[1] + 0.5) * step,
                             dimension == 3 ? (row / n[1] + 0.5) * step : 0.0};
    };
    // The kTop best lattice points (ties: lowest index), each refined by a pattern search:
    // the largest ball's centre need not be near the best lattice point.
    constexpr size_t kTop = 16;
    using Ranked = std::pair<double, long>;  // (-radius, index): sorted best first
    std::vector<std::vector<Ranked>> per_thread(resolve_threads(threads));
    parallel_for(n[2] * n[1], static_cast<int>(per_thread.size()), [&](int begin, int end, int t) {
        std::vector<Ranked>& top = per_thread[t];
        for (long i = static_cast<long>(begin) * n[0]; i < static_cast<long>(end) * n[0]; ++i) {
            const double d = ball_clearance(grid, domain, centre(i), cap);
            if (!(d > 0.0) || (top.size() == kTop && Ranked{-d, i} >= top.back())) continue;
            top.insert(std::upper_bound(top.begin(), top.end(), Ranked{-d, i}), Ranked{-d, i});
            if (top.size() > kTop) top.pop_back();
        }
    });
    std::vector<Ranked> top;
    for (const auto& list : per_thread) top.insert(top.end(), list.begin(), list.end());
    std::sort(top.begin(), top.end());
    if (top.size() > kTop) top.resize(kTop);
    EmptyBall best;
    for (const Ranked& r : top) {
        EmptyBall ball{-r.first, centre(r.second)};
        for (double h = step; h > step * 1e-3; h *= 0.5) {
            bool moved = true;
            for (int guard = 0; moved && guard < 64; ++guard) {
                moved = false;
                for (int k = 0; k < dimension; ++k)
                    for (double sign : {-1.0, 1.0}) {
                        Vec3 c = ball.center;
                        c[k] += sign * h;
                        const double d = ball_clearance(grid, domain, c, cap);
                        if (d > ball.radius) ball = {d, c}, moved = true;
                    }
            }
        }
        if (ball.radius > best.radius) best = ball;
    }
    return best;
}

}  // namespace

EmptyBall largest_empty_ball(const std::vector<Vec3>& points, const std::vector<double>& rims, const Domain& domain,
                             int dimension, double step, int threads) {
    const Box box = domain.bounds();
    int n[3] = {1, 1, 1};
    for (int k = 0; k < dimension; ++k) n[k] = std::max(1, static_cast<int>(std::ceil(box.size()[k] / step)));
    if (static_cast<double>(n[0]) * n[1] * n[2] > 2e8)
        throw Error(ErrorKind::input, "largest empty circle: the domain is too large for its elements");
    ObstacleGrid grid(box, std::max(step * 4.0, 1e-300), dimension);
    for (size_t i = 0; i < points.size(); ++i) grid.add(points[i], rims[i]);
    // Searches reach `cap`; when the largest ball found is that large, the search is redone
    // with twice the cap (a query costs the square or cube of its reach).
    for (double cap = 8.0 * step;; cap *= 2.0) {
        const EmptyBall best = largest_within(grid, domain, dimension, step, n, cap, threads);
        if (best.radius < cap || cap > norm(box.size())) return best;
    }
}

std::vector<Vec3> lattice_inside(const Domain& domain, int dim, double step) {
    const Box box = domain.bounds();
    int n[3] = {1, 1, 1};
    for (int k = 0; k < dim; ++k) n[k] = std::max(1, static_cast<int>(std::floor(box.size()[k] / step)));
    std::vector<Vec3> points;
    for (int z = 0; z < n[2]; ++z)
        for (int y = 0; y < n[1]; ++y)
            for (int x = 0; x < n[0]; ++x) {
                const Vec3 p = box.lo + Vec3{(x + 0.5) * step, (y + 0.5) * step, dim == 3 ? (z + 0.5) * step : 0.0};
                if (domain.inside(p)) points.push_back(p);
            }
    return points;
}

}  // namespace tessera::core
