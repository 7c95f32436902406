// The assignment step of the brush solver (brush/positions.hpp).
#include "brush/positions.hpp"

#include <array>

#include <Eigen/Sparse>
#include <Eigen/IterativeLinearSolvers>

#include "brush/canvas_surface.hpp"
#include "core/parallel.hpp"
#include "tessera/error.hpp"
#include "tessera/field.hpp"

namespace tessera::brush {

namespace {

// A small pull to the current place: keeps the system definite where an element has no
// pair (an isolated element, a lone sample).
constexpr double kAnchor = 0.01;
// Bound on the conjugate-gradient iterations of one position solve (reported when hit).
constexpr int kSolveIterations = 400;

// The unknowns of the position solve. A deformable element's samples are unknowns of their
// own; a rigid element is one unknown, its translation: its samples sit at fixed offsets from
// it (its shape in the frame of its current o(s), as restore_shapes puts it back), so its
// graph rows are constant and its pairs move the whole element. This is the least-squares
// translation of the rigid body, and a fifth of the unknowns of a 5-sample stick.
struct Unknowns {
    std::vector<int> index;    // sample -> unknown, -1 when fixed
    std::vector<Vec3> offset;  // sample -> its position minus its unknown's (0 unless rigid)
    int count = 0;
};

Unknowns make_unknowns(const BrushCanvas::Impl& st, const std::vector<char>& movable) {
    const Arrangement& arr = st.arrangement;
    Unknowns u;
    u.index.assign(arr.samples.size(), -1);
    u.offset.assign(arr.samples.size(), Vec3{});
    for (int i = 0; i < static_cast<int>(arr.elements.size()); ++i) {
        const Element& e = arr.elements[i];
        if (!movable[e.first_sample]) continue;
        const OutType& ot = st.out_types[e.type];
        if (!st.palette[ot.kappa].exemplar.types[ot.type].rigid || e.sample_count == 1) {
            for (int k = 0; k < e.sample_count; ++k) u.index[e.first_sample + k] = u.count++;
            continue;
        }
        Vec3 c;
        for (int k = 0; k < e.sample_count; ++k) c += arr.samples[e.first_sample + k].p;
        c = c / static_cast<double>(e.sample_count);
        const Quat frame = st.frame_of_element(i, c);
        for (int k = 0; k < e.sample_count; ++k) {
            u.index[e.first_sample + k] = u.count;
            u.offset[e.first_sample + k] = frame.rotate(st.reference[e.first_sample + k]) * e.scale;
        }
        ++u.count;
    }
    return u;
}

// Normal equations of rows "x_b - x_a = t" with weights, over the unknowns: x_s is its
// unknown plus its offset, or its current place when fixed.
struct NormalEquations {
    const Unknowns& u;
    const std::vector<Sample>& samples;
    std::vector<Eigen::Triplet<double>> triplets;
    Eigen::MatrixXd rhs;

    NormalEquations(const Unknowns& unknowns, const std::vector<Sample>& s)
        : u(unknowns), samples(s), rhs(Eigen::MatrixXd::Zero(unknowns.count, 3)) {}

    void add_rhs(int i, const Vec3& v, double w) {
        for (int c = 0; c < 3; ++c) rhs(i, c) += w * v[c];
    }
    void difference(int a, int b, const Vec3& t, double w) {
        const int ia = u.index[a], ib = u.index[b];
        if (ia < 0 && ib < 0) return;
        if (ia == ib) return;  // two samples of one rigid element: a constant row
        if (ia >= 0 && ib >= 0) {
            const Vec3 between = t - u.offset[b] + u.offset[a];
            triplets.emplace_back(ia, ia, w);
            triplets.emplace_back(ib, ib, w);
            triplets.emplace_back(ia, ib, -w);
            triplets.emplace_back(ib, ia, -w);
            add_rhs(ib, between, w);
            add_rhs(ia, between, -w);
        } else if (ib >= 0) {
            triplets.emplace_back(ib, ib, w);
            add_rhs(ib, samples[a].p + t - u.offset[b], w);
        } else {
            triplets.emplace_back(ia, ia, w);
            add_rhs(ia, samples[b].p - t - u.offset[a], w);
        }
    }
};

void add_distribution_rows(const BrushCanvas::Impl& st, const std::vector<SampleMatch>& matches, NormalEquations& eq) {
    const double w = st.options.w_distribution;
    for (int s = 0; s < static_cast<int>(matches.size()); ++s) {
        if (eq.u.index[s] < 0 || matches[s].pairs.empty()) continue;
        const Quat frame = st.frame_of_sample(s);
        for (const NeighbourPair& p : matches[s].pairs) eq.difference(s, p.other, frame.rotate(p.target), w);  // Eq. 1
    }
}

void add_conflict_rows(const BrushCanvas::Impl& st, const OutputNeighbours& nb, NormalEquations& eq) {
    const double w = st.options.w_conflict;
    for_each_conflict(st, nb, [&](int a, int b, double summed, double distance) {
        const Vec3 d = st.arrangement.samples[b].p - st.arrangement.samples[a].p;
        // Eq. 3: w_check = summed / |p^| > 1 pushes the pair out to their summed weights; a
        // coincident pair is pushed apart along x.
        const Vec3 target = distance > 1e-12 ? d * (summed / distance) : Vec3{summed, 0, 0};
        eq.difference(a, b, target, w);
    });
}

void add_graph_rows(const BrushCanvas::Impl& st, NormalEquations& eq) {
    const double w = st.options.w_graph;
    const Arrangement& arr = st.arrangement;
    for (const Element& e : arr.elements) {
        if (eq.u.index[e.first_sample] < 0) continue;
        const OutType& ot = st.out_types[e.type];
        for (const auto& edge : st.palette[ot.kappa].graph[ot.type]) {
            const int a = e.first_sample + edge[0], b = e.first_sample + edge[1];
            const Quat frame = st.frame_of_sample(a);
            eq.difference(a, b, frame.rotate(st.reference[b] - st.reference[a]) * e.scale, w);  // Eq. 4
        }
    }
}

// An element poking out of the canvas (a rigid shape re-placed in a turned frame, or samples
// pushed out by the incomplete neighbourhoods at the edge) is moved in whole: by the step that
// brings its furthest-out sample to the edge, at most kContainSteps times. Returns whether all
// its samples are inside then.
constexpr int kContainSteps = 4;

bool move_inside(BrushCanvas::Impl& st, const Element& e) {
    const Domain& canvas = st.space();
    Arrangement& arr = st.arrangement;
    for (int step = 0; step <= kContainSteps; ++step) {
        bool outside = false;
        Vec3 push;
        double longest = -1.0;
        for (int k = 0; k < e.sample_count; ++k) {
            const Vec3& p = arr.samples[e.first_sample + k].p;
            if (canvas.inside(p)) continue;
            outside = true;
            const Vec3 d = canvas.closest_inside(p) - p;
            if (squared_norm(d) > longest) longest = squared_norm(d), push = d;
        }
        if (!outside) return true;
        if (step == kContainSteps) return false;
        for (int k = 0; k < e.sample_count; ++k) arr.samples[e.first_sample + k].p += push;
    }
    return false;
}

// Rigid elements take their exact shape again (at the solved centroid, in the frame of o(s)),
// an element with samples out of the canvas is moved in whole (move_inside), and one whose
// centre left the canvas, or that cannot be moved in, goes back to where it was (projected onto
// the edge instead, the elements that the incomplete neighbourhoods there push out piled up on it).
// On a surface the canvas is its band; the samples go onto the surface afterwards.
void restore_shapes(BrushCanvas::Impl& st, const std::vector<char>& movable, const std::vector<Sample>& before) {
    Arrangement& arr = st.arrangement;
    for (int i = 0; i < static_cast<int>(arr.elements.size()); ++i) {
        const Element& e = arr.elements[i];
        if (!movable[e.first_sample]) continue;
        Vec3 c;
        for (int k = 0; k < e.sample_count; ++k) c += arr.samples[e.first_sample + k].p;
        c = c / static_cast<double>(e.sample_count);
        const OutType& ot = st.out_types[e.type];
        if (st.palette[ot.kappa].exemplar.types[ot.type].rigid) {
            const Quat frame = st.frame_of_element(i, c);
            for (int k = 0; k < e.sample_count; ++k)
                arr.samples[e.first_sample + k].p = c + frame.rotate(st.reference[e.first_sample + k]) * e.scale;
        }
        if (!st.space().inside(c) || !move_inside(st, e))
            for (int k = 0; k < e.sample_count; ++k) arr.samples[e.first_sample + k].p = before[e.first_sample + k].p;
    }
}

}  // namespace

bool assign_positions(BrushCanvas::Impl& st, const std::vector<char>& movable, const std::vector<SampleMatch>& matches) {
    Arrangement& arr = st.arrangement;
    const int n = static_cast<int>(arr.samples.size());
    const Unknowns u = make_unknowns(st, movable);
    const int count = u.count;
    if (count == 0) return false;
    NormalEquations eq(u, arr.samples);
    // One allocation for the rows' entries (growing by doubling copied and page-faulted a
    // large buffer several times per solve): 4 per pair and graph edge, 1 per anchor, and a
    // first guess of 4 per sample for the conflicts.
    size_t rows = 0;
    for (const SampleMatch& m : matches) rows += m.pairs.size();
    eq.triplets.reserve(static_cast<size_t>(n) * 5 + 4 * (rows + arr.samples.size()));
    for (int s = 0; s < n; ++s)
        if (u.index[s] >= 0) eq.triplets.emplace_back(u.index[s], u.index[s], kAnchor), eq.add_rhs(u.index[s], arr.samples[s].p - u.offset[s], kAnchor);
    OutputNeighbours nb;
    nb.build(st);
    add_distribution_rows(st, matches, eq);
    add_conflict_rows(st, nb, eq);
    add_graph_rows(st, eq);
    Eigen::SparseMatrix<double> system(count, count);
    system.setFromTriplets(eq.triplets.begin(), eq.triplets.end());
    // Conjugate gradients from the current positions, bounded: the pairs of a 3D neighbourhood
    // make a sparse Cholesky factor fill in (it took a third of a volume's fill), while the
    // system is symmetric positive definite (the anchor) and the start is close to the answer.
    Eigen::MatrixXd start(count, 3);
    for (int s = 0; s < n; ++s)
        if (u.index[s] >= 0)
            for (int c = 0; c < 3; ++c) start(u.index[s], c) = arr.samples[s].p[c] - u.offset[s][c];
    Eigen::MatrixXd x(count, 3);
    // The coordinates are independent systems with one matrix: solved side by side, each by
    // its own solver (Eigen's keeps per-solve state), so the bits do not depend on threads.
    const int axes = st.dimension == 3 ? 3 : 2;  // in 2D z stays 0
    x.col(2).setZero();
    std::array<char, 3> hit{};
    core::parallel_for(axes, core::resolve_threads(st.options.threads), [&](int begin, int end, int) {
        Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper> solver;
        solver.setMaxIterations(kSolveIterations);
        solver.setTolerance(1e-8);
        solver.compute(system);
        for (int c = begin; c < end; ++c) {
            x.col(c) = solver.solveWithGuess(eq.rhs.col(c), start.col(c));
            hit[static_cast<size_t>(c)] = solver.info() != Eigen::Success;
        }
    });
    const bool bound_hit = hit[0] || hit[1] || hit[2];
    const std::vector<Sample> before = arr.samples;
    for (int s = 0; s < n; ++s)
        if (u.index[s] >= 0) {
            const int i = u.index[s];
            arr.samples[s].p = Vec3{x(i, 0), x(i, 1), st.dimension == 3 ? x(i, 2) : 0.0} + u.offset[s];
        }
    restore_shapes(st, movable, before);
    snap_elements(st, 0, static_cast<int>(arr.elements.size()));  // on a surface: back onto it, o(s) tangent
    update_element_poses(st);
    return bound_hit;
}

void update_element_poses(BrushCanvas::Impl& st, int first_element) {
    Arrangement& arr = st.arrangement;
    for (int i = first_element; i < static_cast<int>(arr.elements.size()); ++i) {
        Element& e = arr.elements[i];
        if (e.locked) continue;  // never touched, not even re-rounded
        Vec3 c;
        for (int k = 0; k < e.sample_count; ++k) c += arr.samples[e.first_sample + k].p;
        e.position = c / static_cast<double>(e.sample_count);
        e.orientation = st.frame_of_element(i, e.position) * st.relative[i];
    }
}

}  // namespace tessera::brush
