// Copies one element (samples, radius, pose, attributes) from one arrangement to another:
// how tiles take their neighbours' elements and how tiles are merged.
#pragma once

#include <vector>

#include "tessera/exemplar.hpp"

namespace tessera::world {

inline int append_element(const Exemplar& from, const Element& e, Exemplar& to, bool locked = false) {
    std::vector<Vec3> samples(e.sample_count);
    for (int s = 0; s < e.sample_count; ++s) samples[s] = from.samples[e.first_sample + s].p;
    const int i = to.add_element(e.type, samples, e.radius);
    Element& c = to.elements[i];
    c.orientation = e.orientation;
    c.scale = e.scale;
    c.attributes = e.attributes;
    c.locked = locked;
    return i;
}

}  // namespace tessera::world
