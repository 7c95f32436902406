// The analysis of classes with few elements (sparse_classes.hpp).
#include "pcf/sparse_classes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pcf/pair_distance.hpp"

namespace tessera::pcf {

const PcfSparseClass* sparse_class(const PcfModel& model, int c) {
    for (const PcfSparseClass& s : model.sparse)
        if (s.cls == c) return &s;
    return nullptr;
}

std::vector<PcfSparseClass> analyse_sparse_classes(const PcfPoints& points, const PcfModel& model) {
    const int classes = static_cast<int>(model.classes.size());
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<PcfSparseClass> out;
    for (int c = 0; c < classes; ++c) {
        if (model.counts[c] >= kPcfSparseCount || model.counts[c] < 1) continue;
        PcfSparseClass s;
        s.cls = c;
        s.closest.assign(classes, inf);
        std::vector<double> farthest(classes, 0.0);  // over c's elements, of the nearest distance to each class
        double own = inf;
        for (size_t i = 0; i < points.p.size(); ++i) {
            if (points.cls[i] != c) continue;
            std::vector<double> nearest(classes, inf);
            for (size_t j = 0; j < points.p.size(); ++j) {
                const int o = points.cls[j];
                if (j == i || o < 0) continue;
                const Vec3 v = points.p[i] - points.p[j];
                const double d = std::sqrt(v.x * v.x + v.y * v.y);
                if (o == c) own = std::min(own, d);
                const double x = normalised_pair_distance(d, points.radius[i], points.radius[j], model.r_max);
                nearest[o] = std::min(nearest[o], x);
            }
            for (int o = 0; o < classes; ++o) {
                s.closest[o] = std::min(s.closest[o], nearest[o]);
                if (nearest[o] < inf) farthest[o] = std::max(farthest[o], nearest[o]);
            }
        }
        // A single element has no spacing of its own: half the mean spacing of its density.
        s.spacing = own < inf ? own : 0.5 * std::sqrt(model.area / model.counts[c]);
        s.tether.assign(classes, 0.0);
        for (int p : model.parents[c])
            if (farthest[p] > 0.0) s.tether[p] = farthest[p] + model.settings.sigma;
        for (int o = 0; o < classes; ++o)
            if (o == c || !(s.closest[o] < inf)) s.closest[o] = 0.0;
        out.push_back(std::move(s));
    }
    return out;
}

}  // namespace tessera::pcf
