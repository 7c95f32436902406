// Every output element's samples in a grid, by sample number, with the element that owns
// each: the queries of the passes that look between multi-sample elements (the sample-hole
// fill, the thinning's hole test). Private to growth.
#pragma once

#include <vector>

#include "core/dynamic_grid.hpp"
#include "grow/grow_state.hpp"

namespace tessera::grow {

class SampleIndex {
public:
    // Indexes every element of g.out; `cell`: the grid's cell size (about the query radius).
    SampleIndex(const Grower::Impl& g, double cell) : g_(g), grid_(cell, g.metric.dimension) {
        for (int i = 0; i < static_cast<int>(g.out.size()); ++i) add(i);
    }
    // Adds element i's samples (an element appended after construction).
    void add(int i) {
        samples_of(i, buffer_);
        for (const Vec3& q : buffer_) {
            grid_.insert(static_cast<int>(at_.size()), q);
            at_.push_back(q);
            owner_.push_back(i);
        }
    }
    // Element i's sample positions into `out`.
    void samples_of(int i, std::vector<Vec3>& out) const {
        const OutElement& o = g_.out[i];
        g_.sample_positions(o.kept, o.source, o.frame, o.p, out);
    }
    // visit(sample) for each sample within `radius` of p, in no particular order.
    template <class Visit>
    void for_each_within(const Vec3& p, double radius, const Visit& visit) const {
        grid_.for_each_within(p, radius, [&](int s) { return at_[s]; }, visit);
    }
    const Vec3& at(int sample) const { return at_[sample]; }
    int owner(int sample) const { return owner_[sample]; }

private:
    const Grower::Impl& g_;
    core::DynamicGrid grid_;
    std::vector<Vec3> at_;
    std::vector<int> owner_;
    std::vector<Vec3> buffer_;
};

}  // namespace tessera::grow
