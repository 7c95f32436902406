// tessera::tile_closure and tessera::make_tiles (tessera/world.hpp): a range of tiles made
// phase by phase, the tiles of one phase side by side on threads.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <mutex>
#include <set>
#include <thread>

#include "tessera/error.hpp"
#include "tessera/world.hpp"

namespace tessera {

std::vector<TileCoord> tile_closure(const std::vector<TileCoord>& wanted, int dimension) {
    std::set<TileCoord> all;
    std::vector<TileCoord> open(wanted.begin(), wanted.end());
    while (!open.empty()) {  // each step goes one phase down, so this ends within tile_phases steps deep
        const TileCoord t = open.back();
        open.pop_back();
        if (!all.insert(t).second) continue;
        for (const TileCoord& d : tile_dependencies(t, dimension)) open.push_back(d);
    }
    std::vector<TileCoord> sorted(all.begin(), all.end());
    std::stable_sort(sorted.begin(), sorted.end(), [dimension](const TileCoord& a, const TileCoord& b) {
        return tile_phase(a, dimension) < tile_phase(b, dimension);
    });
    return sorted;
}

namespace {

// The tiles of one phase, made by `threads` workers taking the next tile in turn. Each tile's
// entry exists before the workers start, so they write distinct, stable map nodes.
void make_phase(const TileMaker& maker, const std::vector<TileCoord>& phase, int threads,
                std::map<TileCoord, Arrangement>& tiles, const std::function<bool()>& finished_one) {
    for (const TileCoord& t : phase) tiles[t];
    std::atomic<size_t> next{0};
    std::atomic<bool> stop{false};
    std::mutex report;
    std::exception_ptr failure;
    auto work = [&] {
        while (!stop) {
            const size_t k = next++;
            if (k >= phase.size()) return;
            try {
                std::vector<NeighbourTile> neighbours;
                for (const TileCoord& d : tile_dependencies(phase[k], maker.dimension())) neighbours.push_back({d, &tiles.at(d)});
                Arrangement made = maker.make(phase[k], neighbours);
                std::lock_guard<std::mutex> lock(report);
                tiles[phase[k]] = std::move(made);
                if (!finished_one()) stop = true;
            } catch (...) {
                std::lock_guard<std::mutex> lock(report);
                if (!failure) failure = std::current_exception();
                stop = true;
            }
        }
    };
    std::vector<std::thread> pool;
    const int n = std::min<int>(threads, static_cast<int>(phase.size()));
    for (int i = 1; i < n; ++i) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
    if (stop) throw Cancelled();
}

}  // namespace

std::map<TileCoord, Arrangement> make_tiles(const TileMaker& maker, const std::vector<TileCoord>& wanted,
                                            int threads, const Progress& progress) {
    if (threads < 0) throw Error(ErrorKind::option, "threads must be >= 0, got " + std::to_string(threads));
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    const int dim = maker.dimension();
    const std::vector<TileCoord> all = tile_closure(wanted, dim);
    std::map<TileCoord, Arrangement> tiles;
    const auto start = std::chrono::steady_clock::now();
    int done = 0;
    auto finished_one = [&] {
        ++done;
        if (!progress) return true;
        ProgressEvent e;
        e.stage = "tile", e.iteration = done, e.iterations = static_cast<int>(all.size());
        e.fraction = static_cast<double>(done) / static_cast<double>(all.size());
        e.elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return progress(e);
    };
    for (auto begin = all.begin(); begin != all.end();) {
        const int phase = tile_phase(*begin, dim);
        const auto end = std::find_if(begin, all.end(), [&](const TileCoord& t) { return tile_phase(t, dim) != phase; });
        make_phase(maker, std::vector<TileCoord>(begin, end), threads, tiles, finished_one);
        begin = end;
    }
    return tiles;
}

}  // namespace tessera
