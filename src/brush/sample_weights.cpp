// Brushing's element representation (section 2 of the paper): a weight per sample, acting
// as the sample's bounding radius (Figure 4), and the element graph joining the samples of
// an element (section 2.2). Both are read from the exemplar's types, with defaults here.
#include <algorithm>
#include <cmath>
#include <limits>

#include "tessera/brush.hpp"
#include "tessera/error.hpp"

namespace tessera {

namespace {

// Half the 10% quantile of the distance from the type's samples to the nearest sample of
// another element: the bounding radius that the exemplar's closest contacts allow.
double default_weight(const Exemplar& ex, int type) {
    std::vector<double> nearest;
    for (const Sample& s : ex.samples) {
        if (ex.elements[s.element].type != type) continue;
        double best = std::numeric_limits<double>::infinity();
        for (const Sample& o : ex.samples)
            if (o.element != s.element) best = std::min(best, squared_norm(o.p - s.p));
        if (std::isfinite(best)) nearest.push_back(std::sqrt(best));
    }
    if (nearest.empty()) return 0.5;  // a lone element: any weight; the spacing is unknown too
    const size_t k = nearest.size() / 10;
    std::nth_element(nearest.begin(), nearest.begin() + static_cast<std::ptrdiff_t>(k), nearest.end());
    return std::max(0.5 * nearest[k], 1e-9);
}

int sample_count_of_type(const Exemplar& ex, int type) {
    for (const Element& e : ex.elements)
        if (e.type == type) return e.sample_count;
    return 0;
}

}  // namespace

std::vector<double> brush_sample_weights(const Exemplar& ex, int type) {
    const ElementType& t = ex.types.at(static_cast<size_t>(type));
    const int count = sample_count_of_type(ex, type);
    if (!t.weights.empty()) return t.weights;
    double radius = 0.0;
    for (const Element& e : ex.elements)
        if (e.type == type && e.radius > 0.0) {
            radius = e.radius;
            break;
        }
    const double w = radius > 0.0 ? radius : default_weight(ex, type);
    return std::vector<double>(static_cast<size_t>(std::max(count, 1)), w);
}

std::vector<std::array<int, 2>> brush_element_graph(const Exemplar& ex, int type) {
    const ElementType& t = ex.types.at(static_cast<size_t>(type));
    if (!t.graph.empty()) return t.graph;
    std::vector<std::array<int, 2>> chain;
    const int count = sample_count_of_type(ex, type);
    for (int i = 0; i + 1 < count; ++i) chain.push_back({i, i + 1});
    return chain;
}

}  // namespace tessera
