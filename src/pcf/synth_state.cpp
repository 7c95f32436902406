// The incremental PCF state of synthesis (synth_state.hpp).
#include "pcf/synth_state.hpp"

#include <algorithm>

namespace tessera::pcf {

namespace {

double max_of(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }
double min_of(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }

}  // namespace

State::State(const PcfModel& model_, const Domain& domain_, const std::vector<std::vector<double>>& radii)
    : model(model_), domain(domain_) {
    axis = make_axis(model.settings, model.disks);
    bins = axis.bins;
    r_max = model.r_max;
    area = domain.measure();
    x_limit = axis.x_limit();
    floor = kFloorShare / axis.step;
    kernel_max = static_cast<int>(std::floor(2.0 * axis.reach() / axis.step)) + 2;
    kernel_half_ = static_cast<int>(std::ceil(axis.reach() / axis.step)) + 1;
    kernel_width_ = 2 * kernel_half_ + 1;
    kernel_table_.resize(static_cast<size_t>(kKernelSteps) * kernel_width_);
    kernel_delta_.resize(kernel_table_.size());
    const auto exact = [&](int j, int m) {
        return pcf::kernel((m - static_cast<double>(j) / kKernelSteps) * axis.step, axis.sigma);
    };
    for (int j = 0; j < kKernelSteps; ++j)
        for (int m = -kernel_half_; m <= kernel_half_; ++m) {
            const size_t at = static_cast<size_t>(j) * kernel_width_ + m + kernel_half_;
            kernel_table_[at] = exact(j, m);
            kernel_delta_[at] = exact(j + 1, m) - exact(j, m);
        }
    inv_step_ = 1.0 / axis.step;
    reach_steps_ = axis.reach() / axis.step;
    inv_r_max_ = 1.0 / r_max;
    for (int k = 0; k < kCircleSamples; ++k) {
        const double a = 2.0 * kPi * (k + 0.5) / kCircleSamples;
        circle_cos_[k] = std::cos(a);
        circle_sin_[k] = std::sin(a);
    }

    const int classes = static_cast<int>(model.classes.size());
    count.assign(classes, 0);
    members.assign(classes, {});
    placed_.assign(classes, 0);
    for (int c = 0; c < classes; ++c) {
        count[c] = static_cast<int>(radii[c].size());
        for (double r : radii[c]) {
            Elem e;
            e.r = r;
            e.cls = c;
            members[c].push_back(static_cast<int>(elems.size()));
            elems.push_back(e);
        }
    }
    inverse.assign(elems.size() * bins, 1.0);

    // Terms: normalisation, targets and reach.
    class_terms.assign(classes, {});
    double reach_max = 0.0;
    for (const PcfEnvelope& env : model.pcfs) {
        Term t;
        t.parent = env.parent;
        t.child = env.child;
        t.within = env.parent == env.child;
        const double n_child = count[t.child];
        const double n_parent = count[t.parent];
        const double pairs = n_child * (t.within ? n_parent - 1.0 : n_parent);
        t.norm.resize(bins);
        t.ind_norm.resize(bins);
        t.inv_target.resize(bins);
        t.inv_upper.resize(bins);
        t.inv_lower.resize(bins);
        for (int k = 0; k < bins; ++k) {
            const double ring = axis.ring_area(k, r_max);
            t.norm[k] = pairs > 0.0 ? area / (ring * pairs) : 0.0;
            t.ind_norm[k] = n_parent > 0.0 ? area / (ring * n_parent) : 0.0;
            t.inv_target[k] = 1.0 / std::max(env.mean[k], floor);
            t.inv_upper[k] = 1.0 / std::max(env.upper[k], floor);
            t.inv_lower[k] = 1.0 / std::max(env.lower[k], floor);
        }
        t.target = env.mean;
        t.lower = env.lower;
        t.upper = env.upper;
        t.sum.assign(bins, 0.0);
        // Euclidean reach: beyond contact x = 3 + gap / r_max (disks), x = d / r_max (points).
        const double rc = max_of(radii[t.child]), rp = max_of(radii[t.parent]);
        double reach = model.disks ? std::max(0.0, x_limit - 3.0) * r_max + rc + rp : x_limit * r_max;
        if (min_of(radii[t.child]) <= 0.0 && min_of(radii[t.parent]) <= 0.0) reach = std::max(reach, x_limit * r_max);
        t.reach = reach * (1.0 + 1e-9);
        reach_max = std::max(reach_max, t.reach);
        class_terms[t.child].push_back(static_cast<int>(terms.size()));
        terms.push_back(std::move(t));
    }
    for (int t = 0; t < static_cast<int>(terms.size()); ++t) refresh(t);

    // The grid: cells of a quarter of the largest query radius (a query visits about 1.6
    // times the area of its disc), coarser if there would be too many.
    const Box b = domain.bounds();
    lo_ = b.lo;
    hi_x_ = b.hi.x;
    hi_y_ = b.hi.y;
    if (domain.kind() == Domain::Kind::polygon) {
        const DomainSource src = domain.source();
        const auto world = [&](const Vec3& v) { return src.origin + (v - src.origin) * src.scale; };
        const auto add_ring = [&](const std::vector<Vec3>& ring) {
            for (size_t k = 0, j = ring.size() - 1; k < ring.size(); j = k++)
                polygon_edges_.push_back({world(ring[j]), world(ring[k])});
        };
        add_ring(src.outer);
        for (const auto& hole : src.holes) add_ring(hole);
    }
    const double w = std::max(b.hi.x - b.lo.x, 1e-300), h = std::max(b.hi.y - b.lo.y, 1e-300);
    double cell = std::max(0.25 * (reach_max + kMaxMove * 2.0 * r_max), 1e-12 * std::max(w, h));
    const double max_cells = 4.0 * static_cast<double>(elems.size()) + 64.0;
    while ((std::floor(w / cell) + 1.0) * (std::floor(h / cell) + 1.0) > max_cells) cell *= 1.5;
    nx_ = static_cast<int>(std::floor(w / cell)) + 1;
    ny_ = static_cast<int>(std::floor(h / cell)) + 1;
    inv_cell_ = 1.0 / cell;
    cells_.assign(classes, std::vector<std::vector<CellEntry>>(static_cast<size_t>(nx_) * ny_));
}

int State::polygon_inside_count(const Vec3& p, double rho) const {
    constexpr int kMaxCrossings = 64;
    double angle[kMaxCrossings];
    int n = 0;
    for (const auto& [a, b] : polygon_edges_) {
        const double dx = b.x - a.x, dy = b.y - a.y, fx = a.x - p.x, fy = a.y - p.y;
        const double qa = dx * dx + dy * dy;
        if (!(qa > 0.0)) continue;
        const double qb = 2.0 * (fx * dx + fy * dy), qc = fx * fx + fy * fy - rho * rho;
        const double disc = qb * qb - 4.0 * qa * qc;
        if (disc < 0.0) continue;
        const double root = std::sqrt(disc);
        for (const double t : {(-qb - root) / (2.0 * qa), (-qb + root) / (2.0 * qa)}) {
            if (t < 0.0 || t >= 1.0) continue;
            if (n == kMaxCrossings) {  // a ring too detailed for the arcs: test the points
                int inside = 0;
                for (int k = 0; k < kCircleSamples; ++k)
                    inside += domain.inside({p.x + rho * circle_cos_[k], p.y + rho * circle_sin_[k], 0.0});
                return inside;
            }
            double theta = std::atan2(fy + t * dy, fx + t * dx);
            if (theta < 0.0) theta += 2.0 * kPi;
            angle[n++] = theta;
        }
    }
    if (n == 0) return domain.inside({p.x + rho * circle_cos_[0], p.y + rho * circle_sin_[0], 0.0}) ? kCircleSamples : 0;
    std::sort(angle, angle + n);
    const double per_radian = kCircleSamples / (2.0 * kPi);
    int inside = 0;
    for (int k = 0; k < n; ++k) {
        const double from = angle[k], to = k + 1 < n ? angle[k + 1] : angle[0] + 2.0 * kPi;
        const int first = static_cast<int>(std::floor(from * per_radian - 0.5)) + 1;
        const int last = static_cast<int>(std::ceil(to * per_radian - 0.5)) - 1;
        if (last < first) continue;  // no point on this arc
        const double middle = 0.5 * (from + to);
        if (domain.inside({p.x + rho * std::cos(middle), p.y + rho * std::sin(middle), 0.0})) inside += last - first + 1;
    }
    return inside;
}

void State::fractions_at(const Vec3& q, double* out) const {
    const double dist = domain.distance_to_boundary(q);
    for (int k = 0; k < bins; ++k) {
        const double rho = axis.x(k) * r_max;
        out[k] = rho <= dist ? 1.0 : 1.0 / inside_fraction(q, rho);
    }
}

LazyInverse State::lazy_at(const Vec3& p, double* storage) const {
    LazyInverse lazy;
    lazy.q = p;
    lazy.dist = domain.distance_to_boundary(lazy.q);
    lazy.values = storage;
    std::fill(storage, storage + bins, 0.0);
    return lazy;
}

int State::cell_of(const Vec3& p) const {
    const int x = std::clamp(static_cast<int>(std::floor((p.x - lo_.x) * inv_cell_)), 0, nx_ - 1);
    const int y = std::clamp(static_cast<int>(std::floor((p.y - lo_.y) * inv_cell_)), 0, ny_ - 1);
    return y * nx_ + x;
}

void State::add_pairs(int i, double sign) {
    const Elem& e = elems[i];
    const double* inv_i = &inverse[static_cast<size_t>(i) * bins];
    std::vector<double> kv(kernel_max);
    for (int t : class_terms[e.cls]) {
        Term& term = terms[t];
        for_each_near(term.parent, e.p, term.reach, [&](int j) {
            if (j == i) return true;
            const Elem& o = elems[j];
            const PairDistance pd = pair(e.p, e.r, o.p, o.r);
            if (pd.x > x_limit) return true;
            int lo = 0;
            const int n = kernel(pd.x, lo, kv.data());
            const double* inv_j = &inverse[static_cast<size_t>(j) * bins];
            for (int m = 0; m < n; ++m) {
                const int k = lo + m;
                term.sum[k] += sign * kv[m] * (term.within ? inv_i[k] + inv_j[k] : inv_i[k]);
            }
            return true;
        });
        refresh(t);
    }
}

void State::insert(int i, const Vec3& p) {
    Elem& e = elems[i];
    e.p = p;
    fractions_at(p, &inverse[static_cast<size_t>(i) * bins]);
    add_pairs(i, 1.0);
    e.placed = true;
    e.cell = cell_of(p);
    cells_[e.cls][e.cell].push_back({i, p.x, p.y});
    ++placed_[e.cls];
}

void State::remove(int i) {
    Elem& e = elems[i];
    auto& list = cells_[e.cls][e.cell];
    for (size_t k = 0; k < list.size(); ++k)
        if (list[k].index == i) {
            list.erase(list.begin() + static_cast<long>(k));
            break;
        }
    e.placed = false;
    e.cell = -1;
    --placed_[e.cls];
    add_pairs(i, -1.0);
}

State::Snapshot State::snapshot(int c) const {
    Snapshot snap;
    for (int i : members[c]) {
        snap.positions.push_back(elems[i].p);
        const double* row = &inverse[static_cast<size_t>(i) * bins];
        snap.inverse.insert(snap.inverse.end(), row, row + bins);
    }
    for (int t : class_terms[c]) snap.sums.push_back(terms[t].sum);
    return snap;
}

void State::restore(int c, const Snapshot& snap) {
    for (size_t k = 0; k < members[c].size(); ++k) {
        const int i = members[c][k];
        elems[i].p = snap.positions[k];
        std::copy_n(&snap.inverse[k * bins], bins, &inverse[static_cast<size_t>(i) * bins]);
    }
    for (size_t k = 0; k < class_terms[c].size(); ++k) {
        terms[class_terms[c][k]].sum = snap.sums[k];
        refresh(class_terms[c][k]);
    }
    rebuild_grid(c);
}

void State::rebuild_grid(int c) {
    for (auto& list : cells_[c]) list.clear();
    for (int i : members[c]) {
        Elem& e = elems[i];
        if (!e.placed) continue;
        e.cell = cell_of(e.p);
        cells_[c][e.cell].push_back({i, e.p.x, e.p.y});
    }
}

void State::refresh(int t) {
    Term& term = terms[t];
    double m = -std::numeric_limits<double>::infinity();
    for (int k = 0; k < bins; ++k) m = std::max(m, (term.norm[k] * term.sum[k] - term.target[k]) * term.inv_target[k]);
    term.base_max = m;
}

double State::term_error(int t) const {
    const Term& term = terms[t];
    double e = 0.0;
    for (int k = 0; k < bins; ++k) {
        const double d = term.norm[k] * term.sum[k] - term.target[k];
        e += d * d;
    }
    return e;
}

double State::class_reach(int c) const {
    double r = 0.0;
    for (int t : class_terms[c]) r = std::max(r, terms[t].reach);
    return r;
}

}  // namespace tessera::pcf
