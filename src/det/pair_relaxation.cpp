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

// Kernel-smoothed, edge-corrected pair sums of one point set on the relaxation's grid. The
// Gaussian comes from a table (linear interpolation, within 1e-6 of the exact kernel).
struct PairSums {
    static constexpr int kTable = 2048;
    int bins = 0;
    double step = 0.0, bandwidth = 0.0;
    const Domain* domain = nullptr;
    std::vector<double> table;  // exp(-t^2/2) / (sqrt(2 pi) h) for t in [0, kKernelReach]

    bool box = false;            // a box domain: the edge correction in closed form
    Vec3 size;
    double measure = 0.0;
    int dim = 2;

    PairSums(int bins_, double step_, double bandwidth_, const Domain* domain_)
        : bins(bins_), step(step_), bandwidth(bandwidth_), domain(domain_), table(kTable + 2),
          box(domain_->kind() == Domain::Kind::box), size(domain_->bounds().size()), measure(domain_->measure()),
          dim(domain_->dimension()) {
        for (int i = 0; i <= kTable + 1; ++i) {
            const double t = kKernelReach * i / kTable;
            table[i] = std::exp(-0.5 * t * t) / (std::sqrt(2.0 * kPi) * bandwidth);
        }
    }
    double kernel(double t) const {  // |t| in bandwidths
        const double u = std::abs(t) * (kTable / kKernelReach);
        const int i = static_cast<int>(u);
        if (i >= kTable) return 0.0;
        return table[i] + (u - i) * (table[i + 1] - table[i]);
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
        for (int k = lo; k <= hi; ++k) values[k - lo] = weight * kernel((k * step - r) / bandwidth);
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

// Per-thread state of the relaxation: the tile's own changes to the sums and scratch.
struct Worker {
    struct Present {
        int slot = 0, lo = 0, count = 0, at = 0;  // a present pair's bins; `at`: offset into values
    };
    std::vector<double> local, delta;  // slots x bins
    std::vector<Present> present;
    std::vector<double> values;
    std::vector<int> near, touched;
    void add(int at, double x) {
        if (delta[at] == 0.0) touched.push_back(at);
        delta[at] += x;
    }
    void clear_delta() {
        for (int at : touched) delta[at] = 0.0;
        touched.clear();
    }
};

}  // namespace

PairRelaxation::Report PairRelaxation::relax(Arrangement& out, const Domain& domain, const std::vector<char>& held,
                                             int sweeps, std::uint64_t seed, int threads,
                                             const std::function<void(int)>& after_sweep) const {
    Report report;
    if (!applies_ || out.types.size() != static_cast<size_t>(types_) || sweeps <= 0) return report;
    const int dim = out.dimension, n = static_cast<int>(out.elements.size());
    const int slots = types_ * (types_ + 1) / 2;
    std::vector<long> count(types_, 0);
    for (const Element& e : out.elements) ++count[e.type];
    const std::vector<double> f = sum_to_g(count, types_, bins_, step_, dim, domain.measure());
    domain.prepare_overlap(threads);
    const PairSums sums(bins_, step_, bandwidth_, &domain);
    const double reach = r_max_ + kKernelReach * bandwidth_, reach2 = reach * reach;
    std::vector<Vec3> p = element_centroids(out.elements, dim);
    MovingGrid grid(domain.bounds(), reach, dim);
    for (int i = 0; i < n; ++i) grid.insert(i, p[i]);
    // The output's sums, then the error: bins from one bandwidth on, as the metric counts.
    std::vector<double> s(static_cast<size_t>(slots) * bins_, 0.0);
    for (int i = 0; i < n; ++i)
        grid.for_each_near(p[i], [&](int j) {
            const Vec3 d = p[j] - p[i];
            if (j > i && squared_norm(d) <= reach2) sums.add(d, pair_index(out.elements[i].type, out.elements[j].type), 1.0, s);
        });
    const int first = static_cast<int>(std::ceil(bandwidth_ / step_));
    const auto error = [&] {
        double e = 0.0;
        for (size_t at = 0; at < s.size(); ++at)
            if (static_cast<int>(at % bins_) >= first) e += (f[at] * s[at] - target_[at]) * (f[at] * s[at] - target_[at]);
        return e;
    };
    report.before = error();
    // The steps' draws are keyed by the lattice cell of the element's place (so fine that two
    // elements never share one) and the sweep, not by its index.
    const double key_cell = kKeyCellSpacings * spacing_;

    // The change of the sums if element i (type a) moved to q: its present pairs out, new in.
    const auto trial_delta = [&](Worker& w, const Vec3& q, int a) {
        w.clear_delta();
        double v[PairSums::kMaxSpan];
        for (const Worker::Present& pr : w.present)
            for (int m = 0; m < pr.count; ++m) w.add(pr.slot * bins_ + pr.lo + m, -w.values[pr.at + m]);
        for (int j : w.near) {
            const Vec3 d = p[j] - q;
            if (squared_norm(d) > reach2) continue;
            const int pair = pair_index(a, out.elements[j].type);
            if (squared_norm(d) < hard_core_[pair] * hard_core_[pair]) return false;  // closer than the exemplar ever is
            int lo = 0;
            const int c = sums.pair(d, lo, v);
            for (int m = 0; m < c; ++m) w.add(pair * bins_ + lo + m, v[m]);
        }
        return true;
    };
    // One element: the best of kProposals keyed random steps, kept if it lowers the error
    // (against the sums at the start of the colour plus the tile's own changes).
    const auto relax_element = [&](int i, int sweep, Worker& w) {
        if (out.elements[i].locked || (!held.empty() && held[i])) return false;
        const int a = out.elements[i].type;
        double v[PairSums::kMaxSpan];
        w.near.clear();
        w.present.clear();
        w.values.clear();
        grid.for_each_near(p[i], [&](int j) {
            if (j == i) return;
            w.near.push_back(j);
            const Vec3 d = p[j] - p[i];
            if (squared_norm(d) > reach2) return;
            Worker::Present pr;
            pr.slot = pair_index(a, out.elements[j].type);
            pr.at = static_cast<int>(w.values.size());
            pr.count = sums.pair(d, pr.lo, v);
            w.values.insert(w.values.end(), v, v + pr.count);
            w.present.push_back(pr);
        });
        double best_change = 0.0;
        Vec3 best;
        const core::KeyedRng rng(seed, core::Purpose::jitter, core::lattice_key(p[i].x, p[i].y, p[i].z, key_cell),
                                 static_cast<std::uint64_t>(sweep));
        for (int m = 0; m < kProposals; ++m) {
            const std::uint64_t key = static_cast<std::uint64_t>(m);
            Vec3 dir;
            if (dim == 2) {
                const double angle = 2.0 * kPi * rng.uniform(3 * key);
                dir = {std::cos(angle), std::sin(angle), 0.0};
            } else {
                const double z = 2.0 * rng.uniform(3 * key) - 1.0, angle = 2.0 * kPi * rng.uniform(3 * key + 1);
                const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
                dir = {r * std::cos(angle), r * std::sin(angle), z};
            }
            const Vec3 q = p[i] + dir * (kStepSpacings * spacing_ * rng.uniform(3 * key + 2));
            if (!domain.inside(q) || !trial_delta(w, q, a)) continue;
            double change = 0.0;
            for (int at : w.touched) {
                if (at % bins_ < first) continue;
                const double now = f[at] * (s[at] + w.local[at]) - target_[at];
                const double next = now + f[at] * w.delta[at];
                change += next * next - now * now;
            }
            if (change < best_change) best_change = change, best = q;
        }
        if (!(best_change < 0.0)) return false;
        trial_delta(w, best, a);  // the scratch holds the last proposal's: the best one again
        for (int at : w.touched) w.local[at] += w.delta[at];
        grid.move(i, p[i], best);
        const Vec3 shift = best - p[i];
        p[i] = best;
        Element& el = out.elements[i];
        el.position += shift;
        out.samples[el.first_sample].p += shift;
        return true;
    };

    // Parallel sweeps that give the same result for any thread count: square tiles three
    // grid cells (three reaches) wide, coloured 2 x 2 (x 2): the tiles of one colour are a
    // tile apart, so their elements never see each other or each other's grid cells; they
    // are relaxed at once, each against the sums at the start of the colour plus its own
    // changes, and the changes are added in tile order afterwards.
    const Box box = domain.bounds();
    const double tile = 3.0 * reach;
    int tiles[3] = {1, 1, 1};
    for (int k = 0; k < dim; ++k) tiles[k] = std::max(1, static_cast<int>(std::ceil(box.size()[k] / tile)));
    const int colours = dim == 2 ? 4 : 8;
    std::vector<Worker> workers(core::resolve_threads(threads));
    for (Worker& w : workers) w.delta.assign(s.size(), 0.0);
    std::vector<std::vector<int>> members(static_cast<size_t>(tiles[0]) * tiles[1] * tiles[2]);
    std::vector<std::vector<double>> changes;
    std::vector<int> moved;
    for (int sweep = 0; sweep < sweeps; ++sweep) {
        for (auto& m : members) m.clear();
        for (int i = 0; i < n; ++i) {
            int c[3] = {0, 0, 0};
            for (int k = 0; k < dim; ++k) c[k] = std::clamp(static_cast<int>((p[i][k] - box.lo[k]) / tile), 0, tiles[k] - 1);
            members[(static_cast<size_t>(c[2]) * tiles[1] + c[1]) * tiles[0] + c[0]].push_back(i);
        }
        for (int colour = 0; colour < colours; ++colour) {
            std::vector<int> active;
            for (size_t t = 0; t < members.size(); ++t) {
                const int x = static_cast<int>(t % tiles[0]), y = static_cast<int>((t / tiles[0]) % tiles[1]),
                          z = static_cast<int>(t / (static_cast<size_t>(tiles[0]) * tiles[1]));
                if ((x % 2) + 2 * (y % 2) + 4 * (z % 2) == colour && !members[t].empty()) active.push_back(static_cast<int>(t));
            }
            const int count_active = static_cast<int>(active.size());
            changes.assign(count_active, {});
            moved.assign(count_active, 0);
            core::parallel_for(count_active, static_cast<int>(workers.size()), [&](int begin, int end, int thread) {
                Worker& w = workers[thread];
                for (int t = begin; t < end; ++t) {
                    w.local.assign(s.size(), 0.0);
                    for (int i : members[active[t]]) moved[t] += relax_element(i, sweep, w);
                    changes[t] = w.local;
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
