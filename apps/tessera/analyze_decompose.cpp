// apps/tessera/analyze_decompose.cpp — `tessera analyze --decompose` (analyze_decompose.hpp).
#include "analyze_decompose.hpp"

#include <cmath>
#include <filesystem>
#include <iostream>

#include "common.hpp"
#include "status_printer.hpp"
#include "tessera/animation_io.hpp"

namespace tessera_cli {

namespace {

// Root mean square and largest length of the detail offsets: what the summary reports.
std::pair<double, double> detail_size(const tessera::Animation& detail) {
    double sum = 0.0, largest = 0.0;
    for (const tessera::Vec3& d : detail.positions) {
        sum += tessera::squared_norm(d);
        largest = std::max(largest, tessera::norm(d));
    }
    return {std::sqrt(sum / static_cast<double>(std::max<size_t>(1, detail.positions.size()))), largest};
}

// Writes both animations, or neither: a failed second write removes the first file.
void write_both(const tessera::MotionSplit& split, const DecomposeRun& run) {
    tessera::save_animation(split.coarse, run.coarse);
    try {
        tessera::save_animation(split.detail, run.detail);
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(run.coarse, ignored);
        throw;
    }
}

}  // namespace

void run_decompose(const DecomposeRun& run) {
    check_output_path(run.coarse, "-o", {".json", ".csv", ".usda"});
    check_output_path(run.detail, "--detail", {".json", ".csv", ".usda"});
    if (std::filesystem::absolute(run.coarse).lexically_normal() ==
        std::filesystem::absolute(run.detail).lexically_normal())
        fail_option("-o and --detail must be different files, got '" + run.coarse + "' for both");
    StatusPrinter status("analyze", run.quiet, std::cerr);
    const tessera::LoadOptions load_options = input_load_options(run.input_domain);
    const tessera::Animation input =
        status.step("reading " + run.input, [&] { return tessera::load_animation(run.input, load_options); });
    const tessera::MotionSplit split =
        status.step("splitting the motion", [&] { return tessera::decompose_motion(input, run.options); });
    status.step("writing " + run.coarse + " and " + run.detail, [&] { write_both(split, run); });
    if (!run.quiet) {
        const auto [rms, largest] = detail_size(split.detail);
        std::cerr << "analyze: " << input.structure.elements.size() << " elements x " << input.frame_count()
                  << " frames split into coarse motion and details (offsets: rms " << format_number(rms)
                  << ", largest " << format_number(largest) << ")\nwrote " << run.coarse << " and "
                  << run.detail << std::endl;
    }
}

}  // namespace tessera_cli
