// Palette entries of a brush canvas (brush/palette.hpp).
#include "brush/palette.hpp"

#include "core/spatial_grid.hpp"
#include "tessera/error.hpp"
#include "tessera/det.hpp"

namespace tessera::brush {

PaletteEntry prepare_entry(const std::string& name, const Exemplar& exemplar, int dimension,
                           const BrushOptions& options) {
    exemplar.validate("palette entry '" + name + "'");
    if (exemplar.dimension != dimension)
        throw Error(ErrorKind::input, "palette entry '" + name + "' is " + std::to_string(exemplar.dimension) +
                                          "D but the canvas is " + std::to_string(dimension) + "D");
    PaletteEntry entry;
    entry.name = name;
    entry.exemplar = exemplar;
    entry.exemplar.update_positions();
    entry.spacing = exemplar.elements.size() > 1 ? mean_nearest_neighbor_distance(entry.exemplar) : 1.0;
    if (!(entry.spacing > 0.0)) entry.spacing = 1.0;
    entry.radius = options.radius * entry.spacing;
    for (int t = 0; t < static_cast<int>(exemplar.types.size()); ++t) {
        entry.weights.push_back(brush_sample_weights(entry.exemplar, t));
        entry.graph.push_back(brush_element_graph(entry.exemplar, t));
    }
    GrowOptions grow;
    grow.seed = options.seed;
    grow.threads = options.threads;
    entry.grower = std::make_shared<const Grower>(entry.exemplar, grow);
    return entry;
}

void index_neighbourhoods(PaletteEntry& entry) {
    const Exemplar& ex = entry.exemplar;
    std::vector<Vec3> points;
    points.reserve(ex.samples.size());
    for (const Sample& s : ex.samples) points.push_back(s.p);
    core::SpatialGrid grid;
    grid.build(points, entry.radius, ex.dimension);
    entry.neighbourhoods.clear();
    entry.by_type.assign(entry.out_type.size(), {});
    for (const Element& e : ex.elements) entry.by_type[e.type].resize(static_cast<size_t>(e.sample_count));
    // Inner samples (whose whole neighbourhood lies in the exemplar) first; a type with none
    // (an exemplar smaller than a neighbourhood) uses all of its samples.
    std::vector<std::vector<char>> has_inner(ex.types.size());
    for (int pass = 0; pass < 2; ++pass) {
        if (pass == 1)
            for (size_t t = 0; t < ex.types.size(); ++t)
                for (const auto& list : entry.by_type[t]) has_inner[t].push_back(!list.empty());
        for (int i = 0; i < static_cast<int>(ex.samples.size()); ++i) {
            const Sample& s = ex.samples[i];
            const int type = ex.elements[s.element].type;
            const bool inner = ex.domain.distance_to_boundary(s.p) >= entry.radius;
            if (pass == 0 ? !inner : (inner || has_inner[type][s.sample_id])) continue;
            InputNeighbourhood n;
            n.sample = i;
            n.type = entry.out_type[type];
            n.weight = entry.weights[type][s.sample_id];
            grid.for_each_within(s.p, entry.radius, [&](int j, double) {
                const Sample& o = ex.samples[j];
                if (o.element == s.element) return;
                const int ot = ex.elements[o.element].type;
                n.offsets.push_back(o.p - s.p);
                n.weights.push_back(entry.weights[ot][o.sample_id]);
                n.types.push_back(entry.out_type[ot]);
                n.inverse_summed.push_back(1.0 / (n.weights.back() + n.weight));
            });
            entry.by_type[type][s.sample_id].push_back(static_cast<int>(entry.neighbourhoods.size()));
            entry.neighbourhoods.push_back(std::move(n));
        }
    }
}

}  // namespace tessera::brush
