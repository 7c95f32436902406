// bench/dynamic_scenarios.cpp — B8 (docs/benchmarks.md): dynamic synthesis, particles frame by
// frame and threads all frames together on a coarse motion.
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

// `count` straight threads of `samples` (spacing 0.24) side by side, hanging from a line
// that swings them (period 3): the coarse motion of the all-frame case.
tessera::Animation swinging_threads(int count, int samples, int frames) {
    tessera::Exemplar ex;
    ex.dimension = 2;
    const int type = ex.type_index("noodle");
    ex.types[type].topology = tessera::ElementTopology::thread;
    std::vector<tessera::Vec3> line(samples);
    for (int n = 0; n < count; ++n) {
        for (int i = 0; i < samples; ++i) line[i] = {0.5 * n, 5.0 - 0.24 * i, 0};
        ex.add_element(type, line);
        ex.elements.back().id = n;
    }
    ex.domain = tessera::Domain::box({-1, -1, 0}, {0.5 * count + 1, 6, 0}, 2);
    tessera::Animation a = tessera::animation_from_exemplar(ex);
    a.positions.clear(), a.times.clear();
    std::vector<tessera::Vec3> p(ex.samples.size());
    for (int f = 0; f < frames; ++f) {
        const double angle = 0.45 * std::sin(2 * 3.141592653589793 * f * 0.1 / 3.0);
        for (size_t s = 0; s < p.size(); ++s) {
            const int i = ex.samples[s].sample_id;
            const tessera::Vec3 top{ex.samples[s].p.x, 5.0, 0};
            p[s] = top + tessera::Vec3{0.24 * i * std::sin(angle), -0.24 * i * std::cos(angle), 0};
        }
        a.add_frame(0.1 * f, p);
    }
    return a;
}

// B8's all-frame case: 100 threads of 20 samples x 50 frames on a coarse swing.
void run_thread_scenario(const std::string& examples, int threads) {
    const tessera::Animation ex = tessera::load_animation(examples + "/dynamic/noodles_2d.json");
    const tessera::Animation coarse = swinging_threads(100, 20, 50);
    tessera::DynamicOptions o;
    o.threads = threads;
    const tessera::AnimatedArrangement out = tessera::synthesize_on_coarse(ex, coarse, o);
    std::printf("\n| scenario | exemplar | threads x samples | frames | threads | initialization s | "
                "ms / frame | total s |\n|---|---|---|---|---|---|---|---|\n");
    std::printf("| B8-threads-all-frames | noodles_2d.json | 100 x 20 | %d | %d | %.3f | %.2f | %.3f |\n",
                out.frame_count(), out.stats.threads, out.stats.init_seconds,
                1000.0 * out.stats.total_seconds / out.frame_count(), out.stats.total_seconds);
    std::fflush(stdout);
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
    run_thread_scenario(examples, threads);
}

}  // namespace tessera_bench
