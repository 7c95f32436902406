// tessera_bench — the benchmark scenarios of docs/benchmarks.md.
//   B1        2D exemplar of ~100 elements -> ~1,000 elements, 10 iterations
//   B1-large  the same exemplar -> ~100,000 elements, 10 iterations
//   B2        3D rigid rods of 5 samples -> ~1,000 elements, 10 iterations
// Usage: tessera_bench EXAMPLES_DIR [--quick] [--threads T]
// Prints a Markdown table (median of repeated runs for the small scenarios).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "tessera/tessera.hpp"

using namespace tessera;

namespace {

struct Scenario {
    std::string name, exemplar;
    double target_elements;
    int repeats;
    bool keep_height;  // grow x and y only (a layer on a floor keeps its thickness)
};

double seconds(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: tessera_bench EXAMPLES_DIR [--quick] [--threads T]\n");
        return 2;
    }
    const std::string dir = argv[1];
    bool quick = false;
    int threads = 0;
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--quick") quick = true;
        else if (a == "--threads" && i + 1 < argc) threads = std::atoi(argv[++i]);
    }
    std::vector<Scenario> scenarios = {
        {"B1", "poisson_disk_2d.json", 1000, 5, false},
        {"B1-large", "poisson_disk_2d.json", 100000, 1, false},
        {"B2", "rods_3d.json", 1000, 3, true},
    };
    if (quick) scenarios.erase(scenarios.begin() + 1);

    std::printf("| scenario | exemplar | elements | samples | iterations | threads | total s | s / iteration | "
                "us per element-iteration | final energy |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
    for (const auto& sc : scenarios) {
        const Exemplar ex = load(dir + "/" + sc.exemplar);
        const int grown_axes = sc.keep_height ? 2 : ex.dimension;
        const double scale = std::pow(sc.target_elements / ex.elements.size(), 1.0 / grown_axes);
        Box box = ex.domain.bounds();
        for (int k = 0; k < grown_axes; ++k) box.hi[k] = box.lo[k] + scale * (box.hi[k] - box.lo[k]);
        const Domain domain = Domain::box(box.lo, box.hi, ex.dimension);
        DetOptions o;
        o.threads = threads;
        o.iterations = 10;
        std::vector<double> times;
        Arrangement out;
        for (int r = 0; r < sc.repeats; ++r) {
            const auto t0 = std::chrono::steady_clock::now();
            out = synthesize_det(ex, domain, o);
            times.push_back(seconds(t0));
        }
        std::sort(times.begin(), times.end());
        const double t = times[times.size() / 2];
        std::printf("| %s | %s | %zu | %zu | %d | %d | %.3f | %.4f | %.2f | %.4g |\n", sc.name.c_str(),
                    sc.exemplar.c_str(), out.elements.size(), out.samples.size(), o.iterations, out.stats.threads, t,
                    t / o.iterations, 1e6 * t / (o.iterations * static_cast<double>(out.elements.size())),
                    out.stats.final_energy);
        std::fflush(stdout);
    }
    return 0;
}
