// dynamic/element_lengths.cpp — rest lengths of threads and sheets (element_lengths.hpp).
#include "dynamic/element_lengths.hpp"

#include <algorithm>
#include <cmath>

#include "core/parallel.hpp"

namespace tessera::dynamic {

namespace {

void add_edge(std::vector<Edge>& out, const Vec3* p, int a, int b, double stretch) {
    if (a >= 0 && b >= 0) out.push_back({a, b, norm(p[b] - p[a]) * stretch});
}

// Moves both ends of each edge halfway towards its rest length; returns the worst strain
// seen before the move.
double sweep(Vec3* p, const std::vector<Edge>& edges, bool forward) {
    double worst = 0.0;
    const int n = static_cast<int>(edges.size());
    for (int i = 0; i < n; ++i) {
        const Edge& e = edges[forward ? i : n - 1 - i];
        const Vec3 d = p[e.b] - p[e.a];
        const double length = norm(d);
        if (!(length > 0.0) || !(e.rest > 0.0)) continue;
        worst = std::max(worst, std::abs(length / e.rest - 1.0));
        const Vec3 correction = d * (0.5 * (length - e.rest) / length);
        p[e.a] += correction;
        p[e.b] -= correction;
    }
    return worst;
}

}  // namespace

std::vector<std::vector<Edge>> element_edges(const TopologyGrid& grid, const std::vector<int>& element_type,
                                             const Vec3* positions, const std::vector<double>& stretch) {
    std::vector<std::vector<Edge>> edges(grid.element_count());
    for (int e = 0; e < grid.element_count(); ++e) {
        if (grid.kind(e) == ElementTopology::none) continue;
        const double k = stretch[element_type[e]];
        for (int r = 0; r < grid.rows(e); ++r)
            for (int c = 0; c < grid.cols(e); ++c) {
                const int s = grid.at(e, r, c);
                add_edge(edges[e], positions, s, grid.at(e, r, c + 1), k);
                add_edge(edges[e], positions, s, grid.at(e, r + 1, c), k);
                add_edge(edges[e], positions, s, grid.at(e, r + 1, c + 1), k);
                add_edge(edges[e], positions, grid.at(e, r, c + 1), grid.at(e, r + 1, c), k);
            }
    }
    return edges;
}

LengthReport keep_lengths(std::vector<Vec3>& positions, int frames, int samples,
                          const std::vector<std::vector<Edge>>& edges, double tolerance, int max_sweeps, int threads) {
    const int elements = static_cast<int>(edges.size());
    std::vector<int> hit(static_cast<size_t>(frames) * elements, 0);
    std::vector<double> strain(hit.size(), 0.0);
    core::parallel_for(
        frames * elements, threads,
        [&](int begin, int end, int) {
            for (int k = begin; k < end; ++k) {
                Vec3* p = positions.data() + static_cast<size_t>(k / elements) * samples;
                const std::vector<Edge>& list = edges[k % elements];
                int sweeps = 0;
                double worst = list.empty() ? 0.0 : sweep(p, list, true);
                while (worst > tolerance && sweeps < max_sweeps) worst = sweep(p, list, ++sweeps % 2 == 0);
                hit[k] = worst > tolerance;
                strain[k] = worst;
            }
        },
        8);
    LengthReport report;
    for (size_t k = 0; k < hit.size(); ++k)
        report.bound_hits += hit[k], report.worst_strain = std::max(report.worst_strain, strain[k]);
    return report;
}

}  // namespace tessera::dynamic
