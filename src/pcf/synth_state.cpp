// The incremental PCF state of synthesis (synth_state.hpp).
#include "pcf/synth_state.hpp"

#include "pcf/sparse_classes.hpp"

#include <algorithm>

namespace tessera::pcf {

namespace {

double max_of(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }
double min_of(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }

}  // namespace

State::State(const PcfModel& model_, const Domain& domain_, const std::vector<std::vector<double>>& radii,
             const std::vector<FixedElem>& fixed_elements)
    : model(model_), domain(domain_) {
    axis = make_axis(model.settings, model.disks);
    bins = axis.bins;
    r_max = model.r_max;
    area = domain.measure();
    x_limit = axis.x_limit();
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
    for (int n = 1; n <= kCircleSamples; ++n) inverse_count_[n] = static_cast<double>(kCircleSamples) / n;

    const int classes = static_cast<int>(model.classes.size());
    count.assign(classes, 0);
    members.assign(classes, {});
    fixed.assign(classes, {});
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
    for (const FixedElem& f : fixed_elements) {
        Elem e;
        e.p = f.p;
        e.r = f.r;
        e.cls = f.cls;
        fixed[f.cls].push_back(static_cast<int>(elems.size()));
        ++count[f.cls];
        elems.push_back(e);
    }
    profiles.resize(elems.size());

    // Terms: normalisation, targets and reach.
    class_terms.assign(classes, {});
    double reach_max = 0.0;
    for (const PcfEnvelope& env : model.pcfs) {
        Term t;
        t.parent = env.parent;
        t.child = env.child;
        t.within = env.parent == env.child;
        const double n_child = count[t.child];
        const double neighbours = t.within ? count[t.parent] - 1.0 : count[t.parent];  // possible, per reference
        const double pairs = n_child * neighbours;
        t.norm.resize(bins);
        t.ind_norm.resize(bins);
        t.inv_target.resize(bins);
        t.inv_upper.resize(bins);
        t.inv_lower.resize(bins);
        for (int k = 0; k < bins; ++k) {
            const double ring = axis.ring_area(k, r_max);  // |W| step / A_k: PcfNormaliser's factor
            t.norm[k] = pairs > 0.0 ? area * axis.step / (ring * pairs) : 0.0;
            t.ind_norm[k] = neighbours > 0.0 ? area * axis.step / (ring * neighbours) : 0.0;
            t.inv_target[k] = 1.0 / std::max(env.mean[k], kFloor);
            t.inv_upper[k] = 1.0 / std::max(env.upper[k], kFloor);
            t.inv_lower[k] = 1.0 / std::max(env.lower[k], kFloor);
        }
        t.lower_lo = bins;
        for (int k = 0; k < bins; ++k)
            if (env.lower[k] > 0.0) {
                t.lower_lo = std::min(t.lower_lo, k);
                t.lower_hi = k;
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
        // A class with few elements is placed without PCFs, and its children are placed
        // without their PCFs on it (PcfSparseClass): the term stays empty.
        if (!sparse_class(model, t.child) && !sparse_class(model, t.parent))
            class_terms[t.child].push_back(static_cast<int>(terms.size()));
        terms.push_back(std::move(t));
    }
    for (int t = 0; t < static_cast<int>(terms.size()); ++t) refresh(t);

    // Separations, both ways: a class checks those placed before it (the others are empty).
    separations.assign(classes, {});
    separation_scale = 1.0 / (kFloor * axis.sigma);
    const auto add = [&](int c, int other, double x) {
        // Beyond contact x = 3 + gap / r_max; up to it a pair overlaps (d <= r1 + r2).
        // `reach` leaves out the element's own radius, added per query.
        Separation s;
        s.other = other;
        s.x = x;
        const double ro = max_of(radii[other]);
        s.reach = model.disks ? std::max(0.0, x - 3.0) * r_max + ro : x * r_max;
        if (min_of(radii[c]) <= 0.0 && min_of(radii[other]) <= 0.0) s.reach = std::max(s.reach, x * r_max);
        s.reach *= 1.0 + 1e-9;
        separations[c].push_back(s);
    };
    for (const PcfSeparation& sep : model.separations) {
        if (!(sep.x > 0.0)) continue;
        add(sep.a, sep.b, sep.x);
        add(sep.b, sep.a, sep.x);
    }
    // A class with few elements keeps its closest approach to every class, both ways.
    for (const PcfSparseClass& sc : model.sparse)
        for (int o = 0; o < classes; ++o) {
            if (o == sc.cls || !(sc.closest[o] > 0.0)) continue;
            add(sc.cls, o, sc.closest[o]);
            add(o, sc.cls, sc.closest[o]);
        }

    // The grid: cells of a quarter of the largest query radius (a query visits about 1.6
    // times the area of its disc), coarser if there would be too many.
    const Box b = domain.bounds();
    lo_ = b.lo;
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

void State::begin_profile(const Vec3& p, CircleProfile& out) const {
    out.p = p;
    out.free = domain.distance_to_boundary(p);
    out.built = false;
    out.sampled = false;
}

void State::build_profile(CircleProfile& out) const {
    out.built = true;
    out.at.clear();
    out.inside.clear();
    const Vec3& p = out.p;
    if (domain.kind() == Domain::Kind::box) {
        // Each point leaves the box once: at the nearest side along its direction.
        const Box& b = domain.bounds();
        for (int k = 0; k < kCircleSamples; ++k) {
            const double c = circle_cos_[k], s = circle_sin_[k];
            double t = std::numeric_limits<double>::infinity();
            if (c > 0.0) t = std::min(t, (b.hi.x - p.x) / c);
            if (c < 0.0) t = std::min(t, (b.lo.x - p.x) / c);
            if (s > 0.0) t = std::min(t, (b.hi.y - p.y) / s);
            if (s < 0.0) t = std::min(t, (b.lo.y - p.y) / s);
            out.at.push_back(t);
        }
        std::sort(out.at.begin(), out.at.end());
        for (int m = 0; m < kCircleSamples; ++m) out.inside.push_back(kCircleSamples - 1 - m);
        return;
    }
    if (polygon_edges_.empty()) {
        out.sampled = true;
        return;
    }
    // A polygon: along each direction the crossings with the rings alternate leaving and
    // entering (the position is inside).
    std::vector<std::pair<double, int>> events;
    std::vector<double> crossings;
    for (int k = 0; k < kCircleSamples; ++k) {
        const double ux = circle_cos_[k], uy = circle_sin_[k];
        crossings.clear();
        for (const auto& [a, b] : polygon_edges_) {
            const double ex = b.x - a.x, ey = b.y - a.y, fx = a.x - p.x, fy = a.y - p.y;
            const double denom = ux * ey - uy * ex;
            if (denom == 0.0) continue;  // parallel
            const double t = (fx * ey - fy * ex) / denom, s = (fx * uy - fy * ux) / denom;
            if (t > 0.0 && s >= 0.0 && s < 1.0) crossings.push_back(t);
        }
        std::sort(crossings.begin(), crossings.end());
        for (size_t m = 0; m < crossings.size(); ++m) events.push_back({crossings[m], m % 2 == 0 ? -1 : 1});
    }
    std::sort(events.begin(), events.end());
    int inside = kCircleSamples;
    for (const auto& [t, delta] : events) {
        inside += delta;
        out.at.push_back(t);
        out.inside.push_back(inside);
    }
}

int State::cell_of(const Vec3& p) const {
    const int x = std::clamp(static_cast<int>(std::floor((p.x - lo_.x) * inv_cell_)), 0, nx_ - 1);
    const int y = std::clamp(static_cast<int>(std::floor((p.y - lo_.y) * inv_cell_)), 0, ny_ - 1);
    return y * nx_ + x;
}

void State::add_pairs(int i, double sign) {
    const Elem& e = elems[i];
    const CircleProfile& own = profiles[i];
    for (int t : class_terms[e.cls]) {
        Term& term = terms[t];
        for_each_near(term.parent, e.p, term.reach, [&](int j) {
            if (j == i) return true;
            const Elem& o = elems[j];
            const double d = distance(e.p, o.p);
            const PairDistance pd = pair(d, e.r, o.r);
            if (pd.x > x_limit) return true;
            const Span sp = kernel_span(pd.x);
            const double w = weight(own, d) + (term.within ? weight(profiles[j], d) : 0.0);
            for (int m = 0; m < sp.n; ++m) term.sum[sp.lo + m] += sign * w * sp.value(m);
            return true;
        });
        refresh(t);
    }
}

void State::insert(int i, CircleProfile& profile) {
    Elem& e = elems[i];
    std::swap(profiles[i], profile);
    // Others read it as a neighbour's, from several threads: it must not change lazily.
    if (!profiles[i].built) build_profile(profiles[i]);
    e.p = profiles[i].p;
    add_pairs(i, 1.0);
    e.placed = true;
    e.cell = cell_of(e.p);
    cells_[e.cls][e.cell].push_back({i, e.p.x, e.p.y});
    ++placed_[e.cls];
}

void State::insert_fixed(int c) {
    for (int i : fixed[c]) {
        CircleProfile profile;
        begin_profile(elems[i].p, profile);
        insert(i, profile);
    }
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

State::Snapshot State::snapshot(int c, const std::vector<int>& elements) const {
    Snapshot snap;
    snap.elements = elements;
    for (int i : elements) {
        snap.positions.push_back(elems[i].p);
        snap.profiles.push_back(profiles[i]);
    }
    for (int t : class_terms[c]) snap.sums.push_back(terms[t].sum);
    return snap;
}

void State::restore(int c, const Snapshot& snap) {
    for (size_t k = 0; k < snap.elements.size(); ++k) {
        const int i = snap.elements[k];
        elems[i].p = snap.positions[k];
        profiles[i] = snap.profiles[k];
    }
    for (size_t k = 0; k < class_terms[c].size(); ++k) {
        terms[class_terms[c][k]].sum = snap.sums[k];
        refresh(class_terms[c][k]);
    }
    rebuild_grid(c);
}

std::vector<int> State::near_members(int c, const std::vector<int>& around, double radius) const {
    std::vector<char> in(elems.size(), 0);
    for (int a : around) {
        in[a] = 1;
        if (elems[a].placed)
            for_each_near(c, elems[a].p, radius, [&](int j) {
                in[j] = 1;
                return true;
            });
    }
    std::vector<int> out;
    for (int i : members[c])
        if (in[i]) out.push_back(i);
    return out;
}

void State::rebuild_grid(int c) {
    for (auto& list : cells_[c]) list.clear();
    for (const auto* list : {&fixed[c], &members[c]})
        for (int i : *list) {
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

}  // namespace tessera::pcf
