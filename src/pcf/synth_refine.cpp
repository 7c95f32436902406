// PCF synthesis, refinement (Eq. 4 to 6): each element moves along the descent direction
// of the error sum_k (PCF_k - target_k)^2 of its class's PCFs, by the one trial distance of
// {1e-1, ..., 1e-5} r_max that lowers the error most (none if none does), searched from
// the distance that worked for it last time.
//
// Parallel sweeps without changing results: the domain is cut into square tiles at least
// half as wide as the reach of a pair within the class plus the largest moves, coloured
// 3 x 3 (two tiles of one colour are two tiles apart); the tiles of one colour are refined
// at the same time, each against the PCF sums at the start of the colour plus its own
// changes (its elements one after the other, in order), and the changes are added in tile
// order afterwards. Elements of two tiles of one colour never see each other, so the
// result is the same for any number of threads (one thread runs the same schedule).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <iterator>
#include <limits>
#include <numeric>

#include "core/parallel.hpp"
#include "pcf/synth_steps.hpp"

namespace tessera::pcf {

namespace {

// How far a move may lift an element's individual PCF above the upper envelope (relative
// to the envelope, as Eq. 11), unless it is already further above.
constexpr double kMoveTolerance = 0.25;
// How far a move may drop it below the lower envelope, unless it is already further below.
// Bins with a lower envelope above 0 are few (configurations every exemplar element has),
// so a tight bound there costs the descent little; a tight upper bound does (5% there
// raised the relative PCF error of the dense ecosystem from 0.019 to 0.028).
constexpr double kLowerTolerance = 0.05;

// A local refinement (outlier rounds) moves the elements within this many r_max of the
// re-placed ones (beyond contact): their first rings of neighbours.
constexpr double kLocalReach = 2.0;

// The refinement's stall test looks at the lowest error over this many sweeps.
constexpr size_t kStallSweeps = 10;

struct Neighbour {
    int slot = 0;    // which of the class's terms
    int index = 0;   // the element
    double x = 0.0, slope = 0.0;
    double weight = 0.0;  // 1 / c_i(d) + 1 / c_j(d) (within a class) or 1 / c_i(d), now
    Vec3 unit;            // from the neighbour towards the element
    State::Span span;
};

struct RefineScratch {
    std::vector<Neighbour> near;
    std::vector<double> old, trial, best;  // slots x bins: the element's share of the sums
    std::vector<double> near_sum;          // slots x bins: its individual kernel sums
    std::vector<double> weight;            // slots x bins: (mean - target) * norm now
    std::vector<char> within;              // per slot
    std::vector<int> old_lo, old_hi, trial_lo, trial_hi, best_lo, best_hi;
    CircleProfile profile, best_profile;   // boundary corrections at trial positions
};

// max over the class's PCFs and bins of (individual - upper) / max(upper, floor), >= 0.
double upper_excess(const State& s, int c, const double* raw, const std::vector<int>& lo, const std::vector<int>& hi) {
    const std::vector<int>& ts = s.class_terms[c];
    double v = 0.0;
    for (size_t slot = 0; slot < ts.size(); ++slot) {
        const Term& T = s.terms[ts[slot]];
        const double* r = raw + slot * s.bins;
        for (int k = lo[slot]; k <= hi[slot]; ++k) v = std::max(v, (T.ind_norm[k] * r[k] - T.upper[k]) * T.inv_upper[k]);
    }
    return v;
}

// max over the class's PCFs and bins of (lower - individual) / max(lower, floor), >= 0
// (only bins with a lower envelope above 0 can count).
double lower_shortfall(const State& s, int c, const double* raw) {
    const std::vector<int>& ts = s.class_terms[c];
    double v = 0.0;
    for (size_t slot = 0; slot < ts.size(); ++slot) {
        const Term& T = s.terms[ts[slot]];
        const double* r = raw + slot * s.bins;
        for (int k = T.lower_lo; k <= T.lower_hi; ++k) v = std::max(v, (T.lower[k] - T.ind_norm[k] * r[k]) * T.inv_lower[k]);
    }
    return v;
}

// The pairs of an element of radius r at q (boundary correction `profile`): their share of
// the sums into `into`, the element's individual kernel sums into sc.near_sum (slots x bins);
// returns how far its individual PCFs rise above the upper envelopes (Eq. 11's upper term).
double pairs_at(const State& s, int c, const Vec3& q, double r, CircleProfile& profile, RefineScratch& sc,
                std::vector<double>& into, std::vector<int>& lo_out, std::vector<int>& hi_out) {
    const int bins = s.bins;
    std::fill(into.begin(), into.end(), 0.0);
    std::fill(sc.near_sum.begin(), sc.near_sum.end(), 0.0);
    std::fill(lo_out.begin(), lo_out.end(), bins);
    std::fill(hi_out.begin(), hi_out.end(), -1);
    for (const Neighbour& nb : sc.near) {
        const Elem& o = s.elems[nb.index];
        const double d = s.distance(q, o.p);
        const PairDistance pd = s.pair(d, r, o.r);
        if (pd.x > s.x_limit) continue;
        const State::Span sp = s.kernel_span(pd.x);
        if (sp.n == 0) continue;
        const double wi = s.weight(profile, d);
        const double w = sc.within[nb.slot] ? wi + s.weight(s.profiles[nb.index], d) : wi;
        const size_t at = static_cast<size_t>(nb.slot) * bins + sp.lo;
        double* acc = &into[at];
        double* raw = &sc.near_sum[at];
        for (int m = 0; m < sp.n; ++m) {
            const double v = sp.value(m);
            acc[m] += w * v;
            raw[m] += wi * v;
        }
        lo_out[nb.slot] = std::min(lo_out[nb.slot], sp.lo);
        hi_out[nb.slot] = std::max(hi_out[nb.slot], sp.lo + sp.n - 1);
    }
    return upper_excess(s, c, sc.near_sum.data(), lo_out, hi_out);
}

// Refines element i; `local` holds this tile's changes to the sums (slots x bins).
// Returns the distance moved.
double refine_element(State& s, int i, double* local, RefineScratch& sc) {
    Elem& e = s.elems[i];
    const std::vector<int>& ts = s.class_terms[e.cls];
    const int slots = static_cast<int>(ts.size());
    const int bins = s.bins;
    const double margin = 2.0 * kMaxMove * s.r_max;
    const CircleProfile& own = s.profiles[i];

    sc.near.clear();
    sc.within.resize(slots);
    for (int slot = 0; slot < slots; ++slot) {
        const Term& T = s.terms[ts[slot]];
        sc.within[slot] = T.within;
        s.for_each_near(T.parent, e.p, T.reach + margin, [&](int j) {
            if (j != i) {
                Neighbour nb;
                nb.slot = slot;
                nb.index = j;
                sc.near.push_back(nb);
            }
            return true;
        });
    }
    const size_t total = static_cast<size_t>(slots) * bins;
    sc.old.assign(total, 0.0);
    sc.near_sum.assign(total, 0.0);
    sc.trial.resize(total);
    sc.best.resize(total);
    sc.weight.resize(total);
    sc.old_lo.assign(slots, bins);
    sc.old_hi.assign(slots, -1);
    sc.trial_lo.resize(slots);
    sc.trial_hi.resize(slots);

    // The pairs now: their kernels and the element's share of the sums.
    for (Neighbour& nb : sc.near) {
        const Elem& o = s.elems[nb.index];
        const double dx = e.p.x - o.p.x, dy = e.p.y - o.p.y;
        const double d = std::sqrt(dx * dx + dy * dy);
        const PairDistance pd = s.pair(d, e.r, o.r);
        nb.x = pd.x;
        nb.slope = pd.slope;
        nb.unit = d > 0.0 ? Vec3{dx / d, dy / d, 0.0} : Vec3{};
        nb.span = pd.x > s.x_limit ? State::Span{} : s.kernel_span(pd.x);
        const State::Span& sp = nb.span;
        if (sp.n == 0) continue;
        const double wi = s.weight(own, d);
        nb.weight = sc.within[nb.slot] ? wi + s.weight(s.profiles[nb.index], d) : wi;
        const size_t at = static_cast<size_t>(nb.slot) * bins + sp.lo;
        double* old = &sc.old[at];
        double* raw = &sc.near_sum[at];
        for (int m = 0; m < sp.n; ++m) {
            old[m] += nb.weight * sp.value(m);
            raw[m] += wi * sp.value(m);
        }
        sc.old_lo[nb.slot] = std::min(sc.old_lo[nb.slot], sp.lo);
        sc.old_hi[nb.slot] = std::max(sc.old_hi[nb.slot], sp.lo + sp.n - 1);
    }
    // Variance-aware moves (section 5.1 applied to refinement): a move may not take the
    // element's individual PCFs further outside their envelopes than they are now, beyond
    // the tolerances: above the upper ones (refinement would push elements onto each
    // other) or below the lower ones (it would pull them out of configurations every
    // exemplar element has, such as a glass touching its plate).
    const double excess_limit = std::max(kMoveTolerance, upper_excess(s, e.cls, sc.near_sum.data(), sc.old_lo, sc.old_hi));
    const double shortfall_limit = std::max(kLowerTolerance, lower_shortfall(s, e.cls, sc.near_sum.data()));
    // Separations from unrelated classes: a move may not take the element further inside.
    const double separation_limit = s.separation_violation(e.cls, e.p, e.r);
    for (int slot = 0; slot < slots; ++slot) {
        const Term& T = s.terms[ts[slot]];
        const double* loc = local + static_cast<size_t>(slot) * bins;
        double* wgt = &sc.weight[static_cast<size_t>(slot) * bins];
        for (int k = 0; k < bins; ++k) wgt[k] = (T.norm[k] * (T.sum[k] + loc[k]) - T.target[k]) * T.norm[k];
    }
    // dE/dP_i = sum_j dE/dx_ij * slope_ij * unit_ij, with (Eq. 6, constant factors dropped)
    // dE/dx_ij ~ sum_k (PCF_k - target_k) norm_k (1/c_i + 1/c_j) k_sigma(x_k - x_ij) (x_k - x_ij)
    // (the corrections are steps in d, flat almost everywhere).
    Vec3 gradient;
    for (const Neighbour& nb : sc.near) {
        const State::Span& sp = nb.span;
        if (sp.n == 0 || nb.slope == 0.0) continue;
        const double* wgt = &sc.weight[static_cast<size_t>(nb.slot) * bins + sp.lo];
        const double t0 = s.axis.x(sp.lo) - nb.x;
        double w = 0.0;
        for (int m = 0; m < sp.n; ++m) w += wgt[m] * sp.value(m) * (t0 + m * s.axis.step);
        gradient += nb.unit * (w * nb.weight * nb.slope);
    }
    const double length = norm(gradient);
    if (!(length > 0.0) || !std::isfinite(length)) return 0.0;
    const Vec3 direction = gradient * (-1.0 / length);

    // The trial moves; the single best one is kept. Each trial gets the boundary
    // correction at its position; a trial that leaves the region to fill (the domain,
    // unless fixed elements hold part of it) or rises above the envelopes is not a candidate.
    constexpr int kSteps = static_cast<int>(std::size(kTrialSteps));
    double best_change = 0.0, best_step = 0.0;
    int best_index = -1;
    const auto trial = [&](int index) {
        const double step = kTrialSteps[index];
        const Vec3 q = e.p + direction * (step * s.r_max);
        if (!s.fill->inside(q)) return kInfinity;
        if (s.separation_violation(e.cls, q, e.r) > separation_limit) return kInfinity;
        s.begin_profile(q, sc.profile);
        const double excess = pairs_at(s, e.cls, q, e.r, sc.profile, sc, sc.trial, sc.trial_lo, sc.trial_hi);
        if (excess > excess_limit) return kInfinity;
        if (lower_shortfall(s, e.cls, sc.near_sum.data()) > shortfall_limit) return kInfinity;
        double change = 0.0;
        for (int slot = 0; slot < slots; ++slot) {
            const Term& T = s.terms[ts[slot]];
            const size_t base = static_cast<size_t>(slot) * bins;
            const double* loc = local + base;
            const int lo = std::min(sc.old_lo[slot], sc.trial_lo[slot]);
            const int hi = std::max(sc.old_hi[slot], sc.trial_hi[slot]);
            for (int k = lo; k <= hi; ++k) {
                const double now = T.norm[k] * (T.sum[k] + loc[k]) - T.target[k];
                const double next = now + T.norm[k] * (sc.trial[base + k] - sc.old[base + k]);
                change += next * next - now * now;
            }
        }
        if (change < best_change) {
            best_change = change;
            best_step = step;
            best_index = index;
            std::swap(sc.trial, sc.best);
            std::swap(sc.profile, sc.best_profile);
            sc.best_lo = sc.trial_lo;
            sc.best_hi = sc.trial_hi;
        }
        return change;
    };
    // Along a line the error is close to a parabola in the distance, so over the trial
    // distances it falls, then rises. The search starts at the distance that worked for
    // this element last time and walks towards larger distances while they do better
    // (if that one lowered the error) and towards smaller ones otherwise, stopping at the
    // first that does worse than the best so far: the best trial, in about two or three.
    const int start = e.hint;
    if (trial(start) < 0.0) {
        for (int k = start - 1; k >= 0 && best_index == k + 1; --k) trial(k);
        if (best_index == start)
            for (int k = start + 1; k < kSteps && best_index == k - 1; ++k) trial(k);
    } else {
        for (int k = start + 1; k < kSteps; ++k) {
            const int before = best_index;
            trial(k);
            if (before >= 0 && best_index == before) break;  // past the best
        }
    }
    if (best_step == 0.0) return 0.0;
    e.hint = best_index;

    for (int slot = 0; slot < slots; ++slot) {
        const size_t base = static_cast<size_t>(slot) * bins;
        const int lo = std::min(sc.old_lo[slot], sc.best_lo[slot]);
        const int hi = std::max(sc.old_hi[slot], sc.best_hi[slot]);
        for (int k = lo; k <= hi; ++k) local[base + k] += sc.best[base + k] - sc.old[base + k];
    }
    // The new position with its correction (built: others read it as a neighbour's).
    if (!sc.best_profile.built) s.build_profile(sc.best_profile);
    e.p = sc.best_profile.p;
    std::swap(s.profiles[i], sc.best_profile);
    return best_step * s.r_max;
}

}  // namespace

double local_reach(const State& s, int c) {
    const double r = s.members[c].empty() ? 0.0 : s.elems[s.members[c].front()].r;  // largest first
    return kLocalReach * s.r_max + 2.0 * r;
}

RefineReport refine(State& s, int c, const std::vector<int>& elements, int max_iterations, double convergence, double stall,
                    int threads, const std::function<void(double)>& on_sweep) {
    RefineReport report;
    if (elements.empty() || max_iterations <= 0) return report;
    const std::vector<int>& ts = s.class_terms[c];
    const int slots = static_cast<int>(ts.size());
    const int bins = s.bins;
    if (slots == 0) return report;

    const Box b = s.domain.bounds();
    const double w = b.hi.x - b.lo.x, h = b.hi.y - b.lo.y;
    // Only pairs within the class move together: its own PCF's reach sets the tiles.
    double within_reach = 0.0;
    for (int t : ts)
        if (s.terms[t].within) within_reach = std::max(within_reach, s.terms[t].reach);
    constexpr int period = 3;
    const double tile = (within_reach + 2.5 * kMaxMove * s.r_max) / (period - 1);
    const int tx = std::max(1, static_cast<int>(std::floor(w / tile)));
    const int ty = std::max(1, static_cast<int>(std::floor(h / tile)));
    const double tw = w / tx, th = h / ty;
    std::vector<RefineScratch> scratch(std::max(1, threads));

    std::vector<double> energies;  // after each sweep, for the stall test
    double best_energy = std::numeric_limits<double>::infinity();
    State::Snapshot best;  // the class at its lowest error so far
    for (int sweep = 0; sweep < max_iterations; ++sweep) {
        // Tiles by the positions at the start of the sweep, elements in the given order.
        std::vector<std::vector<int>> tiles(static_cast<size_t>(tx) * ty);
        for (int i : elements) {
            const Vec3& p = s.elems[i].p;
            const int x = std::clamp(static_cast<int>(std::floor((p.x - b.lo.x) / tw)), 0, tx - 1);
            const int y = std::clamp(static_cast<int>(std::floor((p.y - b.lo.y) / th)), 0, ty - 1);
            tiles[static_cast<size_t>(y) * tx + x].push_back(i);
        }
        double movement = 0.0;
        for (int colour = 0; colour < period * period; ++colour) {
            std::vector<int> active;
            for (int y = colour / period; y < ty; y += period)
                for (int x = colour % period; x < tx; x += period)
                    if (!tiles[static_cast<size_t>(y) * tx + x].empty()) active.push_back(y * tx + x);
            if (active.empty()) continue;
            const int n = static_cast<int>(active.size());
            std::vector<double> local(static_cast<size_t>(n) * slots * bins, 0.0);
            std::vector<double> moved(n, 0.0);
            const auto run_tile = [&](int a, int thread) {
                double* loc = &local[static_cast<size_t>(a) * slots * bins];
                for (int i : tiles[active[a]]) moved[a] += refine_element(s, i, loc, scratch[thread]);
            };
            size_t work = 0;
            for (int a : active) work += tiles[a].size();
            const int use = std::min(threads, n);
            if (use <= 1 || work < 32) {  // starting threads would cost more than it saves
                for (int a = 0; a < n; ++a) run_tile(a, 0);
            } else {
                // Each thread takes the next tile, the most populated first: which thread
                // refines a tile does not change what it computes.
                std::vector<int> by_size(n);
                std::iota(by_size.begin(), by_size.end(), 0);
                std::stable_sort(by_size.begin(), by_size.end(),
                                 [&](int a, int b) { return tiles[active[a]].size() > tiles[active[b]].size(); });
                std::atomic<int> next{0};
                core::parallel_for(use, use, [&](int, int, int thread) {
                    for (int k = next++; k < n; k = next++) run_tile(by_size[k], thread);
                });
            }
            for (int a = 0; a < n; ++a) {
                movement += moved[a];
                for (int slot = 0; slot < slots; ++slot) {
                    std::vector<double>& sum = s.terms[ts[slot]].sum;
                    const double* loc = &local[(static_cast<size_t>(a) * slots + slot) * bins];
                    for (int k = 0; k < bins; ++k) sum[k] += loc[k];
                }
            }
        }
        for (int t : ts) s.refresh(t);
        s.rebuild_grid(c);
        double energy = 0.0;
        for (int t : ts) energy += s.term_error(t);
        ++report.sweeps;
        on_sweep(energy);
        if (energy < best_energy) {
            best_energy = energy;
            best = s.snapshot(c, elements);
        }
        // Converged when the sweep moved the elements by less than convergence x r_max in
        // total (the paper's test), or when the error stalled: over the last kStallSweeps
        // sweeps its lowest value fell by less than a fraction `stall` per sweep. Large
        // classes rarely pass the first: near the error's floor the tiles of a colour each
        // improve the sums they see and together overshoot, so the elements keep moving
        // while the error jitters by a few percent. (A mean movement per element instead
        // stopped small classes while a few of their elements were still settling.)
        energies.push_back(energy);
        const size_t n = energies.size();
        bool stalled = false;
        if (stall > 0.0 && n >= 2 * kStallSweeps) {
            const double before = *std::min_element(energies.begin(), energies.end() - kStallSweeps);
            stalled = before - best_energy <= stall * static_cast<double>(kStallSweeps) * before;
        }
        if (movement < convergence * s.r_max || stalled) {
            report.converged = true;
            break;
        }
    }
    // The class leaves at its lowest error: a jittering last sweep must not cost the fit.
    if (report.sweeps > 0 && best_energy < energies.back()) s.restore(c, best);
    return report;
}

}  // namespace tessera::pcf
