// Rare types brought back to their share (grow/rare_types.hpp).
#include "grow/rare_types.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

#include "core/rng.hpp"
#include "grow/ball_lattice.hpp"

namespace tessera::grow {

namespace {

// An inserted element may remove elements that take up to this many times its own room
// (the sum of its samples' hard-core balls): where more of them overlap it, the site is
// passed over rather than left with a hole around the new element.
constexpr double kRoomRatio = 1.5;

// A minority type of single-sample elements packed at its jamming density (the stones of a
// two-class pattern: growth places them as random sequential adsorption would, 0.17 per unit
// area against the exemplar's 0.19 to 0.22) has no place left at its full hard core. Its
// missing elements go where its own elements are at least this share of the hard core away,
// the nearest of them pushed out to it (make_room).
constexpr double kSqueeze = 0.8;
// The push moves no element further than this share of the hard core, and stops after this
// many sweeps: a site that needs more is passed over.
constexpr double kMaxPush = 0.3;
constexpr int kPushSweeps = 40;
// Beyond an open face of a world's tile the type is taken to stand this share of its hard
// core away (clearance). 0.5 brought the stones within one unit of a first-phase tile's
// border from 1.4x to 1.0x the tile's density; 0.25 left too few there (0.8x), 1.0 changed
// nothing.
constexpr double kOpenFaceDepth = 0.5;
// The gaps of a jammed packing are probed at these shares of the hard core from each of the
// type's elements, along probe_directions (grow/ball_lattice.hpp).
constexpr double kVoidProbe[] = {0.85, 1.0};

// The room of an element of type t: its samples' hard-core balls (radius half the type's
// own sample or centroid hard core), summed.
double room_of(const Grower::Impl& g, int t) {
    const std::vector<int>& pool = g.input.pool[t];
    if (pool.empty()) return 0.0;
    const int samples = g.input.layout_start[pool[0] + 1] - g.input.layout_start[pool[0]];
    const double core = g.bounds.has_samples ? g.sample_core(t, t) : g.hard_core(t, t);
    return std::max(1, samples) * std::pow(0.5 * core, g.metric.dimension);
}

// Inserts elements of one rare type; see complete_rare_types.
class RareInsertion {
public:
    RareInsertion(Grower::Impl& g, int first, const Domain& region, const std::vector<char>& rare,
                  std::vector<char>& removed)
        : g_(g), first_(first), region_(region), rare_(rare), removed_(removed) {
        reach_ = g.bounds.has_samples ? std::max(g.reach, 2.0 * g.extent + g.metric.params.spacing) : g.reach;
    }

    // Inserts up to `want` elements of type t; returns how many. At the places of the
    // call's elements of other types, or, `in_voids`, in the gaps between the type's own.
    int insert(int t, int want, bool in_voids) {
        t_ = t;
        spread_ = type_spacing(t);
        own_ = core::DynamicGrid(spread_, g_.metric.dimension);
        for (int i = 0; i < static_cast<int>(g_.out.size()); ++i)
            if (g_.out[i].type == t && !is_removed(i)) own_.insert(i, g_.out[i].p);
        core_ = g_.hard_core(t, t);
        squeeze_ = !g_.bounds.has_samples && !rare_[t];
        const double floor = squeeze_ ? kSqueeze * core_ : core_;
        if (in_voids)
            void_sites(floor);
        else
            element_sites();
        std::priority_queue<std::pair<double, int>> queue;  // farthest first, then the lower index
        for (int k = 0; k < static_cast<int>(sites_.size()); ++k)
            if (sites_[k].clearance >= floor) queue.push({sites_[k].clearance, -k});
        int inserted = 0;
        while (inserted < want && !queue.empty() && queue.top().first >= floor) {
            const auto [d, minus_k] = queue.top();
            queue.pop();
            const double now = clearance(sites_[-minus_k].p);
            if (now < d) {  // an insertion came nearer since: back in line at its distance now
                queue.push({now, minus_k});
                continue;
            }
            if (try_site(sites_[-minus_k])) ++inserted;
        }
        return inserted;
    }

private:
    // Mean spacing of type t's elements in the exemplar.
    double type_spacing(int t) const {
        const double n = static_cast<double>(g_.input.pool[t].size());
        return std::pow(g_.exemplar.domain.measure() / std::max(1.0, n), 1.0 / g_.metric.dimension);
    }

    bool is_removed(int i) const { return i >= first_ && i - first_ < static_cast<int>(removed_.size()) && removed_[i - first_]; }

    // Distance from p to the nearest element of the type, capped at two of its spacings.
    // Next to an open face of a world's tile (nothing made beyond it yet) the face counts
    // as an element of the type kOpenFaceDepth hard cores beyond it: counted as empty, the
    // face's far side made every site along it look farthest from the type, and a world's
    // first-phase tiles got their stones piled along their borders (1.4x the density within
    // one unit of them), which left the seams of the later tiles without any.
    double clearance(const Vec3& p) const {
        double best = 2.0 * spread_;
        own_.for_each_within(
            p, best, [&](int j) { return g_.out[j].p; }, [&](int j) { best = std::min(best, norm(g_.out[j].p - p)); });
        if (!g_.open_region || region_.kind() != Domain::Kind::box) return best;
        const Box& box = region_.bounds();
        const double beyond = kOpenFaceDepth * core_;
        for (int axis = 0; axis < g_.metric.dimension; ++axis)
            for (const double face : {box.lo[axis], box.hi[axis]}) {
                const double depth = std::abs(p[axis] - face);
                if (depth + beyond >= best) continue;
                Vec3 on_face = p;
                on_face[axis] = face;
                if (open_beyond(on_face)) best = depth + beyond;
            }
        return best;
    }

    // No element of any type outside the region (a locked neighbour's) within the type's
    // spacing of `on_face`, a point on the region's face.
    bool open_beyond(const Vec3& on_face) const {
        bool open = true;
        g_.grid.for_each_within(
            on_face, spread_, [&](int j) { return g_.out[j].p; },
            [&](int j) { open = open && region_.inside(g_.out[j].p); });
        return open;
    }

    // A place to try, and the input element whose nearest of the type it is shaped as.
    struct Site {
        Vec3 p;
        int like = -1;
        double clearance = 0.0;  // when the sites were gathered
    };

    // The places of the call's unlocked elements of other types, each shaped after the input
    // element it copies.
    void element_sites() {
        sites_.clear();
        for (int i = first_; i < static_cast<int>(g_.out.size()); ++i) {
            const OutElement& o = g_.out[i];
            if (o.type != t_ && !o.locked && !is_removed(i))
                sites_.push_back({o.p, o.match >= 0 ? o.match : o.source, clearance(o.p)});
        }
    }

    // Points around the call's unlocked elements of the type, kVoidProbe hard cores away
    // along probe_directions, that stand `floor` or more from the type's elements: the gaps
    // of a packing its growth jammed (most probes do not: a million spheres would otherwise
    // keep 52 million sites).
    void void_sites(double floor) {
        sites_.clear();
        const std::vector<Vec3> directions = probe_directions(g_.metric.dimension);
        for (int i = first_; i < static_cast<int>(g_.out.size()); ++i) {
            const OutElement& o = g_.out[i];
            if (o.type != t_ || o.locked || is_removed(i)) continue;
            for (const double r : kVoidProbe)
                for (const Vec3& u : directions) {
                    const Vec3 p = o.p + u * (r * core_);
                    if (!region_.inside(p)) continue;
                    if (const double c = clearance(p); c >= floor) sites_.push_back({p, o.match >= 0 ? o.match : o.source, c});
                }
        }
    }

    // An element of the type at the site (on the layer the type's input element lies at),
    // shaped as the type's input element nearest the site's.
    bool try_site(const Site& site) {
        const Vec3 near_input = site.like >= 0 ? g_.input.centroid[site.like] : Vec3{};
        OutElement e;
        e.type = t_;
        e.source = g_.input.nearest_in_pool(t_, near_input, 1e300);
        if (e.source < 0) return false;
        e.p = site.p;
        g_.register_on_layer(e.source, e.p);
        if (g_.metric.dimension == 2) e.p.z = 0.0;
        e.frame = g_.frame_at(e.p);
        if (!g_.fits_region(region_, -1, e.source, e.frame, e.p, mine_)) return false;
        if (!g_.crowd_allows(e.p)) return false;
        if (squeeze_ && !make_room(e)) return false;
        g_.sample_positions(-1, e.source, e.frame, e.p, mine_);
        if (!overlapped(e)) return false;
        for (size_t k = 0; k < pushed_.size(); ++k)
            if (!overlapped_by(pushed_[k], pushed_to_[k])) return false;
        for (const int j : overlapped_) removed_[j - first_] = 1;
        for (size_t k = 0; k < pushed_.size(); ++k) {
            g_.move(pushed_[k], pushed_to_[k]);
            own_.move(pushed_[k], pushed_to_[k]);
        }
        e.match = e.source;
        e.born = g_.round;
        e.id = g_.next_id++;
        const int k = g_.add(e);
        removed_.push_back(0);
        own_.insert(k, e.p);
        return true;
    }

    // The type's elements nearer to e than its hard core pushed out to it, e moving too:
    // Gauss-Seidel sweeps over the pairs of the type's elements around e, each pair closer
    // than the core moved apart (half each when both may move). The call's unlocked elements
    // within 1.5 cores of e may move, those beyond stay. Fills pushed_ / pushed_to_ and sets
    // e.p; false when the sweeps do not settle within kPushSweeps, or an element would move
    // further than kMaxPush cores or leave the region.
    bool make_room(OutElement& e) {
        pushed_.clear();
        pushed_to_.clear();
        ids_.assign(1, -1);
        pos_.assign(1, e.p);
        free_.assign(1, 1);
        own_.query(
            e.p, (2.5 + kMaxPush) * core_, [&](int j) { return g_.out[j].p; }, near_);
        for (const int j : near_) {
            if (is_removed(j)) continue;
            ids_.push_back(j);
            pos_.push_back(g_.out[j].p);
            free_.push_back(j >= first_ && !g_.out[j].locked && norm(g_.out[j].p - e.p) < 1.5 * core_);
        }
        from_ = pos_;
        if (!push_apart(push_distance(e.p))) return false;
        for (size_t k = 0; k < pos_.size(); ++k) {
            if (!free_[k]) continue;
            const double moved = norm(pos_[k] - from_[k]);
            if (moved > kMaxPush * core_) return false;
            if (k == 0 || moved == 0.0) continue;
            const OutElement& o = g_.out[ids_[k]];
            if (!g_.fits_region(region_, o.kept, o.source, o.frame, pos_[k], theirs_)) return false;
            pushed_.push_back(ids_[k]);
            pushed_to_.push_back(pos_[k]);
        }
        e.p = pos_[0];
        return g_.fits_region(region_, -1, e.source, e.frame, e.p, mine_) && g_.crowd_allows(e.p);
    }

    // The distance make_room pushes the pairs around a site at p to: drawn (keyed by the
    // site's world cell) from the lower half of the exemplar's nearest distances of the
    // type, never under its hard core. Pushed to the hard core itself, every pushed pair
    // stood at it and the type's pair correlation grew a spike there.
    double push_distance(const Vec3& p) const {
        const core::KeyedRng rng(g_.options.seed, core::Purpose::grow_squeeze,
                                 core::lattice_key(p.x, p.y, p.z, 0.25 * core_), static_cast<std::uint64_t>(t_));
        const double q = g_.bounds.centroids.quantile(t_, t_, 0.5 * rng.uniform(0));
        return std::max(core_, q);
    }

    // The sweeps of make_room; true once a sweep finds no pair closer than `distance`.
    bool push_apart(double distance) {
        const int n = static_cast<int>(pos_.size());
        for (int sweep = 0; sweep < kPushSweeps; ++sweep) {
            bool crowded = false;
            for (int a = 0; a < n; ++a)
                for (int b = a + 1; b < n; ++b) {
                    if (!free_[a] && !free_[b]) continue;
                    const Vec3 d = pos_[b] - pos_[a];
                    const double len = norm(d);
                    // The new element's pairs get `distance`; a pair already there keeps
                    // what it had, the hard core at least.
                    const double want = a == 0 ? distance : std::min(distance, std::max(core_, norm(from_[b] - from_[a])));
                    if (len >= want) continue;
                    crowded = true;
                    const Vec3 dir = len > 1e-12 * core_ ? d / len : Vec3{1.0, 0.0, 0.0};
                    const double share = free_[a] && free_[b] ? 0.5 : 1.0;
                    const Vec3 step = dir * ((want * (1.0 + 1e-9) - len) * share);
                    if (free_[a]) move_pushed(a, pos_[a] - step);
                    if (free_[b]) move_pushed(b, pos_[b] + step);
                }
            if (!crowded) return true;
        }
        return false;
    }

    void move_pushed(int k, Vec3 to) {
        g_.keep_on_layer(pos_[k], to);
        if (g_.metric.dimension == 2) to.z = 0.0;
        pos_[k] = to;
    }

    // The elements e overlaps, in overlapped_; false when one of them may not be removed or
    // they take more room than kRoomRatio times e's.
    bool overlapped(const OutElement& e) {
        overlapped_.clear();
        room_ = 0.0;
        return overlapped_at(e.p, -1, kRoomRatio * room_of(g_, t_));
    }

    // Element `pushed` (of the type) at p: the elements other than the type's it overlaps
    // there added to overlapped_, each at most once; false as overlapped's. Each pushed
    // element may clear kRoomRatio times its room more.
    bool overlapped_by(int pushed, const Vec3& p) {
        const OutElement& o = g_.out[pushed];
        g_.sample_positions(o.kept, o.source, o.frame, p, mine_);
        return overlapped_at(p, pushed, kRoomRatio * room_of(g_, t_) * static_cast<double>(2 + pushed_.size()));
    }

    bool overlapped_at(const Vec3& p, int self, double allowed) {
        g_.grid.query(
            p, reach_, [&](int j) { return g_.out[j].p; }, near_);
        for (const int j : near_) {
            if (j == self || is_removed(j)) continue;
            if (std::find(overlapped_.begin(), overlapped_.end(), j) != overlapped_.end()) continue;
            const OutElement& o = g_.out[j];
            if (squeeze_ && o.type == t_) continue;  // make_room kept the type's own core
            bool hit = norm(o.p - p) < g_.hard_core(t_, o.type);
            if (!hit && g_.bounds.has_samples) {
                g_.sample_positions(o.kept, o.source, o.frame, o.p, theirs_);
                const double core2 = g_.sample_core(t_, o.type) * g_.sample_core(t_, o.type);
                for (const Vec3& a : mine_)
                    for (const Vec3& b : theirs_) hit = hit || dot(a - b, a - b) < core2;
            }
            if (!hit) continue;
            if (j < first_ || o.locked || rare_[o.type]) return false;
            room_ += room_of(g_, o.type);
            if (room_ > allowed) return false;
            overlapped_.push_back(j);
        }
        return true;
    }

    Grower::Impl& g_;
    const int first_;
    const Domain& region_;
    const std::vector<char>& rare_;  // per type: rare, never removed (a glass took its plate)
    std::vector<char>& removed_;  // per element from first_ on
    double reach_ = 0.0, spread_ = 1.0, core_ = 0.0, room_ = 0.0;
    bool squeeze_ = false;  // the type's own elements pushed to make room (kSqueeze)
    // make_room's local state: the type's elements around the site (the new element first,
    // id -1), their places during and before the sweeps, whether each may move; and the
    // elements it moves with their new places.
    std::vector<Site> sites_;
    std::vector<int> ids_, pushed_;
    std::vector<Vec3> pos_, from_, pushed_to_;
    std::vector<char> free_;
    int t_ = 0;
    core::DynamicGrid own_;  // the type's elements
    std::vector<int> near_, overlapped_;
    std::vector<Vec3> mine_, theirs_;
};

}  // namespace

// The type's elements in the region (the call's and those there before) and the count the
// exemplar's density asks of it there.
std::pair<int, double> count_by_density(const Grower::Impl& g, int t, const Domain& region, const std::vector<char>& gone,
                                         int first) {
    int have = 0;
    for (int i = 0; i < static_cast<int>(g.out.size()); ++i) {
        const bool removed = i >= first && gone[i - first];
        have += !removed && g.out[i].type == t && region.inside(g.out[i].p);
    }
    return {have, g.metric.params.type_density[t] * region.measure()};
}

bool packed(const Grower::Impl& g, int t) {
    if (t >= static_cast<int>(g.metric.params.type_density.size()) || !(g.metric.params.type_density[t] > 0.0))
        return false;
    const double spacing = std::pow(1.0 / g.metric.params.type_density[t], 1.0 / g.metric.dimension);
    return g.hard_core(t, t) >= kPackedCore * spacing;
}

TypeCompletion complete_rare_types(Grower::Impl& g, int first, const Domain& region) {
    TypeCompletion result;
    const size_t types = g.exemplar.types.size();
    result.completed.assign(types, 0);
    if (g.exemplar.elements.empty()) return result;
    std::vector<double> share(types, 0.0);
    for (const Element& e : g.exemplar.elements) share[e.type] += 1.0 / static_cast<double>(g.exemplar.elements.size());
    std::vector<char> rare(types, 0), gone(g.out.size() - first, 0);
    for (size_t t = 0; t < types; ++t) rare[t] = share[t] > 0.0 && share[t] < kRareShare;
    RareInsertion insertion(g, first, region, rare, gone);
    const auto record = [&](size_t t, int added, bool squeezed) {
        result.completed[t] = result.completed[t] || added > 0;
        result.inserted += added;
        if (squeezed) result.squeezed += added;
    };
    // First the types short of the exemplar's density (a packing growth jammed below it),
    // then those short of their share: a minority's insertions take the room of the others,
    // which the share asks for.
    const bool layered = g.layer[0] || g.layer[1] || g.layer[2];
    for (size_t t = 0; t < types; ++t) {
        const bool majority = !g.bounds.has_samples && !layered && share[t] >= kMinorityShare;
        if (!majority) continue;
        if (!packed(g, static_cast<int>(t))) continue;
        const auto [have, expected] = count_by_density(g, static_cast<int>(t), region, gone, first);
        if (!(have < kRareShortfall * expected)) continue;
        record(t, insertion.insert(static_cast<int>(t), static_cast<int>(std::lround(expected)) - have, true), true);
    }
    for (size_t t = 0; t < types; ++t) {
        const bool minority = !g.bounds.has_samples && share[t] < kMinorityShare;
        if (!rare[t] && !minority) continue;
        int have = 0, total = 0;
        for (size_t k = 0; k < gone.size(); ++k) {
            if (gone[k]) continue;
            ++total;
            have += g.out[first + k].type == static_cast<int>(t);
        }
        const double expected = share[t] * total;
        if (!(have < kRareShortfall * expected)) continue;
        record(t, insertion.insert(static_cast<int>(t), static_cast<int>(std::lround(expected)) - have, false), !rare[t]);
    }
    result.removed = static_cast<int>(std::count(gone.begin(), gone.end(), 1));
    if (result.removed > 0) g.remove_and_renumber(first, gone);
    return result;
}

}  // namespace tessera::grow
