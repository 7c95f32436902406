#include "det/provenance.hpp"

namespace tessera::det {

std::vector<Vec3> element_centroids(const std::vector<Element>& elements, int dimension) {
    std::vector<Vec3> p;
    p.reserve(elements.size());
    for (const Element& e : elements) {
        Vec3 q = e.position;
        if (dimension == 2) q.z = 0.0;
        p.push_back(q);
    }
    return p;
}

int append_copy(Provenance into, const Exemplar& exemplar, int source, const Quat& rotation, const Vec3& shift,
                int dimension) {
    Arrangement& out = into.out;
    const Element& src = exemplar.elements[source];
    Element e = src;
    e.first_sample = static_cast<int>(out.samples.size());
    e.id = kNewElementId;  // numbered by the session (det/session_steps.hpp, number_new_elements)
    e.locked = false;
    const int index_out = static_cast<int>(out.elements.size());
    for (int s = 0; s < src.sample_count; ++s) {
        Sample smp = exemplar.samples[src.first_sample + s];
        smp.p = rotation.rotate(smp.p) + shift;
        if (dimension == 2) smp.p.z = 0.0;
        smp.element = index_out;
        out.samples.push_back(smp);
        into.source_sample.push_back(src.first_sample + s);
    }
    e.position = rotation.rotate(src.position) + shift;
    e.orientation = rotation * src.orientation;
    if (dimension == 2) e.position.z = 0.0;
    out.elements.push_back(std::move(e));
    into.source_element.push_back(source);
    return index_out;
}

void keep_only(Provenance of, const std::vector<char>& keep) {
    Arrangement& out = of.out;
    std::vector<Element> elements;
    std::vector<Sample> samples;
    std::vector<int> source_sample, source_element;
    for (size_t e = 0; e < out.elements.size(); ++e) {
        if (!keep[e]) continue;
        Element element = out.elements[e];
        const int index = static_cast<int>(elements.size());
        element.first_sample = static_cast<int>(samples.size());
        for (int s = 0; s < element.sample_count; ++s) {
            const int old = out.elements[e].first_sample + s;
            Sample smp = out.samples[old];
            smp.element = index;
            samples.push_back(smp);
            source_sample.push_back(of.source_sample[old]);
        }
        source_element.push_back(of.source_element[e]);
        elements.push_back(std::move(element));
    }
    out.elements = std::move(elements);
    out.samples = std::move(samples);
    of.source_sample = std::move(source_sample);
    of.source_element = std::move(source_element);
}

}  // namespace tessera::det
