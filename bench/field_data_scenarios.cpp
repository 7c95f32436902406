// Benchmark B5 (docs/benchmarks.md): how well each method reproduces real point patterns.
// Every dataset of tests/data/spatstat/points is synthesized into 4x its window with default
// options, and the output's pair correlation (tessera metrics, spatstat's estimator) is
// compared with the exemplar's. Two references frame the figures: a uniform random
// pattern of the same counts (what no structure scores) and a 2 x 2 tiling of the
// exemplar itself (what a verbatim copy scores: the estimator's own edge effects).
#include <algorithm>
#include <chrono>
#include <random>
#include <cstdio>
#include <string>
#include <vector>

#include "field_data_scenarios.hpp"
#include "shared_data.hpp"
#include "tessera/tessera.hpp"

namespace tessera_bench {
namespace {

using namespace tessera;

// The exemplar's elements at `copies` per axis translates of its window (2D box).
Exemplar tiled(const Exemplar& ex, int copies) {
    Exemplar out;
    out.dimension = ex.dimension;
    out.types = ex.types;
    const Box b = ex.domain.bounds();
    const Vec3 size = b.size();
    out.domain = Domain::box(b.lo, b.lo + Vec3{copies * size.x, copies * size.y, 0}, 2);
    for (int i = 0; i < copies; ++i)
        for (int j = 0; j < copies; ++j)
            for (const Element& e : ex.elements)
                out.add_element(e.type, {e.position + Vec3{i * size.x, j * size.y, 0}}, e.radius);
    return out;
}

// Uniform random positions for the elements of `like` (types and radii kept).
Exemplar uniform_like(const Exemplar& like, std::uint64_t seed) {
    Exemplar out;
    out.dimension = like.dimension;
    out.types = like.types;
    out.domain = like.domain;
    const Box b = like.domain.bounds();
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> x(b.lo.x, b.hi.x), y(b.lo.y, b.hi.y);
    for (size_t i = 0; i < like.elements.size(); ++i) {
        const double px = x(rng);
        const Vec3 p{px, y(rng), 0};
        out.add_element(like.elements[i].type, {p}, like.elements[i].radius);
    }
    return out;
}

}  // namespace

namespace {

// The worst ratio over class pairs of the output's crowded share to the exemplar's.
double worst_crowding(const Exemplar& ex, const Exemplar& out) {
    double worst = 0.0;
    for (const CrowdingPair& c : crowding(ex, out))
        if (c.exemplar_share > 0.0) worst = std::max(worst, c.output_share / c.exemplar_share);
    return worst;
}

// What one method's outputs score, as the mean (PCF error, time) or the worst (crowding,
// hole) over the seeds.
struct Scores {
    double error = 0.0, crowding = 0.0, hole = 0.0, seconds = 0.0;
    size_t count = 0;
    void add(const Exemplar& ex, const Arrangement& out, double seconds_taken, double n) {
        error += pcf_relative_error(ex, out) / n;
        crowding = std::max(crowding, worst_crowding(ex, out));
        hole = std::max(hole, largest_empty_circle(out).radius / largest_empty_circle(ex).radius);
        seconds += seconds_taken / n;
        count = out.elements.size();
    }
};

}  // namespace

void run_field_data_scenarios(const std::string& shared, int threads) {
    const std::vector<std::string> names = shared_datasets(shared);
    if (names.empty()) return;
    std::printf("\n| dataset | classes | input | output | det PCF error | pcf PCF error | uniform random | exemplar tiled 2 x 2 | "
                "det crowding | pcf crowding | tiled crowding | det hole | pcf hole | tiled hole | det s | pcf s |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const std::string& name : names) {
        LoadOptions lo;
        lo.input_domain = parse_box_domain(window_of(shared, name), "window");
        const Exemplar ex = load(shared + "/points/" + name + ".csv", lo);
        const Domain domain = ex.domain.scaled(2.0);
        Scores det, pcf;
        const std::vector<std::uint64_t> seeds = {1, 2, 3};
        const double n = static_cast<double>(seeds.size());
        for (std::uint64_t seed : seeds) {
            DetOptions d;
            d.seed = seed;
            d.threads = threads;
            auto t0 = std::chrono::steady_clock::now();
            const Arrangement det_out = synthesize_det(ex, domain, d);
            det.add(ex, det_out, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), n);
            PcfSynthOptions p;
            p.seed = seed;
            p.threads = threads;
            t0 = std::chrono::steady_clock::now();
            const Arrangement pcf_out = synthesize_pcf(ex, domain, p);
            pcf.add(ex, pcf_out, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), n);
        }
        const Exemplar copy = tiled(ex, 2);
        std::printf("| %s | %zu | %zu | %zu | %.3f | %.3f | %.3f | %.3f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.3f | %.3f |\n",
                    name.c_str(), ex.types.size(), ex.elements.size(), det.count, det.error, pcf.error,
                    pcf_relative_error(ex, uniform_like(copy, 1)), pcf_relative_error(ex, copy), det.crowding,
                    pcf.crowding, worst_crowding(ex, copy), det.hole, pcf.hole,
                    largest_empty_circle(copy).radius / largest_empty_circle(ex).radius, det.seconds, pcf.seconds);
        std::fflush(stdout);
    }
}

}  // namespace tessera_bench
