#include "det/assign.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>

#include "core/parallel.hpp"
#include "det/shape_matching.hpp"

namespace tessera::det {

namespace {

constexpr double locked_weight = 1e6;
constexpr int cg_max_iterations = 1000;

}  // namespace

// Eq. 4: minimise sum_{s_o} sum_{s'_o in n(s_o)} w |(p(s'_o) - p(s_o)) - p^(s_o, s'_o)|^2
// + anchor |p - p_current|^2. Solved for the displacement so the tolerance is
// relative to the mismatch, not to the coordinates' magnitude.
AssignReport assign_positions(OutputState& state, const Params& params, int threads, const Domain* domain) {
    Arrangement& out = state.arrangement;
    const int n = static_cast<int>(out.samples.size());
    const int dim = params.dimension;
    std::vector<Eigen::Triplet<double>> triplets;
    std::vector<double> diagonal(n, params.anchor_weight);
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, dim);  // -gradient at the current positions
    size_t total_pairs = 0;
    for (const auto& p : state.pairs) total_pairs += p.size();
    triplets.reserve(2 * total_pairs);
    for (int c = 0; c < n; ++c) {
        const int ce = out.samples[c].element;
        for (const Pair& pr : state.pairs[c]) {
            const int o = pr.output;
            const double w = pr.weight * (out.samples[o].element == ce ? params.intra_weight : 1.0);
            diagonal[c] += w;
            diagonal[o] += w;
            triplets.emplace_back(c, o, -w);
            triplets.emplace_back(o, c, -w);
            const Vec3 residual = (out.samples[o].p - out.samples[c].p) - pr.predicted;
            for (int k = 0; k < dim; ++k) {
                rhs(o, k) -= w * residual[k];
                rhs(c, k) += w * residual[k];
            }
        }
    }
    // Boundary term (a Theta of Eq. 2): a sample outside the domain is pulled to its
    // nearest point inside. Unlike clamping after the solve, the pull is balanced
    // against the neighbours' predictions, so boundary samples do not pile up on the wall.
    if (domain != nullptr) {
        for (int i = 0; i < n; ++i) {
            const Vec3& p = out.samples[i].p;
            if (domain->inside(p)) continue;
            Vec3 target = domain->closest_inside(p);
            // Reflected back across the boundary, not onto it: pulled onto the wall, samples
            // that drift out pile up along it in a line the exemplar never shows.
            if (!params.floor_constraints) {
                const Vec3 mirror = target * 2.0 - p;
                if (domain->inside(mirror)) target = mirror;
            }
            diagonal[i] += params.wall_weight;
            for (int k = 0; k < dim; ++k) rhs(i, k) += params.wall_weight * (target[k] - p[k]);
        }
    }
    for (int i = 0; i < n; ++i) {
        if (out.elements[out.samples[i].element].locked) diagonal[i] += locked_weight;
        triplets.emplace_back(i, i, diagonal[i]);
    }
    Eigen::SparseMatrix<double> a(n, n);
    a.setFromTriplets(triplets.begin(), triplets.end());
    // Constrained selection: floor samples keep their elevation (displacement 0 along
    // gravity's axis), so that axis gets its own matrix with a strong diagonal there.
    Eigen::SparseMatrix<double> a_gravity;
    const bool hold_floor = params.floor_constraints && !state.floor.empty();
    if (hold_floor) {
        a_gravity = a;
        for (int i = 0; i < n; ++i)
            if (state.floor[i] & floor_bit) a_gravity.coeffRef(i, i) += params.floor_weight;
    }

    AssignReport report;
    Eigen::MatrixXd delta = Eigen::MatrixXd::Zero(n, dim);
    std::vector<int> iterations(dim, 0);
    std::vector<char> converged(dim, 1);
    core::parallel_for(dim, std::min(threads, dim), [&](int begin, int end, int) {
        for (int k = begin; k < end; ++k) {
            Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> cg;
            cg.setMaxIterations(cg_max_iterations);
            cg.setTolerance(params.cg_tolerance);
            cg.compute(hold_floor && k == params.gravity.axis ? a_gravity : a);
            delta.col(k) = cg.solve(rhs.col(k));
            iterations[k] = static_cast<int>(cg.iterations());
            converged[k] = cg.info() == Eigen::Success;
        }
    });
    for (int k = 0; k < dim; ++k) {
        report.cg_iterations = std::max(report.cg_iterations, iterations[k]);
        report.cg_converged = report.cg_converged && converged[k];
    }
    for (int i = 0; i < n; ++i) {
        if (out.elements[out.samples[i].element].locked) continue;
        for (int k = 0; k < dim; ++k) out.samples[i].p[k] += delta(i, k);
    }
    return report;
}

namespace {

// Attribute distance |q_a - q_b|^2 between two input elements for Eq. 5:
// type, radius (in spacings), 2D angle and free attributes (in standard deviations).
struct AttributeScale {
    double spacing = 1.0;
    std::vector<double> attribute_sd;
};

double attribute_distance(const Exemplar& ex, int a, int b, const AttributeScale& scale, int dimension) {
    if (a == b) return 0.0;
    const Element& ea = ex.elements[a];
    const Element& eb = ex.elements[b];
    double d = ea.type != eb.type ? 1.0 : 0.0;
    const double dr = (ea.radius - eb.radius) / scale.spacing;
    d += dr * dr;
    if (dimension == 2 && ea.sample_count == 1) d += 0.5 * (1.0 - std::cos(ea.orientation.angle_z() - eb.orientation.angle_z()));
    for (size_t k = 0; k < ea.attributes.size(); ++k) {
        const double da = (ea.attributes[k] - eb.attributes[k]) / scale.attribute_sd[k];
        d += da * da;
    }
    return d;
}

// Eq. 5: each output element takes the attributes of the input element among its
// votes that minimises the summed attribute distance to all votes.
void assign_attributes(OutputState& state, const InputIndex& index, const Params& params, int threads) {
    Arrangement& out = state.arrangement;
    const Exemplar& ex = *index.exemplar;
    const int n_el = static_cast<int>(out.elements.size());
    // Votes per output element: input elements matched to any of its samples.
    std::vector<std::vector<int>> votes(n_el);
    for (size_t so = 0; so < out.samples.size(); ++so) {
        const int m = state.match[so];
        if (m >= 0) votes[out.samples[so].element].push_back(index.element[m]);
        for (const Pair& pr : state.pairs[so]) votes[out.samples[pr.output].element].push_back(index.element[pr.input]);
    }
    AttributeScale scale;
    scale.spacing = params.spacing;
    scale.attribute_sd.assign(ex.attribute_names.size(), 1.0);
    for (size_t k = 0; k < ex.attribute_names.size(); ++k) {
        double mean = 0.0, sq = 0.0;
        for (const auto& e : ex.elements) mean += e.attributes[k];
        mean /= ex.elements.size();
        for (const auto& e : ex.elements) sq += (e.attributes[k] - mean) * (e.attributes[k] - mean);
        const double sd = std::sqrt(sq / ex.elements.size());
        scale.attribute_sd[k] = sd > 0.0 ? sd : 1.0;
    }
    // Per element: the medoid of its votes (best), the medoid among the votes of its own
    // type (own), and what keeping its type costs (gain = cost(own) - cost(best)).
    std::vector<int> best(n_el, -1), own(n_el, -1);
    std::vector<double> gain(n_el, 0.0);
    core::parallel_for(n_el, threads, [&](int begin, int end, int) {
        std::vector<std::pair<int, int>> distinct;  // (input element, count)
        for (int e = begin; e < end; ++e) {
            const Element& el = out.elements[e];
            if (el.locked || votes[e].empty()) continue;
            auto& v = votes[e];
            std::sort(v.begin(), v.end());
            distinct.clear();
            for (int x : v) {
                if (!distinct.empty() && distinct.back().first == x) ++distinct.back().second;
                else distinct.emplace_back(x, 1);
            }
            double best_cost = INFINITY, own_cost = INFINITY;
            for (const auto& [cand, cnt] : distinct) {
                const bool same_type = ex.elements[cand].type == el.type;
                if (!same_type && el.sample_count > 1) continue;  // shapes keep their type
                double c = 0.0;
                for (const auto& [other, count] : distinct)
                    c += count * attribute_distance(ex, cand, other, scale, params.dimension);
                if (c < best_cost) best_cost = c, best[e] = cand;  // ties: lowest input index
                if (same_type && c < own_cost) own_cost = c, own[e] = cand;
            }
            gain[e] = own_cost - best_cost;  // +inf when no vote is of its own type
        }
    });

    // Type changes keep every class at its count (outputs keep the exemplar's
    // class densities). Unconstrained, the vote drifts towards the classes that dominate
    // neighbourhoods (amacrine at 4x: one class +3%, the other -3% after 10 iterations).
    // Changes are taken in order of gain while both classes stay within max(1, 0.5%) of
    // their counts, so they happen as exchanges; a refused element keeps its type and takes
    // the medoid of its own type's votes (or keeps its attributes when it has none).
    std::vector<int> count(out.types.size(), 0), slack(out.types.size(), 0);
    for (const Element& el : out.elements) ++count[el.type];
    const bool constrained = state.type_target.size() == out.types.size();
    if (constrained)
        for (size_t t = 0; t < slack.size(); ++t)
            slack[t] = std::max(1, static_cast<int>(std::lround(0.005 * state.type_target[t])));
    std::vector<int> changes;
    for (int e = 0; e < n_el; ++e)
        if (best[e] >= 0 && ex.elements[best[e]].type != out.elements[e].type) changes.push_back(e);
    std::stable_sort(changes.begin(), changes.end(), [&](int a, int b) { return gain[a] > gain[b]; });
    std::vector<int> chosen = best;
    for (int e : changes) {
        const int from = out.elements[e].type, to = ex.elements[best[e]].type;
        if (!constrained || (count[from] - 1 >= state.type_target[from] - slack[from] &&
                             count[to] + 1 <= state.type_target[to] + slack[to])) {
            --count[from], ++count[to];
        } else {
            chosen[e] = own[e];
        }
    }

    core::parallel_for(n_el, threads, [&](int begin, int end, int) {
        for (int e = begin; e < end; ++e) {
            Element& el = out.elements[e];
            if (chosen[e] < 0) continue;
            const Element& src = ex.elements[chosen[e]];
            state.source_element[e] = chosen[e];
            el.type = src.type;
            el.radius = src.radius;
            el.attributes = src.attributes;
            el.scale = src.scale;
            // Single-sample elements take the source's orientation turned into the local frame (Eq. 7).
            if (el.sample_count == 1)
                el.orientation = params.field.active() ? params.field.frame(el.position, params.dimension) * src.orientation
                                                       : src.orientation;
        }
    });
}

// Rigid elements become the best-fitting rigid copy of their source element.
void snap_rigid_elements(OutputState& state, const InputIndex& index, int dimension, int threads) {
    Arrangement& out = state.arrangement;
    const Exemplar& ex = *index.exemplar;
    core::parallel_for(static_cast<int>(out.elements.size()), threads, [&](int begin, int end, int) {
        std::vector<Vec3> a, b;
        for (int e = begin; e < end; ++e) {
            Element& el = out.elements[e];
            if (el.sample_count < 2 || el.locked || !out.types[el.type].rigid) continue;
            const Element& src = ex.elements[state.source_element[e]];
            a.resize(el.sample_count);
            b.resize(el.sample_count);
            for (int s = 0; s < el.sample_count; ++s) {
                a[s] = ex.samples[src.first_sample + s].p;
                b[s] = out.samples[el.first_sample + s].p;
            }
            Quat r;
            Vec3 t;
            best_rigid_fit(a.data(), b.data(), el.sample_count, dimension, r, t);
            for (int s = 0; s < el.sample_count; ++s) out.samples[el.first_sample + s].p = r.rotate(a[s]) + t;
            el.orientation = r * src.orientation;
        }
    });
}

}  // namespace

// Elements that left the box are translated back (as a whole, so shapes are kept).
int keep_inside_domain(Arrangement& out, const Domain& domain, int dimension) {
    // Works through Domain::closest_inside only, so any domain shape is served: the
    // element moves by the largest correction any of its samples needs, a few times
    // (a move that fixes one sample can push another out); an element that cannot
    // fit (longer than a thin domain) ends with the smallest violation found.
    constexpr int max_rounds = 8;
    int outside = 0;
    for (auto& el : out.elements) {
        if (el.locked) continue;
        for (int round = 0; round <= max_rounds; ++round) {
            Vec3 shift;
            double worst = 0.0;
            for (int s = 0; s < el.sample_count; ++s) {
                const Vec3& p = out.samples[el.first_sample + s].p;
                if (domain.inside(p)) continue;
                Vec3 d = domain.closest_inside(p) - p;
                if (dimension == 2) d.z = 0.0;
                if (squared_norm(d) > worst) worst = squared_norm(d), shift = d;
            }
            if (worst == 0.0) break;
            if (round == max_rounds) {  // the bound: measured, not moved again
                ++outside;
                break;
            }
            for (int s = 0; s < el.sample_count; ++s) out.samples[el.first_sample + s].p += shift;
        }
    }
    return outside;
}

void update_poses(OutputState& state, const InputIndex&, int dimension) {
    Arrangement& out = state.arrangement;
    out.update_positions();
    if (dimension == 2)
        for (auto& el : out.elements) el.position.z = 0.0;
}

AssignReport assign_step(OutputState& state, const InputIndex& index, const Domain& domain, const Params& params,
                         int threads) {
    Arrangement& out = state.arrangement;
    // Elevations of floor elements before the step, restored exactly after it (the
    // solve holds them only up to its weight, and the rigid fit may tilt an element).
    std::vector<double> elevation;
    const bool hold_floor = params.floor_constraints && !state.floor.empty();
    if (hold_floor) {
        elevation.resize(out.elements.size());
        for (size_t e = 0; e < out.elements.size(); ++e)
            elevation[e] = element_elevation(out, out.elements[e], params.gravity);
    }
    // Elements touching chosen boundary sides keep their distance to those sides the same
    // way (the extreme sample's coordinate along each touched side's axis).
    const auto& sides = params.boundary.sides;
    std::vector<double> side_coordinate;
    if (hold_floor && !sides.empty()) {
        side_coordinate.assign(out.elements.size() * sides.size(), 0.0);
        for (size_t e = 0; e < out.elements.size(); ++e)
            for (size_t k = 0; k < sides.size(); ++k)
                side_coordinate[e * sides.size() + k] =
                    element_elevation(out, out.elements[e], Gravity{sides[k].axis, double(sides[k].sign)});
    }
    AssignReport report = assign_positions(state, params, threads, &domain);
    assign_attributes(state, index, params, threads);
    snap_rigid_elements(state, index, params.dimension, threads);
    match_deformable_shapes(state, *index.exemplar, params.dimension, threads);
    if (hold_floor && !sides.empty()) {
        for (size_t e = 0; e < out.elements.size(); ++e) {
            const Element& el = out.elements[e];
            const char code = state.floor[el.first_sample];
            if (el.locked) continue;
            for (size_t k = 0; k < sides.size(); ++k) {
                if (!(code & (2 << k))) continue;
                const Gravity side{sides[k].axis, double(sides[k].sign)};
                const double shift = side_coordinate[e * sides.size() + k] - element_elevation(out, el, side);
                for (int s = 0; s < el.sample_count; ++s) out.samples[el.first_sample + s].p[side.axis] += shift;
            }
        }
    }
    if (hold_floor) {
        for (size_t e = 0; e < out.elements.size(); ++e) {
            const Element& el = out.elements[e];
            if (el.locked || !(state.floor[el.first_sample] & floor_bit)) continue;
            const double shift = elevation[e] - element_elevation(out, el, params.gravity);
            for (int s = 0; s < el.sample_count; ++s) out.samples[el.first_sample + s].p[params.gravity.axis] += shift;
        }
    }
    update_poses(state, index, params.dimension);
    return report;
}

}  // namespace tessera::det
