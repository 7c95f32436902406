// Benchmark B6 (grow_scenarios.hpp): growth over a square region (a layer of the same
// thickness in 3D) sized for each target count, timed from the seed patch to covered.
#include "grow_scenarios.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "tessera/tessera.hpp"

namespace tessera_bench {

namespace {

// Resident memory of this process, bytes (VmRSS of /proc/self/status; 0 when unknown).
double resident_bytes() {
    std::ifstream in("/proc/self/status");
    std::string key;
    while (in >> key) {
        if (key == "VmRSS:") {
            double kib = 0.0;
            in >> kib;
            return kib * 1024.0;
        }
        in.ignore(1 << 16, '\n');
    }
    return 0.0;
}

// The exemplar's box grown in x and y for about `target` elements (z kept in 3D).
tessera::Domain region_for(const tessera::Exemplar& ex, double target) {
    const double scale = std::sqrt(target / static_cast<double>(ex.elements.size()));
    tessera::Box box = ex.domain.bounds();
    for (int k = 0; k < 2; ++k) box.hi[k] = box.lo[k] + scale * (box.hi[k] - box.lo[k]);
    return tessera::Domain::box(box.lo, box.hi, ex.dimension);
}

}  // namespace

void run_grow_scenarios(const std::string& examples, bool quick, int threads) {
    struct Case {
        const char* name;
        const char* exemplar;
    };
    const std::vector<Case> cases = {{"B6-2d", "poisson_disk_2d.json"}, {"B6-3d", "rods_3d.json"}};
    std::vector<double> targets = {1e4, 1e5, 1e6};
    if (quick) targets.pop_back();
    std::printf("\n| scenario | exemplar | target | elements | samples | rounds | threads | s | elements / s | "
                "us / element over 10k's | bytes / element |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const Case& c : cases) {
        const tessera::Exemplar ex = tessera::load(examples + "/" + c.exemplar);
        double base = 0.0;
        for (const double target : targets) {
            tessera::GrowOptions o;
            o.threads = threads;
            const double before = resident_bytes();
            const auto t0 = std::chrono::steady_clock::now();
            tessera::Grower grower(ex, o);
            const tessera::GrowReport report = grower.grow(region_for(ex, target));
            const tessera::Arrangement& out = grower.arrangement();
            const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            const double n = static_cast<double>(out.elements.size());
            const double per = s / n;
            if (base == 0.0) base = per;
            std::printf("| %s | %s | %.0f | %zu | %zu | %d | %d | %.2f | %.0f | %.2f | %.0f |\n", c.name, c.exemplar, target,
                        out.elements.size(), out.samples.size(), report.rounds, out.stats.threads, s, n / s, per / base,
                        (resident_bytes() - before) / n);
            std::fflush(stdout);
        }
    }
}

}  // namespace tessera_bench
