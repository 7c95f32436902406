#include "det/session_region.hpp"

#include <algorithm>

#include "core/spatial_grid.hpp"
#include "det/session_steps.hpp"

namespace tessera::det {

namespace {

// Which elements a region's iterations touch: moving (1) or fixed context (2); 0 = neither.
std::vector<char> region_roles(const Arrangement& out, const Domain& region, double reach, int dimension) {
    const int n = static_cast<int>(out.elements.size());
    std::vector<char> role(n, 0);
    std::vector<Vec3> moving_samples;
    for (int e = 0; e < n; ++e) {
        const Element& el = out.elements[e];
        if (el.locked || !region.inside(el.position)) continue;
        role[e] = 1;
        for (int k = 0; k < el.sample_count; ++k) moving_samples.push_back(out.samples[el.first_sample + k].p);
    }
    if (moving_samples.empty()) return role;
    for (Vec3& p : moving_samples)
        if (dimension == 2) p.z = 0.0;
    // Candidates by the moving samples' bounds grown by the reach, then each sample of a
    // candidate against a grid of the moving samples.
    Box box{moving_samples.front(), moving_samples.front()};
    for (const Vec3& p : moving_samples)
        for (int k = 0; k < 3; ++k) box.lo[k] = std::min(box.lo[k], p[k]), box.hi[k] = std::max(box.hi[k], p[k]);
    core::SpatialGrid grid;
    grid.build(moving_samples, reach, dimension);
    for (int e = 0; e < n; ++e) {
        if (role[e] != 0) continue;
        const Element& el = out.elements[e];
        for (int k = 0; k < el.sample_count && role[e] == 0; ++k) {
            Vec3 p = out.samples[el.first_sample + k].p;
            if (dimension == 2) p.z = 0.0;
            bool near_box = true;
            for (int a = 0; a < dimension; ++a) near_box = near_box && p[a] >= box.lo[a] - reach && p[a] <= box.hi[a] + reach;
            if (near_box && grid.nearest(p, reach, [](int) { return true; }) >= 0) role[e] = 2;
        }
    }
    return role;
}

// The sub-problem: the elements with a role, context ones locked; `origin` maps each
// sub element to its element in `from`.
OutputState extract(const OutputState& from, const std::vector<char>& role, std::vector<int>& origin) {
    OutputState sub;
    const Arrangement& out = from.arrangement;
    Arrangement& a = sub.arrangement;
    a.dimension = out.dimension;
    a.types = out.types;
    a.attribute_names = out.attribute_names;
    a.domain = out.domain;
    origin.clear();
    for (size_t e = 0; e < out.elements.size(); ++e) {
        if (role[e] == 0) continue;
        Element el = out.elements[e];
        const int index = static_cast<int>(a.elements.size());
        el.first_sample = static_cast<int>(a.samples.size());
        el.locked = el.locked || role[e] == 2;
        for (int k = 0; k < el.sample_count; ++k) {
            Sample smp = out.samples[out.elements[e].first_sample + k];
            smp.element = index;
            a.samples.push_back(smp);
            sub.match.push_back(from.match.empty() ? -1 : from.match[out.elements[e].first_sample + k]);
        }
        a.elements.push_back(std::move(el));
        sub.source_element.push_back(from.source_element[e]);
        origin.push_back(static_cast<int>(e));
    }
    sub.key = sample_keys(a);
    // The vote keeps the sub-problem's own counts per type.
    sub.type_target.assign(a.types.size(), 0);
    for (const Element& el : a.elements)
        if (!el.locked) ++sub.type_target[el.type];
    return sub;
}

// The held arrangement with its moving elements replaced by the sub-problem's unlocked
// ones (which the repair may have removed some of), appended at the end.
void merge(OutputState& into, const OutputState& sub, const std::vector<char>& role) {
    const Arrangement& from = into.arrangement;
    OutputState merged;
    Arrangement& a = merged.arrangement;
    a.dimension = from.dimension;
    a.types = from.types;
    a.attribute_names = from.attribute_names;
    a.domain = from.domain;
    a.stats = std::move(into.arrangement.stats);
    const auto copy_element = [&](const OutputState& src, size_t e) {
        Element el = src.arrangement.elements[e];
        const int index = static_cast<int>(a.elements.size());
        const int first = el.first_sample;
        el.first_sample = static_cast<int>(a.samples.size());
        for (int k = 0; k < el.sample_count; ++k) {
            Sample smp = src.arrangement.samples[first + k];
            smp.element = index;
            a.samples.push_back(smp);
            merged.match.push_back(src.match.empty() ? -1 : src.match[first + k]);
        }
        a.elements.push_back(std::move(el));
        merged.source_element.push_back(src.source_element[e]);
    };
    for (size_t e = 0; e < from.elements.size(); ++e)
        if (role[e] != 1) copy_element(into, e);
    for (size_t e = 0; e < sub.arrangement.elements.size(); ++e)
        if (!sub.arrangement.elements[e].locked) copy_element(sub, e);
    merged.key = sample_keys(a);
    merged.type_target = into.type_target;
    into = std::move(merged);
}

}  // namespace

double iterate_region(DetSession::Impl& s, const Domain& region, int iterations) {
    s.state.arrangement.update_positions();
    const std::vector<char> role = region_roles(s.state.arrangement, region, 2.0 * s.params.radius, s.params.dimension);
    if (std::find(role.begin(), role.end(), 1) == role.end() || iterations == 0) return 0.0;
    std::vector<int> origin;
    OutputState whole = std::move(s.state);
    s.state = extract(whole, role, origin);
    s.state.arrangement.stats = std::move(whole.arrangement.stats);
    const auto put_back = [&] {
        whole.arrangement.stats = std::move(s.state.arrangement.stats);
        OutputState sub = std::move(s.state);
        s.state = std::move(whole);
        merge(s.state, sub, role);
    };
    double energy = 0.0;
    try {
        for (int it = 0; it < iterations; ++it) {
            energy = s.iterate_once(false);
            s.report("iteration", it, iterations, energy);
        }
    } catch (...) {  // cancelled: the arrangement as the last finished iteration left it
        put_back();
        number_new_elements(s.state.arrangement, s.next_id);
        throw;
    }
    put_back();
    number_new_elements(s.state.arrangement, s.next_id);
    return energy;
}

}  // namespace tessera::det
