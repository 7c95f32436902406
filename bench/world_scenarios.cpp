// Benchmark B7 (world_scenarios.hpp): tessera::make_tiles over square ranges of tiles of the
// two-class pattern, one process, the tiles of a phase side by side on the threads.
#include "world_scenarios.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>
#include <vector>

#include "tessera/tessera.hpp"

namespace tessera_bench {

namespace {

struct Measured {
    double seconds = 0.0, tiles_made = 0.0, elements = 0.0, elements_per_tile = 0.0;
};

Measured make_world(const tessera::TileMaker& maker, int side, int threads) {
    std::vector<tessera::TileCoord> wanted;
    for (int x = 0; x < side; ++x)
        for (int y = 0; y < side; ++y) wanted.push_back({x, y, 0});
    const auto t0 = std::chrono::steady_clock::now();
    const auto tiles = tessera::make_tiles(maker, wanted, threads);
    Measured m;
    m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    m.tiles_made = static_cast<double>(tiles.size());
    for (const tessera::TileCoord& t : wanted) m.elements += static_cast<double>(tiles.at(t).elements.size());
    m.elements_per_tile = m.elements / static_cast<double>(wanted.size());
    return m;
}

// 10^8 elements on 100 machines of `cores` cores: the tiles split evenly over the workers, a
// phase after another (a phase waits for the one before), at the measured core-seconds per
// tile made, plus a scheduling latency per phase.
void print_estimate(const Measured& m, int threads) {
    const double core_seconds_per_tile = m.seconds * threads / m.tiles_made;
    const double tiles = 1e8 / m.elements_per_tile;
    const double workers = 100.0 * 2;
    const int phases = tessera::tile_phases(2);
    const double per_phase = std::ceil(tiles / phases / workers) * core_seconds_per_tile;
    const double latency = 0.5;  // seconds per phase for the scheduler to hand out its tasks and results
    std::printf("\nEstimate, from the largest world above: %.0f elements per tile, %.3f core-seconds per tile "
                "made; 10^8 elements are %.0f tiles in %d phases; on 100 machines of 2 cores (200 workers) "
                "each phase takes %.0f s of work + ~%.1f s of scheduling: about %.0f s (%.1f min) in all, "
                "against %.1f h on one core.\n",
                m.elements_per_tile, core_seconds_per_tile, tiles, phases, per_phase, latency,
                phases * (per_phase + latency), phases * (per_phase + latency) / 60.0,
                tiles * core_seconds_per_tile / 3600.0);
}

}  // namespace

void run_world_scenarios(const std::string& examples, bool quick, int threads) {
    const tessera::Exemplar ex = tessera::load(examples + "/two_class_2d.json");
    tessera::WorldOptions o;
    o.tile_size = 12.0;
    o.grow.threads = 1;  // tiles side by side, each on one thread (as tessera world)
    const tessera::TileMaker maker(ex, o);
    const int used = threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    std::vector<int> sides = {4, 8, 16, 32, 64};
    if (quick) sides.pop_back();
    std::printf("\n| scenario | tiles | tiles made | elements | threads | s | tiles / s | elements / s | "
                "s per tile made over 4 x 4's |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|\n");
    double base = 0.0;
    Measured last;
    for (const int side : sides) {
        const Measured m = make_world(maker, side, used);
        const double per = m.seconds / m.tiles_made;
        if (base == 0.0) base = per;
        std::printf("| B7-%dx%d | %d | %.0f | %.0f | %d | %.2f | %.1f | %.0f | %.2f |\n", side, side, side * side,
                    m.tiles_made, m.elements, used, m.seconds, side * side / m.seconds, m.elements / m.seconds,
                    per / base);
        std::fflush(stdout);
        last = m;
    }
    print_estimate(last, used);
}

}  // namespace tessera_bench
