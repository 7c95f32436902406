// Element layouts for the motion analysis (low_pass.hpp): particles, or a grid of samples
// (a thread is one row, a sheet rows x columns), from each type's effective topology.
#include "analysis/low_pass.hpp"

namespace tessera::analysis {

const char* topology_word(ElementTopology topology) {
    switch (topology) {
        case ElementTopology::thread:
            return "thread";
        case ElementTopology::sheet:
            return "sheet";
        default:
            return "particle";
    }
}

std::vector<Layout> element_layouts(const Exemplar& data) {
    // effective_topology scans the elements for an automatic type: once per type.
    std::vector<ElementTopology> by_type(data.types.size());
    for (size_t t = 0; t < data.types.size(); ++t) by_type[t] = effective_topology(data, static_cast<int>(t));
    std::vector<Layout> layouts(data.elements.size());
    for (size_t i = 0; i < data.elements.size(); ++i) {
        const Element& e = data.elements[i];
        Layout& l = layouts[i];
        l.topology = by_type[e.type];
        if (l.topology == ElementTopology::thread) {
            l.kind = Kind::grid;
            l.columns = e.sample_count;
        } else if (l.topology == ElementTopology::sheet) {
            l.kind = Kind::grid;
            l.columns = data.types[e.type].sheet_columns;
            l.rows = e.sample_count / l.columns;
        } else {
            l.topology = ElementTopology::none;
            l.columns = e.sample_count;
        }
    }
    return layouts;
}

}  // namespace tessera::analysis
