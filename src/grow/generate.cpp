// Candidate generation and filters for growth (grow/generate.hpp).
#include "grow/generate.hpp"

#include <algorithm>
#include <cmath>

#include "core/parallel.hpp"
#include "grow/neighborhood.hpp"

namespace tessera::grow {

namespace {

// Candidates whose centre lies at most this share of the spacing outside the region are
// moved onto its boundary instead of being discarded.
constexpr double kBoundaryPull = 0.5;
// A candidate of a type short of its share is moved out of overlaps by at most this share of
// its own hard core, in at most kNudgeSteps pushes (drop_overlapping).
constexpr double kNudge = 0.25;
constexpr int kNudgeSteps = 6;
// Shapes of the type's pool a multi-sample candidate that touches others tries, after its
// similarity set (drop_overlapping's reshape), spread over the pool.
constexpr int kReshapeTries = 32;

// The input entries of `e`'s patch paired with an output element within c (position only:
// a pair of different types still occupies the place).
void mark_assigned(const Grower::Impl& g, int e, int patch, int m_out, Scratch& s, std::vector<char>& taken) {
    const InputElements& in = g.input;
    s.partner.assign(m_out, -1);
    pair_greedy(s.entries.data(), m_out, in, e, patch, g.metric.params, s.pair, s.partner.data(), 1e300);
    taken.assign(patch, 0);
    for (int o = 0; o < m_out; ++o) {
        const int i = s.partner[o];
        if (i < 0) continue;
        const Vec3 d = s.entries[o].offset - in.neighbors(e)[i].offset;
        if (dot(d, d) < g.metric.threshold2) taken[i] = 1;
    }
}

// Whether a candidate of type t at p, proposed by horizon element h, lies in h's Voronoi cell
// among the existing elements of the types it is owned against (Impl::owned): no such
// element other than h is nearer. A horizon element's patch then fills only the room
// nearer to it than to anything already there; where the pattern's hard core is far under
// its spacing, the unpaired input neighbours of a match otherwise become candidates between
// elements already placed, round after round (a soft pattern grew at several times its
// density).
bool in_proposer_cell(const Grower::Impl& g, int h, int t, const Vec3& p) {
    Vec3 d = p - g.out[h].p;
    if (g.metric.dimension == 2) d.z = 0.0;
    bool foreign = false;
    g.grid.for_each_within(
        p, norm(d), [&](int i) { return g.out[i].p; },
        [&](int i) { foreign = foreign || (i != h && g.owned_by_proposer(t, g.out[i].type)); });
    return !foreign;
}

}  // namespace

std::vector<Candidate> propose(Grower::Impl& g, double extent) {
    const int n = static_cast<int>(g.horizon.size());
    std::vector<std::vector<Candidate>> per(n);
    std::vector<int> matched(n, -1);
    const double gather = extent + std::sqrt(g.metric.threshold2);
    core::parallel_for(
        n, g.threads,
        [&](int begin, int end, int thread) {
            Scratch s;
            std::vector<char> taken;
            for (int k = begin; k < end; ++k) {
                g.interrupt.check(thread);
                const int h = g.horizon[k];
                const OutElement& he = g.out[h];
                const Quat frame = g.frame_at(he.p);
                gather_output(g, he.p, frame, h, gather, s);
                const Match best = best_match(g, he.type, he.match >= 0 ? he.match : he.source, he.source,
                                              count_within(s, g.metric.params.radius), s);
                if (best.input < 0) continue;
                matched[k] = best.input;
                int patch = 0;
                const det::NeighborEntry* nb = g.input.neighbors(best.input);
                const double extent2 = extent * extent;
                while (patch < g.input.patch_count[best.input] &&
                       dot(nb[patch].offset, nb[patch].offset) <= extent2)
                    ++patch;
                mark_assigned(g, best.input, patch, static_cast<int>(s.entries.size()), s, taken);
                for (int i = 0; i < patch; ++i) {
                    if (taken[i]) continue;
                    Candidate c;
                    c.p = he.p + frame.rotate(nb[i].offset);
                    if (g.metric.dimension == 2) c.p.z = 0.0;
                    g.register_on_layer(nb[i].element, c.p);
                    if (g.any_owned && !in_proposer_cell(g, h, nb[i].type, c.p)) continue;
                    c.type = nb[i].type;
                    c.source = nb[i].element;
                    c.frame = frame;
                    c.fit = best.mean();
                    c.proposer = h;
                    c.order = i;
                    per[k].push_back(c);
                }
            }
        },
        kElementsPerThread);
    std::vector<Candidate> all;
    for (int k = 0; k < n; ++k) {
        if (matched[k] >= 0) g.out[g.horizon[k]].match = matched[k];
        all.insert(all.end(), per[k].begin(), per[k].end());
    }
    return all;
}

int drop_outside(const Grower::Impl& g, const Domain& region, std::vector<Candidate>& candidates) {
    std::vector<Vec3> samples;
    const size_t before = candidates.size();
    const double pull = kBoundaryPull * g.metric.params.spacing;
    std::erase_if(candidates, [&](Candidate& c) {
        if (g.open_region) return !region.inside(c.p);  // the neighbouring cell's to place
        if (!region.inside(c.p)) {
            // Just outside: moved to the boundary, so that the region's edge is not left
            // with a gap wherever the pattern's rows happen to fall beyond it. Not under a
            // count ceiling: its patterns have no rows, and a band's candidates pulled onto
            // the edge would line up there (field data grew 5% over their density so).
            const Vec3 q = region.closest_inside(c.p);
            if (g.crowd.active() || norm(q - c.p) > pull) return true;
            c.p = q;
        }
        g.sample_positions(-1, c.source, c.frame, c.p, samples);
        for (const Vec3& q : samples)
            if (!region.inside(q)) return true;
        return false;
    });
    return static_cast<int>(before - candidates.size());
}

namespace {

// Two elements' samples closer than the exemplar ever shows samples of different elements
// (noodles that cross have distant centroids but touching samples).
bool samples_clash(const std::vector<Vec3>& a, const std::vector<Vec3>& b, double core) {
    const double c2 = core * core;
    for (const Vec3& p : a)
        for (const Vec3& q : b)
            if (dot(p - q, p - q) < c2) return true;
    return false;
}

}  // namespace

TypeBalance::TypeBalance(const Grower::Impl& g)
    : g_(g), count_(g.exemplar.types.size(), 0), share_(count_.size(), 0.0) {
    count_ = g.type_count;
    total_ = static_cast<int>(g.out.size());
    for (const Element& e : g.exemplar.elements)
        share_[e.type] += 1.0 / static_cast<double>(g.exemplar.elements.size());
}

bool TypeBalance::may_displace(int t, const std::vector<int>& blocking) const {
    if (static_cast<int>(blocking.size()) > kMaxDisplaced || !is_short(t)) return false;
    for (const int i : blocking) {
        const OutElement& o = g_.out[i];
        if (i < g_.recent_first || o.locked || o.type == t || !over(o.type)) return false;
    }
    return true;
}

int TypeBalance::short_type(int u) const {
    if (!over(u)) return -1;
    int best = -1;
    for (int t = 0; t < static_cast<int>(share_.size()); ++t)
        if (t != u && is_short(t) && (best < 0 || share(t) / share_[t] < share(best) / share_[best]))
            best = t;
    return best;
}

int drop_overlapping(Grower::Impl& g, std::vector<Candidate>& candidates, double merge,
                     const Domain* region, std::vector<Candidate>& over_ceiling) {
    std::vector<int> order(candidates.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        const Candidate &ca = candidates[a], &cb = candidates[b];
        // Elements that keep others furthest away first: a small element taken first would
        // block every large one (a pebble where a stone belongs), never the reverse.
        const double xa = g.hard_core(ca.type, ca.type), xb = g.hard_core(cb.type, cb.type);
        if (xa != xb) return xa > xb;
        if (ca.fit != cb.fit) return ca.fit < cb.fit;
        return a < b;  // horizon order, then the proposer's own order
    });
    const bool by_samples = g.bounds.has_samples;
    const double reach = by_samples ? std::max(g.reach, 2.0 * g.extent + g.metric.params.spacing) : g.reach;
    core::DynamicGrid taken_grid(std::max(reach, 1e-9), g.metric.dimension);
    std::vector<Candidate> kept;
    std::vector<std::vector<Vec3>> kept_samples;
    std::vector<int> near;
    std::vector<Vec3> mine, theirs;
    std::vector<int> blocking;
    std::vector<char> displaced(g.out.size() - g.recent_first, 0);
    TypeBalance balance(g);
    // The count ceiling (grow/crowd_ceiling.hpp) over elements and taken candidates alike:
    // the existing elements' crowd grows by `pending` as candidates are taken near them.
    const CrowdCeiling& ceiling = g.crowd;
    core::DynamicGrid crowd_grid(ceiling.active() ? ceiling.radius : 1.0, g.metric.dimension);
    std::vector<int> pending(ceiling.active() ? g.out.size() : 0, 0), kept_crowd;
    auto within_ceiling = [&](const Vec3& p) {
        if (!ceiling.active()) return true;
        int own = 0;
        bool fits = true;
        g.grid.for_each_within(
            p, ceiling.radius, [&](int i) { return g.out[i].p; },
            [&](int i) {
                ++own;
                fits = fits && ceiling.allows(g.out[i].crowd + pending[i] + 1);
            });
        crowd_grid.for_each_within(
            p, ceiling.radius, [&](int k) { return kept[k].p; },
            [&](int k) {
                ++own;
                fits = fits && ceiling.allows(kept_crowd[k] + 1);
            });
        return fits && ceiling.allows(own);
    };
    auto count_taken = [&](const Vec3& p) {
        if (!ceiling.active()) return;
        int own = 0;
        g.grid.for_each_within(
            p, ceiling.radius, [&](int i) { return g.out[i].p; }, [&](int i) { ++pending[i], ++own; });
        crowd_grid.for_each_within(
            p, ceiling.radius, [&](int k) { return kept[k].p; }, [&](int k) { ++kept_crowd[k], ++own; });
        crowd_grid.insert(static_cast<int>(kept_crowd.size()), p);
        kept_crowd.push_back(own);
    };
    // The elements and taken candidates a candidate of type t at p (samples `mine`) would
    // crowd: existing ones into `blocking`; returns true when a taken candidate is crowded
    // (then `blocking` is left empty: most candidates merge with a taken one, and the
    // existing elements need not be looked at for them).
    // Neither answer depends on the order neighbours are visited in (unsorted queries).
    auto crowds = [&](const Vec3& p, int t, const std::vector<Vec3>& mine, std::vector<int>& blocking) {
        blocking.clear();
        bool merges = false;
        taken_grid.for_each_within(
            p, reach, [&](int i) { return kept[i].p; },
            [&](int i) {
                merges = merges || norm(kept[i].p - p) < merge * g.hard_core(t, kept[i].type) ||
                         (by_samples &&
                          samples_clash(mine, kept_samples[i], merge * g.sample_core(t, kept[i].type)));
            });
        if (merges) return true;
        g.grid.for_each_within(
            p, reach, [&](int i) { return g.out[i].p; },
            [&](int i) {
                if (i >= g.recent_first && displaced[i - g.recent_first]) return;
                const OutElement& o = g.out[i];
                Vec3 d = o.p - p;
                if (g.metric.dimension == 2) d.z = 0.0;
                bool hit = norm(d) < g.hard_core(t, o.type);
                if (!hit && by_samples) {
                    g.sample_positions(o.kept, o.source, o.frame, o.p, theirs);
                    hit = samples_clash(mine, theirs, g.sample_core(t, o.type));
                }
                if (hit) blocking.push_back(i);
            });
        return false;
    };
    // The push that takes candidate c (its samples `own` when multi-sample) out of the hard
    // cores of the elements and taken candidates it overlaps: the sum of the overlaps, each
    // along the line of centres, or of the samples that clash.
    auto push_out = [&](const Candidate& c, const std::vector<Vec3>& own) {
        // How far a must move away from b to leave a hard core `core` round b.
        auto overlap = [&](const Vec3& a, const Vec3& b, double core) {
            Vec3 d = a - b;
            if (g.metric.dimension == 2) d.z = 0.0;
            const double l = norm(d);
            return l < core && l > 1e-12 ? d * ((core - l) / l) : Vec3{};
        };
        // Per element, the deepest overlap: of the centres, or of its samples with the
        // candidate's (the move that clears them all if they overlap along one direction).
        Vec3 push;
        auto add_element = [&](const Vec3& q, const std::vector<Vec3>& samples, int type, double scale) {
            Vec3 deepest = overlap(c.p, q, scale * g.hard_core(c.type, type));
            if (by_samples) {
                const double core = scale * g.sample_core(c.type, type);
                for (const Vec3& a : own)
                    for (const Vec3& b : samples)
                        if (const Vec3 o = overlap(a, b, core); dot(o, o) > dot(deepest, deepest)) deepest = o;
            }
            push = push + deepest;
        };
        g.grid.query(
            c.p, reach, [&](int i) { return g.out[i].p; }, near);
        for (const int i : near) {
            if (i >= g.recent_first && displaced[i - g.recent_first]) continue;
            const OutElement& o = g.out[i];
            if (by_samples) g.sample_positions(o.kept, o.source, o.frame, o.p, theirs);
            add_element(o.p, theirs, o.type, 1.0);
        }
        taken_grid.query(
            c.p, reach, [&](int i) { return kept[i].p; }, near);
        for (const int i : near) add_element(kept[i].p, kept_samples[i], kept[i].type, merge);
        return push;
    };
    // Moves a candidate of a type short of its share out of small overlaps: where patches
    // copied at misaligned offsets meet, a large element finds no place exactly where it is
    // proposed although one lies a fraction of its hard core away, and dropping it leaves
    // the large type jammed at random sequential adsorption's density (far under a
    // compacted exemplar's) while small elements fill the gaps. A multi-sample element (a
    // membrane's channel protein, whose samples span both leaflets) is moved out of the
    // samples it clashes with: 96% of the channels a membrane's patches proposed touched a
    // lipid already there, and it grew with 44% of its channel share. Returns false when no
    // place within kNudge of its hard core is found.
    std::vector<Vec3> moved;
    auto nudge = [&](Candidate& c) {
        const double limit = kNudge * g.hard_core(c.type, c.type);
        Candidate at = c;
        for (int step = 0; step < kNudgeSteps; ++step) {
            if (by_samples) g.sample_positions(-1, at.source, at.frame, at.p, moved);
            Vec3 push = push_out(at, moved);
            if (g.metric.dimension == 2) push.z = 0.0;
            g.keep_on_layer(Vec3{}, push);  // it stays on its layer
            // A multi-sample element moves across its chord only: along it its samples slide
            // past their neighbours' and it leaves the layer it spans (a channel through a
            // membrane shifted up, and the lipids copied round it stacked above the membrane).
            if (by_samples && moved.size() > 1) {
                const Vec3 chord = moved.back() - moved.front();
                const double l = norm(chord);
                if (l > 1e-12) push = push - chord * (dot(push, chord) / (l * l));
            }
            if (dot(push, push) == 0.0) break;
            at.p = at.p + push;
            if (norm(at.p - c.p) > limit) return false;
        }
        if (region && !(by_samples ? g.fits_region(*region, -1, at.source, at.frame, at.p, moved)
                                   : region->inside(at.p)))
            return false;
        c.p = at.p;
        return true;
    };
    // Whether an element or taken candidate sits at p (centroids closer than the merge
    // distance): a second proposal for that place, not a shape that fails to fit there.
    auto place_taken = [&](const Vec3& p, int t) {
        bool taken = false;
        taken_grid.for_each_within(
            p, reach, [&](int i) { return kept[i].p; },
            [&](int i) { taken = taken || norm(kept[i].p - p) < merge * g.hard_core(t, kept[i].type); });
        g.grid.for_each_within(
            p, reach, [&](int i) { return g.out[i].p; },
            [&](int i) {
                if (i >= g.recent_first && displaced[i - g.recent_first]) return;
                Vec3 d = g.out[i].p - p;
                if (g.metric.dimension == 2) d.z = 0.0;
                taken = taken || norm(d) < g.hard_core(t, g.out[i].type);
            });
        return taken;
    };
    // A multi-sample candidate whose samples touch others' at a free place takes, if one
    // fits, the shape of an input element of its similarity set (k-coherence) instead: a
    // noodle bent otherwise rather than none (growth filled 75% of a noodle exemplar's
    // density when every such candidate was dropped). Returns true when c was reshaped.
    std::vector<Vec3> trial;
    // Whether the place holds as many elements within r as the exemplar's typical one.
    const double count_radius = g.metric.params.radius;
    auto count_near = [&](const Vec3& p) {
        int n = 0;
        g.grid.for_each_within(
            p, count_radius, [&](int i) { return g.out[i].p; },
            [&](int i) { n += !(i >= g.recent_first && displaced[i - g.recent_first]); });
        taken_grid.for_each_within(
            p, count_radius, [&](int i) { return kept[i].p; }, [&](int) { ++n; });
        return n;
    };
    std::vector<int> around;
    auto place_full = [&](const Vec3& p) {
        if (g.reshape_ceiling <= 0) return false;
        if (count_near(p) >= g.reshape_ceiling) return true;
        // Its neighbours would hold one more: none may pass the ceiling (at the horizon the
        // place's own neighbourhood is half empty, theirs behind it is not).
        g.grid.query(
            p, count_radius, [&](int i) { return g.out[i].p; }, around);
        for (const int i : around)
            if (count_near(g.out[i].p) >= g.reshape_ceiling) return true;
        return false;
    };
    auto reshape = [&](Candidate& c) {
        if (c.source < 0 || place_taken(c.p, c.type) || place_full(c.p)) return false;
        const InputElements& in = g.input;
        const std::vector<int>& pool = in.pool[c.type];
        const int similar = in.sim_start[c.source + 1] - in.sim_start[c.source];
        const int stride = std::max<int>(1, static_cast<int>(pool.size()) / kReshapeTries);
        for (int k = 0; k < similar + kReshapeTries && k - similar < static_cast<int>(pool.size()); ++k) {
            const int alt = k < similar ? in.sim[in.sim_start[c.source] + k] : pool[((k - similar) * stride) % pool.size()];
            if (in.type[alt] != c.type || alt == c.source) continue;
            // On a registered layer the shape keeps its own depth: one of another depth (a
            // lipid of the other leaflet) does not belong at this place.
            Vec3 p = c.p;
            g.register_on_layer(alt, p);
            if (norm(p - c.p) > Grower::Impl::kLayerTolerance * g.metric.params.spacing) continue;
            g.sample_positions(-1, alt, c.frame, p, trial);
            if (region && !g.fits_region(*region, -1, alt, c.frame, p, theirs)) continue;
            if (crowds(p, c.type, trial, blocking) || !blocking.empty()) continue;
            c.source = alt;
            c.p = p;
            mine.swap(trial);
            return true;
        }
        return false;
    };
    // Takes candidate c (or not): returns true when taken.
    auto take = [&](Candidate c) {
        if (by_samples) {
            g.sample_positions(-1, c.source, c.frame, c.p, mine);
            if ((crowds(c.p, c.type, mine, blocking) || !blocking.empty()) && reshape(c)) ++g.reshaped;
        }
        if (crowds(c.p, c.type, mine, blocking)) return false;
        if (!within_ceiling(c.p)) {
            over_ceiling.push_back(c);
            ++over_ceiling.back().tries;
            return false;
        }
        if (!blocking.empty()) {
            // A type short of its share may take the place of recent elements of types over
            // theirs (the big element the small ones crowded out); otherwise it yields.
            if (!balance.may_displace(c.type, blocking)) return false;
            for (const int i : blocking) displaced[i - g.recent_first] = 1, balance.remove(g.out[i].type);
            g.displaced += static_cast<int>(blocking.size());
        } else if (const int t = balance.short_type(c.type); t >= 0 && !by_samples) {
            // Redistribution (section V.C) by the global histogram: a candidate of a type over
            // its share becomes the type most short of its share where that one fits.
            const int source = g.input.nearest_in_pool(t, g.input.centroid[c.source], 1e300);
            if (source >= 0 && !crowds(c.p, t, mine, blocking) && blocking.empty()) {
                c.type = t;
                c.source = source;
            }
        }
        count_taken(c.p);
        taken_grid.insert(static_cast<int>(kept.size()), c.p);
        kept.push_back(c);
        balance.add(c.type);
        if (by_samples)
            kept_samples.push_back(mine);
        else
            kept_samples.emplace_back();
        return true;
    };
    // Candidates of one hard core are taken where they are first; those of a type short of
    // its share that found no place are then nudged (after every exact place of their
    // class is taken, so that a nudged one never takes a place proposed exactly).
    std::vector<Candidate> deferred;
    auto flush_deferred = [&] {
        for (Candidate& c : deferred)
            if (balance.is_short(c.type) && nudge(c)) take(c);
        deferred.clear();
    };
    for (size_t begin = 0; begin < order.size();) {
        const double core = g.hard_core(candidates[order[begin]].type, candidates[order[begin]].type);
        size_t end = begin;
        while (end < order.size() &&
               g.hard_core(candidates[order[end]].type, candidates[order[end]].type) == core)
            ++end;
        for (size_t k = begin; k < end; ++k) {
            g.interrupt.check(0);
            const Candidate& c = candidates[order[k]];
            if (!take(c) && balance.is_short(c.type)) deferred.push_back(c);
        }
        flush_deferred();
        begin = end;
    }
    const int dropped = static_cast<int>(candidates.size() - kept.size());
    candidates = std::move(kept);
    if (std::find(displaced.begin(), displaced.end(), 1) != displaced.end()) g.remove_and_renumber(g.recent_first, displaced);
    return dropped;
}

int add_candidates(Grower::Impl& g, const std::vector<Candidate>& candidates) {
    const int first = static_cast<int>(g.out.size());
    for (const Candidate& c : candidates) {
        OutElement e;
        e.p = c.p;
        e.type = c.type;
        e.source = c.source;
        e.frame = c.frame;
        e.match = c.source;
        e.born = g.round;
        e.tries = c.tries;
        g.add(e);
    }
    return first;
}

int drop_high_energy(Grower::Impl& g, int first, double t, double& mean,
                     std::vector<Candidate>& dropped_out) {
    const int n = static_cast<int>(g.out.size()) - first;
    std::vector<double> energy(n, 0.0);
    std::vector<int> matched(n, -1);
    core::parallel_for(
        n, g.threads,
        [&](int begin, int end, int thread) {
            Scratch s;
            for (int k = begin; k < end; ++k) {
                g.interrupt.check(thread);
                const OutElement& e = g.out[first + k];
                gather_output(g, e.p, e.frame, first + k, g.metric.params.radius, s);
                const Match m =
                    best_match(g, e.type, e.source, e.source, static_cast<int>(s.entries.size()), s);
                energy[k] = m.mean();
                matched[k] = m.input;
            }
        },
        kElementsPerThread);
    double sum = 0.0;
    for (const double e : energy) sum += e;
    const double round_mean = n > 0 ? sum / n : 0.0;
    std::vector<char> keep(n, 1);
    int dropped = 0;
    double kept_sum = 0.0;
    for (int k = 0; k < n; ++k) {
        if (matched[k] >= 0) g.out[first + k].match = matched[k];
        keep[k] = energy[k] <= t * round_mean;
        if (keep[k]) {
            kept_sum += energy[k];
            continue;
        }
        ++dropped;
        const OutElement& e = g.out[first + k];
        Candidate c;
        c.p = e.p;
        c.type = e.type;
        c.source = e.source;
        c.frame = e.frame;
        c.fit = energy[k];
        c.tries = e.tries + 1;
        dropped_out.push_back(c);
    }
    mean = n - dropped > 0 ? kept_sum / (n - dropped) : 0.0;
    g.drop_tail(first, keep);
    return dropped;
}

}  // namespace tessera::grow
