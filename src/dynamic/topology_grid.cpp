// dynamic/topology_grid.cpp — samples on their element's grid, and grid neighbourhoods.
#include "dynamic/topology_grid.hpp"

#include <cmath>

#include "tessera/animation.hpp"
#include "tessera/error.hpp"

namespace tessera::dynamic {

TopologyGrid::TopologyGrid(const Exemplar& data, const std::string& source) {
    const size_t n = data.samples.size();
    element_.assign(n, -1), row_.assign(n, 0), col_.assign(n, 0);
    for (size_t e = 0; e < data.elements.size(); ++e) {
        const Element& el = data.elements[e];
        const ElementTopology kind = effective_topology(data, el.type);
        if (kind == ElementTopology::none && el.sample_count > 1)
            throw Error(ErrorKind::input, source + ": type '" + data.types[el.type].name +
                                              "' has multi-sample elements of topology none; give them the "
                                              "topology thread or sheet");
        const int cols = kind == ElementTopology::sheet ? data.types[el.type].sheet_columns : el.sample_count;
        kind_.push_back(kind);
        first_.push_back(el.first_sample);
        cols_.push_back(cols);
        rows_.push_back(el.sample_count / cols);
        for (int k = 0; k < el.sample_count; ++k) {
            const int s = el.first_sample + k;
            element_[s] = static_cast<int>(e), row_[s] = k / cols, col_[s] = k % cols;
        }
    }
}

std::vector<GridOffset> grid_offsets(ElementTopology kind, int half_size, int half_window, NeighbourhoodShape shape,
                                     double sigma_p, double sigma_t) {
    const int hr = kind == ElementTopology::sheet ? half_size : 0;
    const int hc = kind == ElementTopology::none ? 0 : half_size;
    // Eq. 10, with the grid step as the unit of length (so sigma_p is in half-widths).
    const double inv_p2 = sigma_p > 0.0 ? 1.0 / (sigma_p * half_size * sigma_p * half_size) : 0.0;
    const double inv_t2 = sigma_t > 0.0 ? 1.0 / (sigma_t * sigma_t) : 0.0;
    std::vector<GridOffset> out{{0, 0, 0, 1.0}};
    for (int dt = -half_window; dt <= half_window; ++dt)
        for (int dr = -hr; dr <= hr; ++dr)
            for (int dc = -hc; dc <= hc; ++dc) {
                if (dr == 0 && dc == 0 && dt == 0) continue;
                const bool spatial = dt == 0, trail = dr == 0 && dc == 0;
                if (shape == NeighbourhoodShape::compact && !spatial && !trail) continue;
                const double kappa = std::exp(-double(dr * dr + dc * dc) * inv_p2 - double(dt * dt) * inv_t2);
                out.push_back({dr, dc, dt, kappa});
            }
    return out;
}

}  // namespace tessera::dynamic
