// bench/dynamic_scenarios.cpp — B8 (docs/benchmarks.md): frame-by-frame dynamic synthesis.
#include "dynamic_scenarios.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "tessera/tessera.hpp"

namespace tessera_bench {

namespace {

struct DynamicScenario {
    const char* name;
    const char* exemplar;   // under examples/dynamic/
    int particles;          // about this many in the output
    int frames;
    tessera::Vec3 flow;
};

// A square box from the exemplar's lower corner holding about `particles` at its density.
tessera::Domain box_for(const tessera::Animation& ex, int particles) {
    const tessera::Box b = ex.structure.domain.bounds();
    const double area = (b.hi.x - b.lo.x) * (b.hi.y - b.lo.y);
    const double side = std::sqrt(area * particles / static_cast<double>(ex.structure.elements.size()));
    return tessera::Domain::box(b.lo, b.lo + tessera::Vec3{side, side, 0}, 2);
}

}  // namespace

void run_dynamic_scenarios(const std::string& examples, int threads) {
    const DynamicScenario scenarios[] = {
        {"B8-particles", "swirl_particles_2d.json", 1000, 100, {}},
        {"B8-particles-flow", "swirl_particles_2d.json", 1000, 100, {1.5, 0, 0}},
    };
    std::printf("\n| scenario | exemplar | particles | frames | threads | first frame s | ms / later frame | "
                "slowest frame ms | total s |\n|---|---|---|---|---|---|---|---|---|\n");
    for (const DynamicScenario& sc : scenarios) {
        const tessera::Animation ex = tessera::load_animation(examples + "/dynamic/" + sc.exemplar);
        tessera::DynamicOptions o;
        o.frames = sc.frames;
        o.threads = threads;
        o.flow = sc.flow;
        o.wrap = true;
        const tessera::AnimatedArrangement out = synthesize_dynamic(ex, box_for(ex, sc.particles), o);
        const std::vector<double>& per_frame = out.stats.iteration_seconds;
        double sum = 0.0;
        for (double t : per_frame) sum += t;
        const double slowest = per_frame.empty() ? 0.0 : *std::max_element(per_frame.begin(), per_frame.end());
        std::printf("| %s | %s | %zu | %d | %d | %.3f | %.2f | %.2f | %.3f |\n", sc.name, sc.exemplar,
                    out.structure.elements.size(), out.frame_count(), out.stats.threads, out.stats.init_seconds,
                    1000.0 * sum / std::max<size_t>(1, per_frame.size()), 1000.0 * slowest, out.stats.total_seconds);
        std::fflush(stdout);
    }
}

}  // namespace tessera_bench
