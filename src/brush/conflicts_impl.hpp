// brush/conflicts_impl.hpp — for_each_conflict (brush/positions.hpp), a template over the
// caller's action so that the energy, the solve and the overlap counts share one query.
#pragma once

#include <algorithm>
#include <cmath>

namespace tessera::brush {

template <class Fn>
void for_each_conflict(const BrushCanvas::Impl& st, const OutputNeighbours& nb, Fn&& fn) {
    const Arrangement& arr = st.arrangement;
    double reach = 0.0;
    for (int s = 0; s < static_cast<int>(arr.samples.size()); ++s)
        reach = std::max(reach, arr.elements[arr.samples[s].element].scale * st.weight_of_sample(s));
    for (int s = 0; s < static_cast<int>(arr.samples.size()); ++s) {
        const Element& e = arr.elements[arr.samples[s].element];
        const double ws = e.scale * st.weight_of_sample(s);
        nb.grid.for_each_within(nb.points[s], ws + reach, [&](int o, double d2) {
            if (o <= s || arr.samples[o].element == arr.samples[s].element) return;
            const double summed = ws + arr.elements[arr.samples[o].element].scale * st.weight_of_sample(o);
            if (d2 < summed * summed) fn(s, o, summed, std::sqrt(d2));
        });
    }
}

}  // namespace tessera::brush
