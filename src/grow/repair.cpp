// Crowding repair of a growth round (grow/repair.hpp).
#include "grow/repair.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <unordered_set>

#include "core/crowding_repair.hpp"

namespace tessera::grow {

namespace {

// Tiles of this many reaches: a part's bounding box stays compact whatever the horizon's
// shape (a ring around a large grown region would make the repair's grid cover the whole
// region, and its cost grow faster than the output).
constexpr double kTileReaches = 8.0;

// Repairs one part: `movable`, and the elements within reach of it locked in the copy.
int repair_part(Grower::Impl& g, const std::vector<int>& movable, const Domain* region, double reach) {
    // The movable elements, then the fixed ones within reach of them (locked in the copy).
    std::vector<int> members = movable;
    std::unordered_set<int> in(movable.begin(), movable.end());
    std::vector<int> near;
    for (const int v : movable) {
        g.grid.query(
            g.out[v].p, reach, [&](int i) { return g.out[i].p; }, near);
        for (const int i : near)
            if (in.insert(i).second) members.push_back(i);
    }
    std::sort(members.begin() + static_cast<long>(movable.size()), members.end());
    Exemplar part;
    part.dimension = g.metric.dimension;
    part.types = g.exemplar.types;
    std::vector<Vec3> samples;
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (size_t k = 0; k < members.size(); ++k) {
        const OutElement& o = g.out[members[k]];
        g.sample_positions(o.kept, o.source, o.frame, o.p, samples);
        const int e = part.add_element(o.type, samples);
        part.elements[e].radius =
            o.kept >= 0 ? g.existing.elements[o.kept].radius : g.exemplar.elements[o.source].radius;
        part.elements[e].locked = k >= movable.size() || o.locked;
        for (const Vec3& q : samples)
            for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], q[a]), hi[a] = std::max(hi[a], q[a]);
    }
    const Vec3 pad{g.metric.params.spacing, g.metric.params.spacing, g.metric.params.spacing};
    Vec3 blo = lo - pad, bhi = hi + pad;
    if (part.dimension == 2) blo.z = bhi.z = 0.0;
    const Domain around = Domain::box(blo, bhi, part.dimension);
    core::CrowdingRepairOptions options;
    options.threads = g.threads;  // the same result for any count
    // An open region (a world's tile) holds centres only: the repair may move samples past
    // its edge, and a move that would take a centre out of it is not made.
    const bool walled = region && !g.open_region;
    const core::CrowdingRepairReport report =
        core::repair_crowding(part, walled ? *region : around, g.bounds, options);
    for (size_t k = 0; k < movable.size(); ++k) {
        const Element& e = part.elements[k];
        if (e.locked) continue;
        Vec3 c;
        for (int s = 0; s < e.sample_count; ++s) c = c + part.samples[e.first_sample + s].p;
        c = c * (1.0 / e.sample_count);
        g.keep_on_layer(g.out[movable[k]].p, c);
        if (region && g.open_region && !region->inside(c)) continue;
        g.move(movable[k], c);
    }
    return report.remaining;
}

// Whether some movable element has a neighbour closer than the farthest bound a repair
// holds their types to. When none has, a repair would find nothing to move (every bound
// it checks lies below that one): the part is skipped, which saves building it. Centroid
// bounds only, so for exemplars of single-sample elements.
bool may_crowd(const Grower::Impl& g, const std::vector<int>& movable) {
    bool close = false;
    for (const int v : movable) {
        const OutElement& e = g.out[v];
        g.grid.for_each_within(
            e.p, g.repair_reach, [&](int i) { return g.out[i].p; },
            [&](int i) {
                if (i != v && norm(g.out[i].p - e.p) < g.repair_bound(e.type, g.out[i].type)) close = true;
            });
        if (close) return true;
    }
    return false;
}

}  // namespace

int repair_round(Grower::Impl& g, const std::vector<int>& movable, const Domain* region) {
    if (movable.empty()) return 0;
    const double reach = g.reach + 2.0 * g.extent + g.metric.params.spacing;
    const double tile = kTileReaches * reach;
    std::map<std::array<long long, 3>, std::vector<int>> tiles;  // ordered: a fixed order of parts
    for (const int v : movable) {
        std::array<long long, 3> key{0, 0, 0};
        for (int k = 0; k < g.metric.dimension; ++k)
            key[k] = static_cast<long long>(std::floor(g.out[v].p[k] / tile));
        tiles[key].push_back(v);
    }
    int remaining = 0;
    for (const auto& [key, part] : tiles)
        if (g.bounds.has_samples || may_crowd(g, part)) remaining += repair_part(g, part, region, reach);
    return remaining;
}

}  // namespace tessera::grow
