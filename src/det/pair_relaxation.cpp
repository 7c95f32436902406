#include "det/pair_relaxation.hpp"

#include <algorithm>
#include <cmath>

#include "core/parallel.hpp"
#include "core/rng.hpp"
#include "det/layers.hpp"
#include "det/provenance.hpp"

namespace tessera::det {

namespace {

constexpr int kBins = 50;             // r grid: 0 .. r_max
constexpr double kReachSpacings = 5.0;  // r_max in mean spacings (as `tessera metrics`)
constexpr int kProposals = 3;         // trial steps per element and sweep
constexpr double kStepSpacings = 0.15;  // the largest trial step, in spacings
constexpr double kKeyCellSpacings = 1.0 / 1024.0;  // the lattice keying the steps' draws
constexpr double kKernelReach = 4.0;  // kernel evaluated within this many bandwidths

constexpr double kPi = 3.14159265358979323846;

// A grid over moving points: cells of r_max, points moved between cells as they move.
class MovingGrid {
public:
    MovingGrid(const Box& box, double cell, int dim) : lo_(box.lo), cell_(cell), dim_(dim) {
        for (int k = 0; k < 3; ++k)
            dims_[k] = k < dim ? std::max(1, static_cast<int>(std::ceil(box.size()[k] / cell)) + 1) : 1;
        cells_.resize(static_cast<size_t>(dims_[0]) * dims_[1] * dims_[2]);
    }
    int cell_of(const Vec3& p) const {
        int c[3];
        coords(p, c);
        return (c[2] * dims_[1] + c[1]) * dims_[0] + c[0];
    }
    void insert(int i, const Vec3& p) { cells_[cell_of(p)].push_back(i); }
    void move(int i, const Vec3& from, const Vec3& to) {
        const int a = cell_of(from), b = cell_of(to);
        if (a == b) return;
        auto& v = cells_[a];
        v.erase(std::find(v.begin(), v.end(), i));
        cells_[b].push_back(i);
    }
    template <class Fn>
    void for_each_near(const Vec3& p, Fn&& fn) const {  // the 3^d cells around p
        int c[3];
        coords(p, c);
        for (int z = (dim_ == 3 ? std::max(0, c[2] - 1) : 0); z <= (dim_ == 3 ? std::min(dims_[2] - 1, c[2] + 1) : 0); ++z)
            for (int y = std::max(0, c[1] - 1); y <= std::min(dims_[1] - 1, c[1] + 1); ++y)
                for (int x = std::max(0, c[0] - 1); x <= std::min(dims_[0] - 1, c[0] + 1); ++x)
                    for (int j : cells_[(static_cast<size_t>(z) * dims_[1] + y) * dims_[0] + x]) fn(j);
    }

private:
    void coords(const Vec3& p, int* c) const {
        for (int k = 0; k < 3; ++k)
            c[k] = k < dim_ ? std::clamp(static_cast<int>(std::floor((p[k] - lo_[k]) / cell_)), 0, dims_[k] - 1) : 0;
    }
    Vec3 lo_;
    double cell_;
    int dim_;
    int dims_[3] = {1, 1, 1};
    std::vector<std::vector<int>> cells_;
};

// Kernel-smoothed, edge-corrected pair sums of one point set on the relaxation's grid. A
// pair's Gaussian over the bins it touches comes from a recurrence, two products per bin:
// at the bins' evenly spaced t_k (in bandwidths, delta apart) the kernel is exp(-t_k^2 / 2),
// with exp(-t_{k+1}^2 / 2) = exp(-t_k^2 / 2) q_k and q_{k+1} = q_k exp(-delta^2). The first
// bin's t lies in [-kKernelReach, -kKernelReach + delta) unless it is bin 0, so its two
// starting values come from tables over that interval (linear interpolation, relative error
// under 1e-7); the exp calls they replace were half of the relaxation's time.
struct PairSums {
    static constexpr int kTable = 4096;
    int bins = 0;
    double step = 0.0, bandwidth = 0.0;
    const Domain* domain = nullptr;
    double norm_factor = 0.0;  // 1 / (sqrt(2 pi) h)
    double delta = 0.0;        // the bins' spacing in bandwidths
    double q_step = 0.0;       // exp(-delta^2)
    std::vector<double> start_g, start_q;  // exp(-t^2 / 2), exp(-t delta - delta^2 / 2) at t = -reach + u

    bool box = false;            // a box domain: the edge correction in closed form
    Vec3 size;
    double measure = 0.0;
    int dim = 2;

    PairSums(int bins_, double step_, double bandwidth_, const Domain* domain_)
        : bins(bins_), step(step_), bandwidth(bandwidth_), domain(domain_),
          norm_factor(1.0 / (std::sqrt(2.0 * kPi) * bandwidth_)), delta(step_ / bandwidth_),
          q_step(std::exp(-delta * delta)), start_g(kTable + 2), start_q(kTable + 2),
          box(domain_->kind() == Domain::Kind::box), size(domain_->bounds().size()), measure(domain_->measure()),
          dim(domain_->dimension()) {
        for (int i = 0; i <= kTable + 1; ++i) {
            double g = 0.0, q = 0.0;
            starting_values(-kKernelReach + delta * i / kTable, g, q);
            start_g[i] = g, start_q[i] = q;
        }
    }
    void starting_values(double t, double& g, double& q) const {
        g = std::exp(-0.5 * t * t);
        q = std::exp(-t * delta - 0.5 * delta * delta);
    }
    // |W ∩ (W + d)| (the translation edge correction of spatstat's estimator).
    double overlap(const Vec3& d) const {
        if (!box) return domain->translated_overlap(d);
        double m = 1.0;
        for (int k = 0; k < dim; ++k) m *= std::max(0.0, size[k] - std::abs(d[k]));
        return m;
    }
    // The bins [lo, lo + count) a pair at offset d touches and its value in each; returns count.
    int pair(const Vec3& d, int& lo, double* values) const {
        const double r = norm(d);
        const double weight = measure / std::max(overlap(d), 1e-300);
        lo = std::max(0, static_cast<int>(std::ceil((r - kKernelReach * bandwidth) / step)));
        const int hi = std::min(bins - 1, static_cast<int>(std::floor((r + kKernelReach * bandwidth) / step)));
        const double t = (lo * step - r) / bandwidth;
        double g = 0.0, q = 0.0;
        if (lo == 0) {
            starting_values(t, g, q);
        } else {
            const double u = std::clamp((t + kKernelReach) / delta, 0.0, 1.0) * kTable;
            const int i = static_cast<int>(u);
            const double w = u - i;
            g = start_g[i] + w * (start_g[i + 1] - start_g[i]);
            q = start_q[i] + w * (start_q[i + 1] - start_q[i]);
        }
        g *= weight * norm_factor;
        for (int k = lo; k <= hi; ++k) {
            values[k - lo] = g;
            g *= q;
            q *= q_step;
        }
        return std::max(0, hi - lo + 1);
    }
    // Adds sign x the pair's contribution into sum[slot * bins + k].
    void add(const Vec3& d, int slot, double sign, std::vector<double>& sum) const {
        double v[kMaxSpan];
        int lo = 0;
        const int n = pair(d, lo, v);
        for (int m = 0; m < n; ++m) sum[slot * bins + lo + m] += sign * v[m];
    }
    static constexpr int kMaxSpan = 64;
};

int slot_of(int a, int b, int types) {
    if (a > b) std::swap(a, b);
    return a * types - a * (a - 1) / 2 + (b - a);
}

// g(r_k) = |W| S_k / (S(r_k) P_ab): the factor that turns sums into the pair correlation.
std::vector<double> sum_to_g(const std::vector<long>& count, int types, int bins, double step, int dim, double measure) {
    std::vector<double> f(static_cast<size_t>(types * (types + 1) / 2) * bins, 0.0);
    for (int a = 0; a < types; ++a)
        for (int b = a; b < types; ++b) {
            const double pairs = a == b ? 0.5 * count[a] * (count[a] - 1.0) : static_cast<double>(count[a]) * count[b];
            if (!(pairs > 0.0)) continue;
            for (int k = 1; k < bins; ++k) {
                const double r = k * step;
                const double shell = dim == 2 ? 2.0 * kPi * r : 4.0 * kPi * r * r;
                f[slot_of(a, b, types) * bins + k] = measure / (shell * pairs);
            }
        }
    return f;
}

}  // namespace

int PairRelaxation::pair_index(int a, int b) const { return slot_of(a, b, types_); }

double PairRelaxation::max_step() const { return kStepSpacings * spacing_; }

PairRelaxation::PairRelaxation(const Exemplar& exemplar, const Params& params) {
    // Not for layers: a layer's statistics live in its plane, not in the 3D pair correlation.
    applies_ = !exemplar.has_multi_sample_elements() && exemplar.elements.size() >= 8 && params.spacing > 0.0 &&
               !layer_axes(exemplar.domain.bounds(), exemplar.dimension, params.radius).any;
    if (!applies_) return;
    types_ = static_cast<int>(exemplar.types.size());
    bins_ = kBins;
    spacing_ = params.spacing;
    r_max_ = kReachSpacings * params.spacing;
    step_ = r_max_ / (bins_ - 1);
    bandwidth_ = r_max_ / 40.0;
    std::vector<long> count(types_, 0);
    for (const Element& e : exemplar.elements) ++count[e.type];
    const PairSums sums(bins_, step_, bandwidth_, &exemplar.domain);
    std::vector<double> s(static_cast<size_t>(types_ * (types_ + 1) / 2) * bins_, 0.0);
    const std::vector<Vec3> p = element_centroids(exemplar.elements, exemplar.dimension);
    hard_core_.assign(static_cast<size_t>(types_ * (types_ + 1) / 2), INFINITY);
    for (size_t i = 0; i < p.size(); ++i)
        for (size_t j = i + 1; j < p.size(); ++j) {
            const Vec3 d = p[j] - p[i];
            double& closest = hard_core_[pair_index(exemplar.elements[i].type, exemplar.elements[j].type)];
            closest = std::min(closest, norm(d));
            if (squared_norm(d) > (r_max_ + kKernelReach * bandwidth_) * (r_max_ + kKernelReach * bandwidth_)) continue;
            sums.add(d, pair_index(exemplar.elements[i].type, exemplar.elements[j].type), 1.0, s);
        }
    for (double& d : hard_core_)
        if (!std::isfinite(d)) d = 0.0;  // a type pair the exemplar never shows (a single element)
    const std::vector<double> f = sum_to_g(count, types_, bins_, step_, exemplar.dimension, exemplar.domain.measure());
    target_.resize(s.size());
    for (size_t k = 0; k < s.size(); ++k) target_[k] = f[k] * s[k];
}

namespace {

// What one thread needs to move elements: the sums' shape, the error's factors and its
// scratch. The sums of element i's pairs are dense per class pair of its type (a few times
// 50 bins), which is cheaper than tracking the bins a move touches: every bin is touched.
class Mover {
public:
    struct Shared {
        const PairSums* sums;
        const std::vector<double>* f;       // sums -> g, per slot and bin
        const std::vector<double>* target;  // the exemplar's g
        const std::vector<double>* hard_core;
        const std::vector<std::vector<int>>* slots_of_type;  // type a -> slot of (a, b) for each b
        int bins, first;                                   // first: the first bin the error counts
        double reach2;
    };
    Mover(const Shared& shared, size_t size)  // size: slots x bins
        : local(size, 0.0), sh_(shared), old_(size, 0.0), trial_(size, 0.0), best_(size, 0.0) {}

    std::vector<double> local;  // this tile's changes to the sums since the colour began

    // Gathers element i's neighbours that any step of at most `step` could pair with, and
    // the sums of its present pairs.
    void gather(int i, const std::vector<Vec3>& p, const std::vector<int>& type, double step, const MovingGrid& grid) {
        const double r = std::sqrt(sh_.reach2) + step, r2 = r * r;
        near_.clear();
        grid.for_each_near(p[i], [&](int j) {
            if (j != i && squared_norm(p[j] - p[i]) <= r2) near_.push_back(j);
        });
        a_ = type[i];
        pairs_at(p[i], p, type, old_, false);  // the present place stands whatever its distances
    }
    // The change of the error if the gathered element moved to q; false when q comes closer
    // to a neighbour than the exemplar's closest pair of their types.
    bool change_at(const Vec3& q, const std::vector<Vec3>& p, const std::vector<int>& type,
                   const std::vector<double>& s, double& change) {
        if (!pairs_at(q, p, type, trial_, true)) return false;
        const std::vector<double>& f = *sh_.f;
        const std::vector<double>& target = *sh_.target;
        change = 0.0;
        for (int slot : (*sh_.slots_of_type)[a_])
            for (int k = sh_.first; k < sh_.bins; ++k) {
                const size_t at = static_cast<size_t>(slot) * sh_.bins + k;
                const double now = f[at] * (s[at] + local[at]) - target[at];
                const double next = now + f[at] * (trial_[at] - old_[at]);
                change += next * next - now * now;
            }
        return true;
    }
    void keep_trial() { std::swap(trial_, best_); }
    // Books the kept move (the trial last passed to keep_trial) into `local`.
    void commit() {
        for (int slot : (*sh_.slots_of_type)[a_])
            for (int k = 0; k < sh_.bins; ++k) {
                const size_t at = static_cast<size_t>(slot) * sh_.bins + k;
                local[at] += best_[at] - old_[at];
            }
    }

private:
    // Sums of the pairs element (type a_) would make at q into `out` (its type's slots).
    bool pairs_at(const Vec3& q, const std::vector<Vec3>& p, const std::vector<int>& type, std::vector<double>& out,
                  bool check_hard_core) const {
        for (int slot : (*sh_.slots_of_type)[a_]) std::fill_n(out.begin() + static_cast<long>(slot) * sh_.bins, sh_.bins, 0.0);
        double v[PairSums::kMaxSpan];
        for (int j : near_) {
            const Vec3 d = p[j] - q;
            const double d2 = squared_norm(d);
            if (d2 > sh_.reach2) continue;
            const int slot = (*sh_.slots_of_type)[a_][type[j]];
            const double core = (*sh_.hard_core)[slot];
            if (check_hard_core && d2 < core * core) return false;  // closer than the exemplar ever is
            int lo = 0;
            const int c = sh_.sums->pair(d, lo, v);
            double* row = out.data() + static_cast<size_t>(slot) * sh_.bins + lo;
            for (int m = 0; m < c; ++m) row[m] += v[m];
        }
        return true;
    }
    Shared sh_;
    std::vector<double> old_, trial_, best_;
    std::vector<int> near_;
    int a_ = 0;
};

// A direction drawn from the keyed stream: uniform on the circle (2D) or sphere (3D).
Vec3 random_direction(const core::KeyedRng& rng, std::uint64_t key, int dim) {
    if (dim == 2) {
        const double angle = 2.0 * kPi * rng.uniform(3 * key);
        return {std::cos(angle), std::sin(angle), 0.0};
    }
    const double z = 2.0 * rng.uniform(3 * key) - 1.0, angle = 2.0 * kPi * rng.uniform(3 * key + 1);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(angle), r * std::sin(angle), z};
}

// The tiles of a sweep: square (cubic) tiles three reaches wide, coloured 2 x 2 (x 2), so
// that tiles of one colour are a tile apart and never see each other's elements.
struct SweepTiles {
    SweepTiles(const Box& box, double tile, int dim) : box_(box), tile_(tile), dim_(dim) {
        for (int k = 0; k < dim; ++k) n_[k] = std::max(1, static_cast<int>(std::ceil(box.size()[k] / tile)));
        members.resize(static_cast<size_t>(n_[0]) * n_[1] * n_[2]);
    }
    int colours() const { return dim_ == 2 ? 4 : 8; }
    void assign(const std::vector<Vec3>& p) {
        for (auto& m : members) m.clear();
        for (int i = 0; i < static_cast<int>(p.size()); ++i) {
            int c[3] = {0, 0, 0};
            for (int k = 0; k < dim_; ++k) c[k] = std::clamp(static_cast<int>((p[i][k] - box_.lo[k]) / tile_), 0, n_[k] - 1);
            members[(static_cast<size_t>(c[2]) * n_[1] + c[1]) * n_[0] + c[0]].push_back(i);
        }
    }
    std::vector<int> of_colour(int colour) const {
        std::vector<int> active;
        for (size_t t = 0; t < members.size(); ++t) {
            const int x = static_cast<int>(t % n_[0]), y = static_cast<int>((t / n_[0]) % n_[1]),
                      z = static_cast<int>(t / (static_cast<size_t>(n_[0]) * n_[1]));
            if ((x % 2) + 2 * (y % 2) + 4 * (z % 2) == colour && !members[t].empty()) active.push_back(static_cast<int>(t));
        }
        return active;
    }
    std::vector<std::vector<int>> members;

private:
    Box box_;
    double tile_;
    int dim_;
    int n_[3] = {1, 1, 1};
};

// The kernel sums of every pair of the output closer than the reach, per class pair. Blocks
// of a fixed number of elements are summed in parallel and added in block order, so the
// result does not depend on the thread count.
std::vector<double> output_sums(const std::vector<Vec3>& p, const std::vector<int>& type, const MovingGrid& grid,
                                const PairSums& sums, double reach2, int types, int bins, int threads,
                                const core::Interrupt* interrupt) {
    constexpr int kBlock = 2048;
    const int n = static_cast<int>(p.size()), blocks = (n + kBlock - 1) / kBlock;
    const size_t size = static_cast<size_t>(types * (types + 1) / 2) * bins;
    std::vector<std::vector<double>> part(blocks, std::vector<double>(size, 0.0));
    core::parallel_for(blocks, threads, [&](int begin, int end, int thread) {
        for (int b = begin; b < end; ++b, core::check(interrupt, thread))
            for (int i = b * kBlock; i < std::min(n, (b + 1) * kBlock); ++i)
                grid.for_each_near(p[i], [&](int j) {
                    const Vec3 d = p[j] - p[i];
                    if (j > i && squared_norm(d) <= reach2) sums.add(d, slot_of(type[i], type[j], types), 1.0, part[b]);
                });
    });
    std::vector<double> s(size, 0.0);
    for (const std::vector<double>& block : part)
        for (size_t at = 0; at < size; ++at) s[at] += block[at];
    return s;
}

}  // namespace

PairRelaxation::Report PairRelaxation::relax(Arrangement& out, const Domain& domain, const std::vector<char>& held,
                                             int sweeps, std::uint64_t seed, int threads,
                                             const std::function<void(int)>& after_sweep,
                                             const core::Interrupt* interrupt) const {
    Report report;
    if (!applies_ || out.types.size() != static_cast<size_t>(types_) || sweeps <= 0) return report;
    const int dim = out.dimension, n = static_cast<int>(out.elements.size());
    std::vector<long> count(types_, 0);
    std::vector<int> type(n);
    for (int i = 0; i < n; ++i) ++count[type[i] = out.elements[i].type];
    const std::vector<double> f = sum_to_g(count, types_, bins_, step_, dim, domain.measure());
    domain.prepare_overlap(threads);
    const PairSums sums(bins_, step_, bandwidth_, &domain);
    const double reach = r_max_ + kKernelReach * bandwidth_, reach2 = reach * reach;
    std::vector<Vec3> p = element_centroids(out.elements, dim);
    MovingGrid grid(domain.bounds(), reach, dim);
    for (int i = 0; i < n; ++i) grid.insert(i, p[i]);
    // The output's sums, then the error: bins from one bandwidth on, as the metric counts.
    std::vector<double> s = output_sums(p, type, grid, sums, reach2, types_, bins_, core::resolve_threads(threads), interrupt);
    const int first = static_cast<int>(std::ceil(bandwidth_ / step_));
    const auto error = [&] {
        double e = 0.0;
        for (size_t at = 0; at < s.size(); ++at)
            if (static_cast<int>(at % bins_) >= first) e += (f[at] * s[at] - target_[at]) * (f[at] * s[at] - target_[at]);
        return e;
    };
    report.before = error();
    std::vector<std::vector<int>> slots_of_type(types_);
    for (int a = 0; a < types_; ++a)
        for (int b = 0; b < types_; ++b) slots_of_type[a].push_back(pair_index(a, b));
    const Mover::Shared shared{&sums, &f, &target_, &hard_core_, &slots_of_type, bins_, first, reach2};
    // The steps' draws are keyed by the lattice cell of the element's place (so fine that two
    // elements never share one) and the sweep, not by its index.
    const double key_cell = kKeyCellSpacings * spacing_, largest_step = kStepSpacings * spacing_;

    // One element: the best of kProposals keyed random steps, kept if it lowers the error
    // (against the sums at the start of the colour plus the tile's own changes).
    const auto relax_element = [&](int i, int sweep, Mover& mover) {
        if (out.elements[i].locked || (!held.empty() && held[i])) return false;
        mover.gather(i, p, type, largest_step, grid);
        const core::KeyedRng rng(seed, core::Purpose::jitter, core::lattice_key(p[i].x, p[i].y, p[i].z, key_cell),
                                 static_cast<std::uint64_t>(sweep));
        double best_change = 0.0;
        Vec3 best;
        for (int m = 0; m < kProposals; ++m) {
            const std::uint64_t key = static_cast<std::uint64_t>(m);
            const Vec3 q = p[i] + random_direction(rng, key, dim) * (largest_step * rng.uniform(3 * key + 2));
            double change = 0.0;
            if (!domain.inside(q) || !mover.change_at(q, p, type, s, change)) continue;
            if (change < best_change) best_change = change, best = q, mover.keep_trial();
        }
        if (!(best_change < 0.0)) return false;
        mover.commit();
        grid.move(i, p[i], best);
        const Vec3 shift = best - p[i];
        p[i] = best;
        Element& el = out.elements[i];
        el.position += shift;
        out.samples[el.first_sample].p += shift;
        return true;
    };

    // Parallel sweeps that give the same result for any thread count: the tiles of one
    // colour are relaxed at once, each against the sums at the start of the colour plus its
    // own changes, and the changes are added in tile order afterwards.
    SweepTiles tiles(domain.bounds(), 3.0 * reach, dim);
    std::vector<Mover> movers(core::resolve_threads(threads), Mover(shared, s.size()));
    std::vector<std::vector<double>> changes;
    std::vector<int> moved;
    for (int sweep = 0; sweep < sweeps; ++sweep) {
        tiles.assign(p);
        for (int colour = 0; colour < tiles.colours(); ++colour) {
            const std::vector<int> active = tiles.of_colour(colour);
            const int count_active = static_cast<int>(active.size());
            changes.assign(count_active, {});
            moved.assign(count_active, 0);
            core::parallel_for(count_active, static_cast<int>(movers.size()), [&](int begin, int end, int thread) {
                Mover& mover = movers[thread];
                for (int t = begin; t < end; ++t) {
                    core::check(interrupt, thread);
                    mover.local.assign(s.size(), 0.0);
                    for (int i : tiles.members[active[t]]) moved[t] += relax_element(i, sweep, mover);
                    changes[t] = mover.local;
                }
            });
            for (int t = 0; t < count_active; ++t) {
                for (size_t at = 0; at < s.size(); ++at) s[at] += changes[t][at];
                report.moves += moved[t];
            }
        }
        if (after_sweep) after_sweep(sweep);
    }
    report.after = error();
    return report;
}

}  // namespace tessera::det
