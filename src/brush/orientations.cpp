// The element field's orientation solve (brush/orientations.hpp): Eq. 5, 6, 7 by L-BFGS.
#include "brush/orientations.hpp"

#include <LBFGS.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <exception>

#include "brush/canvas_surface.hpp"
#include "brush/strokes.hpp"
#include "core/parallel.hpp"

namespace tessera::brush {

namespace {

// Keeps |v| near 1 so that the normalisation stays well conditioned.
constexpr double kNormPull = 0.1;

struct Pair {
    int a, b;
    double weight;
};

// The terms, precomputed for fixed positions: per sample its alignment weight and target,
// its distribution target; pairs for continuity and rigidity.
struct FieldProblem {
    int dim = 2;
    std::vector<int> group;           // sample -> variable group, -1 fixed
    std::vector<Vec3> fixed;          // sample -> its (fixed) direction
    std::vector<double> align_w;      // w_alignment exp(-d^2 / sigma^2)
    std::vector<Vec3> align_to;       // O(p)
    std::vector<Pair> pairs;          // continuity (Eq. 6) and rigidity (Eq. 7)
    int groups = 0;
    // Variables per group: the dimension; on a surface 2, the coordinates in a tangent basis
    // of the group (at its sample, or at a rigid element's centre), so that every o(s) the
    // solve tries stays in the tangent plane (the gradient is the 3D one projected onto it).
    int vars = 2;
    std::vector<std::array<Vec3, 2>> basis;  // per group, on a surface only
};

double sigma_of(const BrushCanvas::Impl& st, int s) { return st.options.sigma * st.spacing_of_sample(s); }
double neighbourhood_radius(const BrushCanvas::Impl& st, int s) {
    return st.palette[st.kappa_of_element(st.arrangement.samples[s].element)].radius;
}

// Eq. 6 over each sample's neighbourhood N_s (the samples of other elements within the radius
// of Eq. 1), weighted by exp(-d^2 / sigma^2), with each sample's weights normalised to sum to 1
// (the mean of the pair's two sums): the term then weighs as much for a sample in a crowd as
// for one alone, against its alignment term.
void add_continuity_pairs(const BrushCanvas::Impl& st, FieldProblem& fp, double weight) {
    OutputNeighbours nb;
    nb.build(st);
    const Arrangement& arr = st.arrangement;
    const size_t first = fp.pairs.size();
    std::vector<double> sum(arr.samples.size(), 0.0);
    for (int s = 0; s < static_cast<int>(arr.samples.size()); ++s) {
        const double sigma = sigma_of(st, s), radius = neighbourhood_radius(st, s);
        nb.grid.for_each_within(nb.points[s], radius, [&](int o, double d2) {
            if (o <= s || arr.samples[o].element == arr.samples[s].element) return;
            const double k = std::exp(-d2 / (sigma * sigma));
            sum[s] += k, sum[o] += k;
            if (fp.group[s] < 0 && fp.group[o] < 0) return;
            fp.pairs.push_back({s, o, k});
        });
    }
    for (size_t i = first; i < fp.pairs.size(); ++i) {
        Pair& p = fp.pairs[i];
        p.weight *= weight * 0.5 * (1.0 / sum[p.a] + 1.0 / sum[p.b]);
    }
}

void add_rigidity_pairs(const BrushCanvas::Impl& st, FieldProblem& fp, double weight) {
    for (const Element& e : st.arrangement.elements) {
        const OutType& ot = st.out_types[e.type];
        if (st.palette[ot.kappa].exemplar.types[ot.type].rigid || fp.group[e.first_sample] < 0) continue;
        for (const auto& edge : st.palette[ot.kappa].graph[ot.type])
            fp.pairs.push_back({e.first_sample + edge[0], e.first_sample + edge[1], weight});  // Eq. 7
    }
}

// On a surface, each variable group's tangent basis: (t1, t2) with t1 the group's current
// o(s) (tangent at its sample, or at a rigid element's centre) and t2 = n x t1.
void add_tangent_bases(const BrushCanvas::Impl& st, FieldProblem& fp) {
    fp.vars = 2;
    fp.basis.assign(static_cast<size_t>(fp.groups), {});
    const Arrangement& arr = st.arrangement;
    auto set = [&](int g, const Vec3& d, const Vec3& at) {
        const Quat frame = frame_at(st, d, at);
        fp.basis[g] = {frame.rotate(Vec3{1, 0, 0}), frame.rotate(Vec3{0, 1, 0})};
    };
    for (const Element& e : arr.elements) {
        if (fp.group[e.first_sample] < 0) continue;
        const OutType& ot = st.out_types[e.type];
        if (st.palette[ot.kappa].exemplar.types[ot.type].rigid) {
            Vec3 c;
            for (int k = 0; k < e.sample_count; ++k) c += arr.samples[e.first_sample + k].p;
            set(fp.group[e.first_sample], st.direction[e.first_sample], c / static_cast<double>(e.sample_count));
            continue;
        }
        for (int k = 0; k < e.sample_count; ++k) {
            const int s = e.first_sample + k;
            set(fp.group[s], st.direction[s], arr.samples[s].p);
        }
    }
}

// Eq. 5 per sample: its weight w exp(-d^2 / sigma^2) by its distance d to the strokes, and
// O(p), the direction of the stroke there.
void add_alignment_terms(const BrushCanvas::Impl& st, FieldProblem& fp, double weight) {
    const Arrangement& arr = st.arrangement;
    const int n = static_cast<int>(arr.samples.size());
    fp.align_w.assign(n, 0.0);
    fp.align_to.assign(n, Vec3{});
    core::parallel_for(
        n, core::resolve_threads(st.options.threads),
        [&](int begin, int end, int) {
            for (int s = begin; s < end; ++s) {
                const StrokePoint sp = closest_stroke_point(st.strokes, arr.samples[s].p);
                const double sigma = sigma_of(st, s);
                if (std::isfinite(sp.distance)) fp.align_w[s] = weight * std::exp(-sp.distance * sp.distance / (sigma * sigma));
                // O(p) of Eq. 5; on a surface its tangent part at the sample, which o(s) can reach.
                fp.align_to[s] = tangent_at(st, sp.tangent, arr.samples[s].p);
            }
        },
        256);
}

// The objective sees a pair only through the directions of its two ends: the variable group
// of a movable sample, the fixed direction of another. Pairs with the same two ends (the 5 x 5
// sample pairs of two rigid sticks share two groups) become one with the summed weight, which
// is the same sum of Eq. 6 terms in a twentieth of the work; pairs within one group (a rigid
// element with itself) are constant and dropped.
void merge_pairs(FieldProblem& fp) {
    // An end's key: its group, or past the groups, its sample when fixed.
    const int samples = static_cast<int>(fp.group.size());
    const int keys = fp.groups + samples;
    auto key = [&](int s) { return fp.group[s] >= 0 ? fp.group[s] : fp.groups + s; };
    // Bucketed by the lower key (a counting sort, stable), then merged within a bucket through
    // a table of the higher keys seen in it: linear, and in an order fixed by the input.
    std::vector<int> first(static_cast<size_t>(keys) + 1, 0);
    for (Pair& p : fp.pairs) {
        if (key(p.a) > key(p.b)) std::swap(p.a, p.b);
        ++first[static_cast<size_t>(key(p.a)) + 1];
    }
    for (int k = 0; k < keys; ++k) first[k + 1] += first[k];
    std::vector<Pair> bucketed(fp.pairs.size());
    std::vector<int> next(first.begin(), first.end() - 1);
    for (const Pair& p : fp.pairs) bucketed[static_cast<size_t>(next[key(p.a)]++)] = p;
    std::vector<int> seen_in(static_cast<size_t>(keys), -1), slot(static_cast<size_t>(keys), 0);
    std::vector<Pair> merged;
    merged.reserve(fp.pairs.size());
    for (int ka = 0; ka < keys; ++ka)
        for (int i = first[ka]; i < first[ka + 1]; ++i) {
            const Pair& p = bucketed[static_cast<size_t>(i)];
            const int kb = key(p.b);
            if (kb == ka) continue;
            if (seen_in[kb] == ka) {
                merged[static_cast<size_t>(slot[kb])].weight += p.weight;
            } else {
                seen_in[kb] = ka, slot[kb] = static_cast<int>(merged.size());
                merged.push_back(p);
            }
        }
    fp.pairs = std::move(merged);
}

FieldProblem build_problem(const BrushCanvas::Impl& st, const std::vector<char>& movable, bool with_weights) {
    const Arrangement& arr = st.arrangement;
    const int n = static_cast<int>(arr.samples.size());
    FieldProblem fp;
    fp.dim = st.dimension;
    fp.group.assign(n, -1);
    for (const Element& e : arr.elements) {
        if (!movable[e.first_sample]) continue;
        const OutType& ot = st.out_types[e.type];
        const bool rigid = st.palette[ot.kappa].exemplar.types[ot.type].rigid;
        for (int k = 0; k < e.sample_count; ++k) fp.group[e.first_sample + k] = rigid ? fp.groups : fp.groups + k;
        fp.groups += rigid ? 1 : e.sample_count;
    }
    const BrushOptions& o = st.options;
    fp.vars = fp.dim;
    if (st.surface && with_weights) add_tangent_bases(st, fp);
    fp.fixed = st.direction;
    add_alignment_terms(st, fp, with_weights ? o.w_alignment : 1.0);
    add_continuity_pairs(st, fp, with_weights ? o.w_continuity : 1.0);
    add_rigidity_pairs(st, fp, with_weights ? o.w_rigidity : 1.0);
    merge_pairs(fp);
    return fp;
}

// The objective and its gradient in the free variables.
class FieldObjective {
public:
    explicit FieldObjective(const FieldProblem& fp) : fp_(fp) {}

    double operator()(const Eigen::VectorXd& v, Eigen::VectorXd& grad) {
        const int d = fp_.dim;
        units_.resize(static_cast<size_t>(fp_.groups));
        du_.assign(static_cast<size_t>(fp_.groups), Vec3{});
        for (int g = 0; g < fp_.groups; ++g) units_[g] = unit(v, g);
        double f = 0.0;
        for (size_t s = 0; s < fp_.group.size(); ++s) {
            const int g = fp_.group[s];
            if (g < 0) continue;
            f += term(units_[g], fp_.align_to[s], fp_.align_w[s], du_[g]);
        }
        for (const Pair& p : fp_.pairs) {
            const int ga = fp_.group[p.a], gb = fp_.group[p.b];
            if (ga >= 0 && ga == gb) continue;  // one rigid element: identical by construction
            const Vec3 ua = ga >= 0 ? units_[ga] : fp_.fixed[p.a], ub = gb >= 0 ? units_[gb] : fp_.fixed[p.b];
            const Vec3 diff = ua - ub;
            f += p.weight * squared_norm(diff);
            if (ga >= 0) du_[ga] += diff * (2.0 * p.weight);
            if (gb >= 0) du_[gb] -= diff * (2.0 * p.weight);
        }
        grad.setZero(v.size());
        for (int g = 0; g < fp_.groups; ++g) {
            const Vec3 raw = vector_of(v, g);
            const double len = std::max(norm(raw), 1e-12);
            const Vec3 u = units_[g];
            // d u / d v = (I - u u^T) / |v|
            const Vec3 gu = (du_[g] - u * dot(u, du_[g])) / len;
            const double stretch = squared_norm(raw) - 1.0;
            f += kNormPull * stretch * stretch;
            if (fp_.basis.empty()) {
                for (int c = 0; c < d; ++c) grad[g * d + c] = gu[c] + kNormPull * 4.0 * stretch * raw[c];
            } else {  // the chain rule through raw = v0 t1 + v1 t2: the gradient projected on the plane
                const Vec3 total = gu + raw * (kNormPull * 4.0 * stretch);
                for (int c = 0; c < 2; ++c) grad[g * 2 + c] = dot(total, fp_.basis[g][c]);
            }
        }
        if (!(f >= best_f)) best_f = f, best_v = v;  // a failed line search leaves v at a trial point
        return f;
    }

    double best_f = std::numeric_limits<double>::infinity();
    Eigen::VectorXd best_v;

    Vec3 unit(const Eigen::VectorXd& v, int g) const {
        const Vec3 raw = vector_of(v, g);
        const double len = norm(raw);
        return len > 1e-12 ? raw / len : fp_.basis.empty() ? Vec3{1, 0, 0} : fp_.basis[g][0];
    }

    // The unnormalised o(s) of group g: its variables, or on a surface their tangent combination.
    Vec3 vector_of(const Eigen::VectorXd& v, int g) const {
        if (!fp_.basis.empty()) return fp_.basis[g][0] * v[g * 2] + fp_.basis[g][1] * v[g * 2 + 1];
        Vec3 raw;
        for (int c = 0; c < fp_.dim; ++c) raw[c] = v[g * fp_.dim + c];
        return raw;
    }

private:
    static double term(const Vec3& u, const Vec3& target, double w, Vec3& du) {
        if (w <= 0.0) return 0.0;
        const Vec3 diff = u - target;
        du += diff * (2.0 * w);
        return w * squared_norm(diff);
    }
    const FieldProblem& fp_;
    std::vector<Vec3> units_;
    std::vector<Vec3> du_;
};

}  // namespace

OrientationResult solve_orientations(BrushCanvas::Impl& st, const std::vector<char>& movable) {
    OrientationResult result;
    const FieldProblem fp = build_problem(st, movable, true);
    if (fp.groups == 0) return result;
    const int d = fp.vars;
    Eigen::VectorXd v(fp.groups * d);
    for (size_t s = 0; s < fp.group.size(); ++s)
        if (fp.group[s] >= 0)
            for (int c = 0; c < d; ++c)
                v[fp.group[s] * d + c] = fp.basis.empty() ? st.direction[s][c] : dot(st.direction[s], fp.basis[fp.group[s]][c]);
    LBFGSpp::LBFGSParam<double> param;
    param.max_iterations = st.options.lbfgs_iterations;
    param.epsilon = 1e-6;
    param.epsilon_rel = 1e-6;
    LBFGSpp::LBFGSSolver<double> solver(param);
    FieldObjective objective(fp);
    double fx = 0.0;
    try {
        const int used = solver.minimize(objective, v, fx);
        result.bound_hit = used >= param.max_iterations;
    } catch (const std::exception&) {
        // The line search found no decrease (flat, at machine precision, or a BFGS direction that
        // went uphill on this non-convex objective): the best point the
        // objective saw is as good as this solve gets.
    }
    if (objective.best_v.size() == v.size()) v = objective.best_v, fx = objective.best_f;
    for (size_t s = 0; s < fp.group.size(); ++s)
        if (fp.group[s] >= 0) st.direction[s] = objective.unit(v, fp.group[s]);
    result.energy = fx / static_cast<double>(std::max(1, fp.groups));
    return result;
}

FieldEnergies field_energies(const BrushCanvas::Impl& st) {
    FieldProblem fp;
    add_alignment_terms(st, fp, 1.0);
    FieldEnergies e;
    for (size_t s = 0; s < fp.align_w.size(); ++s) e.alignment += fp.align_w[s] * squared_norm(st.direction[s] - fp.align_to[s]);
    // Eq. 6 and 7 over every pair, movable or not.
    OutputNeighbours nb;
    nb.build(st);
    const Arrangement& arr = st.arrangement;
    for (int s = 0; s < static_cast<int>(arr.samples.size()); ++s) {
        const double sigma = sigma_of(st, s);
        nb.grid.for_each_within(nb.points[s], neighbourhood_radius(st, s), [&](int o, double d2) {
            if (o <= s || arr.samples[o].element == arr.samples[s].element) return;
            e.continuity += std::exp(-d2 / (sigma * sigma)) * squared_norm(st.direction[s] - st.direction[o]);
        });
    }
    for (const Element& el : arr.elements) {
        const OutType& ot = st.out_types[el.type];
        for (const auto& edge : st.palette[ot.kappa].graph[ot.type])
            e.rigidity += squared_norm(st.direction[el.first_sample + edge[0]] - st.direction[el.first_sample + edge[1]]);
    }
    return e;
}

}  // namespace tessera::brush
