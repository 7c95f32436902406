// PCF synthesis, initialisation: the candidate error of Eq. 11 and Algorithm 1 (dart
// throwing with a threshold relaxed by every rejection, then grid search).
#include <algorithm>
#include <cmath>

#include "core/parallel.hpp"
#include "core/rng.hpp"
#include "pcf/synth_steps.hpp"

namespace tessera::pcf {

namespace {

// The grid search's zoom into its chosen cell: levels, and sub-cells per side.
constexpr int kZoomLevels = 2;
constexpr int kZoom = 4;

}  // namespace

double candidate_error(const State& s, int c, const Vec3& p, double r, double fill, double limit, Scratch& sc) {
    const int bins = s.bins;
    s.begin_profile(p, sc.profile);
    double* R = sc.near_sum.data();
    double* D = sc.near_ref.data();

    // Separations from unrelated classes only grow as pairs are added: checked first.
    double E = s.separation_violation(c, p, r) * s.separation_scale;
    if (E > limit) return kInfinity;
    for (int t : s.class_terms[c]) {
        const Term& T = s.terms[t];
        // The mean term can only grow from base_max (contributions are >= 0).
        if (std::max(E, std::max(T.base_max, 0.0)) > limit) return kInfinity;
        std::fill(R, R + bins, 0.0);
        std::fill(D, D + bins, 0.0);  // stays 0 for a parent edge
        int tlo = bins, thi = -1;
        double a_run = T.base_max, b_run = 0.0;
        const bool complete = s.for_each_near(T.parent, p, T.reach, [&](int j) {
            const Elem& o = s.elems[j];
            const double d = s.distance(p, o.p);
            const PairDistance pd = s.pair(d, r, o.r);
            if (pd.x > s.x_limit) return true;
            const State::Span sp = s.kernel_span(pd.x);
            if (sp.n == 0) return true;
            const double wi = s.weight(sc.profile, d);
            const double wj = T.within ? s.weight(s.profiles[j], d) : 0.0;
            for (int m = 0; m < sp.n; ++m) {
                const double v = sp.value(m);
                R[sp.lo + m] += wi * v;
                D[sp.lo + m] += wj * v;
            }
            tlo = std::min(tlo, sp.lo);
            thi = std::max(thi, sp.lo + sp.n - 1);
            if (limit < kInfinity) {
                // Both the mean term and the upper-envelope term only grow as pairs are
                // added: a lower bound of E that lets a hopeless candidate go early.
                for (int k = sp.lo; k < sp.lo + sp.n; ++k) {
                    a_run = std::max(a_run, (T.norm[k] * (T.sum[k] + R[k] + D[k]) - T.target[k]) * T.inv_target[k]);
                    b_run = std::max(b_run, (T.ind_norm[k] * R[k] - T.upper[k]) * T.inv_upper[k]);
                }
                if (std::max(E, std::max(a_run, 0.0) + b_run) > limit) return false;
            }
            return true;
        });
        if (!complete) return kInfinity;
        double a_max = T.base_max;
        for (int k = tlo; k <= thi; ++k)
            a_max = std::max(a_max, (T.norm[k] * (T.sum[k] + R[k] + D[k]) - T.target[k]) * T.inv_target[k]);
        // The lower envelope of a class's own PCF cannot be reached while the class is
        // still being placed: it counts only once the class is complete.
        const bool use_lower = !T.within || fill >= 1.0;
        double env = 0.0;
        for (int k = 0; k < bins; ++k) {
            const double ind = T.ind_norm[k] * R[k];
            env = std::max(env, (ind - T.upper[k]) * T.inv_upper[k]);
            if (use_lower) env = std::max(env, (T.lower[k] - ind) * T.inv_lower[k]);
        }
        E = std::max(E, std::max(a_max, 0.0) + env);
        if (E > limit) return kInfinity;
    }
    return E;
}

double envelope_violation(const State& s, int i, Scratch& sc) {
    const int bins = s.bins;
    const Elem& e = s.elems[i];
    const CircleProfile& own = s.profiles[i];
    double* R = sc.near_sum.data();
    double v = s.separation_violation(e.cls, e.p, e.r) * s.separation_scale;
    for (int t : s.class_terms[e.cls]) {
        const Term& T = s.terms[t];
        std::fill(R, R + bins, 0.0);
        s.for_each_near(T.parent, e.p, T.reach, [&](int j) {
            if (j == i) return true;
            const Elem& o = s.elems[j];
            const double d = s.distance(e.p, o.p);
            const PairDistance pd = s.pair(d, e.r, o.r);
            if (pd.x > s.x_limit) return true;
            const State::Span sp = s.kernel_span(pd.x);
            const double w = s.weight(own, d);
            for (int m = 0; m < sp.n; ++m) R[sp.lo + m] += w * sp.value(m);
            return true;
        });
        for (int k = 0; k < bins; ++k) {
            const double ind = T.ind_norm[k] * R[k];
            v = std::max(v, (ind - T.upper[k]) * T.inv_upper[k]);
            v = std::max(v, (T.lower[k] - ind) * T.inv_lower[k]);
        }
    }
    return v;
}

InitReport initialise(State& s, int c, const std::vector<int>& elements, const InitSettings& st,
                      const std::function<void()>& tick) {
    InitReport report;
    if (elements.empty()) return report;
    const Box b = s.fill->bounds();
    const double w = b.hi.x - b.lo.x, h = b.hi.y - b.lo.y;
    const core::KeyedRng dart(st.seed, core::Purpose::pcf_dart, static_cast<std::uint64_t>(c),
                              static_cast<std::uint64_t>(st.round));
    std::vector<Scratch> scratch(std::max(1, st.threads), Scratch(s));
    std::uint64_t attempt = 0;  // dart throws of this class (and round): the key of their positions
    int fails = 0;              // successive rejections
    bool grid_mode = st.max_fails <= 0;
    // Draws a dart inside the domain (draws outside it are not candidates: they are skipped).
    const auto draw_inside = [&](Vec3& p) {
        for (int miss = 0; miss < 1000000; ++miss) {
            const std::uint64_t a = attempt++;
            p = {b.lo.x + w * dart.uniform(2 * a), b.lo.y + h * dart.uniform(2 * a + 1), 0.0};
            if (s.fill->inside(p)) return true;
        }
        return false;
    };
    // The grid of the grid search (section 5.2): grid_cells cells along the longer side.
    const double cell_size = std::max(w, h) / st.grid_cells;
    const int nx = std::max(1, static_cast<int>(std::ceil(w / cell_size - 1e-9)));
    const int ny = std::max(1, static_cast<int>(std::ceil(h / cell_size - 1e-9)));
    const int cells = nx * ny;

    for (int i : elements) {
        const double r = s.elems[i].r;
        const double fill = s.count[c] > 0 ? static_cast<double>(s.placed(c)) / s.count[c] : 1.0;
        bool placed = false;
        while (!grid_mode) {
            Vec3 p;
            if (!draw_inside(p)) {  // a domain that covers almost none of its bounds
                grid_mode = true;
                break;
            }
            const double eps = st.epsilon0 + st.epsilon_step * fails;
            // Accept when E < eps: anything not below eps is rejected, so evaluation may stop there.
            const double E = candidate_error(s, c, p, r, fill, std::nextafter(eps, -kInfinity), scratch[0]);
            if (E < eps) {
                s.insert(i, scratch[0].profile);
                fails = 0;
                placed = true;
                break;
            }
            if (++fails >= st.max_fails) grid_mode = true;
        }
        if (!placed) {
            // Grid search: the error at a keyed random point of every cell, the lowest wins,
            // evaluated in parallel; each chunk stops evaluating a cell once it cannot equal
            // the chunk's best, which never changes the set of winners.
            const core::KeyedRng jitter(st.seed, core::Purpose::pcf_grid, static_cast<std::uint64_t>(c),
                                        (static_cast<std::uint64_t>(st.round) << 32) | static_cast<std::uint64_t>(i));
            std::vector<double> error(cells, kInfinity);
            const auto point = [&](int cell) {
                return Vec3{b.lo.x + (cell % nx + jitter.uniform(2 * static_cast<std::uint64_t>(cell))) * cell_size,
                            b.lo.y + (cell / nx + jitter.uniform(2 * static_cast<std::uint64_t>(cell) + 1)) * cell_size,
                            0.0};
            };
            core::parallel_for(cells, st.threads, [&](int begin, int end, int thread) {
                double best = kInfinity;
                for (int cell = begin; cell < end; ++cell) {
                    const Vec3 p = point(cell);
                    if (!s.fill->inside(p)) continue;
                    error[cell] = candidate_error(s, c, p, r, fill, best, scratch[thread]);
                    best = std::min(best, error[cell]);
                }
            });
            // The lowest error; a keyed random one of the cells that share it (E is 0 in
            // every cell where the element fits, and the first of them would be a corner).
            double lowest = kInfinity;
            for (int cell = 0; cell < cells; ++cell) lowest = std::min(lowest, error[cell]);
            int chosen = -1;
            if (lowest < kInfinity) {
                std::vector<int> ties;
                for (int cell = 0; cell < cells; ++cell)
                    if (error[cell] == lowest) ties.push_back(cell);
                chosen = ties[jitter.below(2 * static_cast<std::uint64_t>(cells), ties.size())];
            }
            Vec3 p;
            if (chosen >= 0) {
                p = point(chosen);
                ++report.by_grid;
                // Zoom: the chosen cell again at kZoom x kZoom sub-cells (a keyed random point
                // in each), then the best sub-cell likewise; the lowest error wins (the first
                // in order on ties). One random point per cell rarely lands where a tight
                // configuration needs it (touching or centred on a parent).
                double best = lowest;
                Vec3 corner{b.lo.x + (chosen % nx) * cell_size, b.lo.y + (chosen / nx) * cell_size, 0.0};
                double size = cell_size;
                std::uint64_t key = 2 * static_cast<std::uint64_t>(cells) + 1;  // after the cells' and the tie's
                for (int level = 0; level < kZoomLevels && best > 0.0; ++level) {
                    const double sub = size / kZoom;
                    Vec3 best_corner = corner;
                    for (int k = 0; k < kZoom * kZoom; ++k, key += 2) {
                        const Vec3 at{corner.x + (k % kZoom) * sub, corner.y + (k / kZoom) * sub, 0.0};
                        const Vec3 q{at.x + jitter.uniform(key) * sub, at.y + jitter.uniform(key + 1) * sub, 0.0};
                        if (!s.fill->inside(q)) continue;
                        const double E = candidate_error(s, c, q, r, fill, best, scratch[0]);
                        if (E < best) {
                            best = E;
                            p = q;
                            best_corner = at;
                        }
                    }
                    corner = best_corner;
                    size = sub;
                }
            } else {
                // No cell's point fell inside (a domain thinner than a cell): any point inside.
                if (!draw_inside(p)) p = s.fill->closest_inside(b.lo + (b.hi - b.lo) * 0.5);
                ++report.by_fallback;
            }
            s.begin_profile(p, scratch[0].profile);
            s.insert(i, scratch[0].profile);
        }
        tick();  // the caller throttles it by time
    }
    return report;
}

}  // namespace tessera::pcf
