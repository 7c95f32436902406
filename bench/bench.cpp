// tessera_bench — the benchmark scenarios of docs/benchmarks.md.
//   B1        2D exemplar of ~100 elements -> ~1,000 elements, 10 iterations
//   B1-large  the same exemplar -> ~100,000 elements, 10 iterations
//   B2        3D rigid rods of 5 samples -> ~1,000 elements, 10 iterations
//   B3-dish   the dish (corn, carrot dice, 3-sample beans) filling a bowl mesh, ~2,000
//             elements, interleaved physics on, 10 iterations
//   B3-spaghetti  deformable 24-sample noodles filling a plate mesh, 10 iterations
//   B4-*      the PCF method (pcf_scenarios.cpp): examples/pcf/ and shared real datasets
//   B5        both methods on every shared real dataset (field_data_scenarios.cpp)
//   B6-*      on-demand growth, 10,000 to 1,000,000 elements, 2D and 3D (grow_scenarios.cpp)
//   B7-*      worlds of 4 x 4 to 64 x 64 deterministic tiles in one process (world_scenarios.cpp)
//   B8-*      dynamic synthesis: 1,000 particles x 100 frames, frame by frame (dynamic_scenarios.cpp)
//   B9        brushing: a 100-element paint stroke and "fill the rest" of a 2,000-element canvas
// Usage: tessera_bench EXAMPLES_DIR [--quick] [--threads T] [--shared DATA_DIR]
// Prints a Markdown table (median of repeated runs for the small scenarios).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "field_data_scenarios.hpp"
#include "grow_scenarios.hpp"
#include "pcf_scenarios.hpp"
#include "brush_scenarios.hpp"
#include "dynamic_scenarios.hpp"
#include "world_scenarios.hpp"
#include "tessera/tessera.hpp"

using namespace tessera;

namespace {

struct Scenario {
    std::string name, exemplar;
    double target_elements;
    int repeats;
    bool keep_height;  // grow x and y only (a layer on a floor keeps its thickness)
    std::string mesh_domain = "";  // a closed mesh (relative to EXAMPLES_DIR) as the domain instead of a box
    bool physics = false;          // interleaved physics after every iteration
};

double seconds(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Runs every scenario and prints their tables (defined after main).
void run(const std::string& dir, bool quick, int threads, const std::string& shared, const std::string& only);

}  // namespace

int main(int argc, char** argv) {
    const char* usage =
        "usage: tessera_bench EXAMPLES_DIR [--quick] [--threads T] [--shared DATA_DIR] [--only B1|B4|B5|B6|B7|B8|B9]\n"
        "Runs benchmarks B1-B9 (docs/benchmarks.md) and prints Markdown tables; --quick skips B1-large,\n"
        "B6's 1,000,000-element runs and B7's 64 x 64 tiles,\n"
        "--shared names the real point patterns' directory (default EXAMPLES_DIR/../tests/data/spatstat),\n"
        "--only runs one table (B1 = B1-B3).\n";
    if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
        std::fprintf(argc < 2 ? stderr : stdout, "%s", usage);
        return argc < 2 ? 2 : 0;
    }
    const std::string dir = argv[1];
    bool quick = false;
    int threads = 0;
    std::string shared = dir + "/../tests/data/spatstat";
    std::string only;
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--quick") quick = true;
        else if (a == "--threads" && i + 1 < argc) threads = std::atoi(argv[++i]);
        else if (a == "--shared" && i + 1 < argc) shared = argv[++i];
        else if (a == "--only" && i + 1 < argc) only = argv[++i];
        else {
            std::fprintf(stderr, "tessera_bench: unknown argument '%s'\n%s", a.c_str(), usage);
            return 2;
        }
    }
    try {
        run(dir, quick, threads, shared, only);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "tessera_bench: error: %s\n", e.what());
        return 1;
    }
    return 0;
}

namespace {

void run(const std::string& dir, bool quick, int threads, const std::string& shared, const std::string& only) {
    auto wanted = [&](const char* table) { return only.empty() || only == table; };
    std::vector<Scenario> scenarios = {
        {"B1", "poisson_disk_2d.json", 1000, 5, false},
        {"B1-large", "poisson_disk_2d.json", 100000, 1, false},
        {"B2", "rods_3d.json", 1000, 3, true},
        {"B3-dish", "scenes/dish_3d.json", 0, 1, false, "scenes/bowl.obj", true},
        {"B3-spaghetti", "scenes/spaghetti_3d.json", 0, 1, false, "scenes/plate.obj", false},
    };
    if (quick) scenarios.erase(scenarios.begin() + 1);
    if (!wanted("B1")) scenarios.clear();

    if (!scenarios.empty())
        std::printf("| scenario | exemplar | elements | samples | iterations | threads | total s | s / iteration | "
                "us per element-iteration | final energy | domain setup s |\n");
    if (!scenarios.empty()) std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const auto& sc : scenarios) {
        const Exemplar ex = load(dir + "/" + sc.exemplar);
        const int grown_axes = sc.keep_height ? 2 : ex.dimension;
        const double scale = sc.target_elements > 0 ? std::pow(sc.target_elements / ex.elements.size(), 1.0 / grown_axes) : 1.0;
        Box box = ex.domain.bounds();
        for (int k = 0; k < grown_axes; ++k) box.hi[k] = box.lo[k] + scale * (box.hi[k] - box.lo[k]);
        const auto setup_start = std::chrono::steady_clock::now();
        const Domain domain = sc.mesh_domain.empty() ? Domain::box(box.lo, box.hi, ex.dimension)
                                                     : Domain::mesh(dir + "/" + sc.mesh_domain);
        const double setup = seconds(setup_start);  // reading and voxelizing a mesh domain
        DetOptions o;
        o.physics = sc.physics;
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
        std::printf("| %s | %s | %zu | %zu | %d | %d | %.3f | %.4f | %.2f | %.4g | %.3f |\n", sc.name.c_str(),
                    sc.exemplar.c_str(), out.elements.size(), out.samples.size(), o.iterations, out.stats.threads, t,
                    t / o.iterations, 1e6 * t / (o.iterations * static_cast<double>(out.elements.size())),
                    out.stats.final_energy, setup);
        std::fflush(stdout);
    }
    if (wanted("B4")) tessera_bench::run_pcf_scenarios(dir, shared, threads);
    if (wanted("B5")) tessera_bench::run_field_data_scenarios(shared, threads);
    if (wanted("B6")) tessera_bench::run_grow_scenarios(dir, quick, threads);
    if (wanted("B7")) tessera_bench::run_world_scenarios(dir, quick, threads);
    if (wanted("B8")) tessera_bench::run_dynamic_scenarios(dir, threads);
    if (wanted("B9")) tessera_bench::run_brush_scenarios(dir, threads);
}

}  // namespace
