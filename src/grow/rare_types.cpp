// Rare types brought back to their share (grow/rare_types.hpp).
#include "grow/rare_types.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

namespace tessera::grow {

namespace {

// An inserted element may remove elements that take up to this many times its own room
// (the sum of its samples' hard-core balls): where more of them overlap it, the site is
// passed over rather than left with a hole around the new element.
constexpr double kRoomRatio = 1.5;

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

    // Inserts up to `want` elements of type t; returns how many.
    int insert(int t, int want) {
        t_ = t;
        spread_ = type_spacing(t);
        own_ = core::DynamicGrid(spread_, g_.metric.dimension);
        for (int i = 0; i < static_cast<int>(g_.out.size()); ++i)
            if (g_.out[i].type == t && !is_removed(i)) own_.insert(i, g_.out[i].p);
        const double floor = g_.hard_core(t, t);
        std::priority_queue<std::pair<double, int>> sites;  // farthest first, then the lower index
        const int end = static_cast<int>(g_.out.size());
        for (int i = first_; i < end; ++i)
            if (g_.out[i].type != t && !g_.out[i].locked) sites.push({clearance(g_.out[i].p), -i});
        int inserted = 0;
        while (inserted < want && !sites.empty() && sites.top().first >= floor) {
            const auto [d, minus_i] = sites.top();
            sites.pop();
            const double now = clearance(g_.out[-minus_i].p);
            if (now < d) {  // an insertion came nearer since: back in line at its distance now
                sites.push({now, minus_i});
                continue;
            }
            if (try_site(-minus_i)) ++inserted;
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
    double clearance(const Vec3& p) const {
        double best = 2.0 * spread_;
        own_.for_each_within(
            p, best, [&](int j) { return g_.out[j].p; }, [&](int j) { best = std::min(best, norm(g_.out[j].p - p)); });
        return best;
    }

    // An element of the type at site element i's place (on the layer the type's input
    // element lies at), shaped as the type's input element nearest i's match.
    bool try_site(int i) {
        const OutElement& at = g_.out[i];
        const int like = at.match >= 0 ? at.match : at.source;
        const Vec3 near_input = like >= 0 ? g_.input.centroid[like] : Vec3{};
        OutElement e;
        e.type = t_;
        e.source = g_.input.nearest_in_pool(t_, near_input, 1e300);
        if (e.source < 0) return false;
        e.p = at.p;
        g_.register_on_layer(e.source, e.p);
        if (g_.metric.dimension == 2) e.p.z = 0.0;
        e.frame = g_.frame_at(e.p);
        if (!g_.fits_region(region_, -1, e.source, e.frame, e.p, mine_)) return false;
        if (!g_.crowd_allows(e.p)) return false;
        g_.sample_positions(-1, e.source, e.frame, e.p, mine_);
        if (!overlapped(e)) return false;
        for (const int j : overlapped_) removed_[j - first_] = 1;
        e.match = e.source;
        e.born = g_.round;
        e.id = g_.next_id++;
        const int k = g_.add(e);
        removed_.push_back(0);
        own_.insert(k, e.p);
        return true;
    }

    // The elements e overlaps, in overlapped_; false when one of them may not be removed or
    // they take more room than kRoomRatio times e's.
    bool overlapped(const OutElement& e) {
        overlapped_.clear();
        g_.grid.query(
            e.p, reach_, [&](int j) { return g_.out[j].p; }, near_);
        double room = 0.0;
        const double allowed = kRoomRatio * room_of(g_, t_);
        for (const int j : near_) {
            if (is_removed(j)) continue;
            const OutElement& o = g_.out[j];
            bool hit = norm(o.p - e.p) < g_.hard_core(t_, o.type);
            if (!hit && g_.bounds.has_samples) {
                g_.sample_positions(o.kept, o.source, o.frame, o.p, theirs_);
                const double core2 = g_.sample_core(t_, o.type) * g_.sample_core(t_, o.type);
                for (const Vec3& a : mine_)
                    for (const Vec3& b : theirs_) hit = hit || dot(a - b, a - b) < core2;
            }
            if (!hit) continue;
            if (j < first_ || o.locked || rare_[o.type]) return false;
            room += room_of(g_, o.type);
            if (room > allowed) return false;
            overlapped_.push_back(j);
        }
        return true;
    }

    Grower::Impl& g_;
    const int first_;
    const Domain& region_;
    const std::vector<char>& rare_;  // per type: rare, never removed (a glass took its plate)
    std::vector<char>& removed_;  // per element from first_ on
    double reach_ = 0.0, spread_ = 1.0;
    int t_ = 0;
    core::DynamicGrid own_;  // the type's elements
    std::vector<int> near_, overlapped_;
    std::vector<Vec3> mine_, theirs_;
};

}  // namespace

int complete_rare_types(Grower::Impl& g, int first, const Domain& region, int& removed) {
    removed = 0;
    const size_t types = g.exemplar.types.size();
    if (types < 2 || g.exemplar.elements.empty()) return 0;
    std::vector<double> share(types, 0.0);
    for (const Element& e : g.exemplar.elements) share[e.type] += 1.0 / static_cast<double>(g.exemplar.elements.size());
    std::vector<char> rare(types, 0), gone(g.out.size() - first, 0);
    for (size_t t = 0; t < types; ++t) rare[t] = share[t] > 0.0 && share[t] < kRareShare;
    RareInsertion insertion(g, first, region, rare, gone);
    int inserted = 0;
    for (size_t t = 0; t < types; ++t) {
        if (!rare[t]) continue;
        int have = 0, total = 0;
        for (size_t k = 0; k < gone.size(); ++k) {
            if (gone[k]) continue;
            ++total;
            have += g.out[first + k].type == static_cast<int>(t);
        }
        const double expected = share[t] * total;
        if (!(have < kRareShortfall * expected)) continue;
        inserted += insertion.insert(static_cast<int>(t), static_cast<int>(std::lround(expected)) - have);
    }
    removed = static_cast<int>(std::count(gone.begin(), gone.end(), 1));
    if (removed > 0) g.remove_and_renumber(first, gone);
    return inserted;
}

}  // namespace tessera::grow
