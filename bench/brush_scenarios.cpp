// Benchmark B9 (bench/brush_scenarios.hpp).
#include "brush_scenarios.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "tessera/tessera.hpp"

namespace tessera_bench {

namespace {

double since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Measure {
    double paint_s = 0, fill_s = 0;
    size_t painted = 0, filled = 0;
};

// A square canvas sized for about `target` elements of the exemplar's density; a stroke across
// its middle, long enough for about 100 elements at the default width (4 spacings).
Measure measure(const tessera::Exemplar& ex, int target, int threads) {
    const double density = ex.elements.size() / ex.domain.measure();
    const double side = std::sqrt(target / density);
    const double spacing = tessera::mean_nearest_neighbor_distance(ex);
    const double length = std::min(0.9 * side, 100.0 / (density * 4.0 * spacing));
    tessera::BrushOptions o;
    o.threads = threads;
    tessera::BrushCanvas canvas(tessera::Domain::box({0, 0, 0}, {side, side, 0}, 2), o);
    const int k = canvas.add_exemplar("entry", ex);
    const double y = 0.5 * side, x0 = 0.5 * (side - length);
    tessera::Stroke stroke{{{x0, y, 0}, {x0 + length, y, 0}}, 0.0};
    Measure m;
    auto t0 = std::chrono::steady_clock::now();
    m.painted = static_cast<size_t>(canvas.paint(k, stroke).added);
    m.paint_s = since(t0);
    canvas.direct({{{0.1 * side, 0.9 * side, 0}, {0.9 * side, 0.8 * side, 0}}, 0.0});
    t0 = std::chrono::steady_clock::now();
    canvas.fill();
    m.fill_s = since(t0);
    m.filled = canvas.arrangement().elements.size();
    return m;
}

}  // namespace

void run_brush_scenarios(const std::string& examples, int threads) {
    std::printf("\n| scenario | exemplar | painted | paint s | canvas elements | fill the rest s | fill us / element |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    for (const char* name : {"poisson_disk_2d.json", "sticks_2d.json"}) {
        const tessera::Exemplar ex = tessera::load(examples + "/" + name);
        std::vector<Measure> runs;
        for (int r = 0; r < 3; ++r) runs.push_back(measure(ex, 2000, threads));
        std::sort(runs.begin(), runs.end(), [](const Measure& a, const Measure& b) { return a.fill_s < b.fill_s; });
        const Measure& m = runs[1];
        std::printf("| B9 | %s | %zu | %.3f | %zu | %.3f | %.0f |\n", name, m.painted, m.paint_s, m.filled, m.fill_s,
                    1e6 * m.fill_s / static_cast<double>(m.filled));
        std::fflush(stdout);
    }
}

}  // namespace tessera_bench
