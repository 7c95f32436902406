// apps/tessera/synth_dynamic.cpp — the dynamic method of `tessera synth`.
#include "synth_dynamic.hpp"

#include <cstdio>
#include <iostream>

#include "common.hpp"
#include "interrupt_scope.hpp"
#include "status_printer.hpp"
#include "tessera/animation_io.hpp"
#include "tessera/animation_render.hpp"

namespace tessera_cli {

namespace {

// Paths drawn behind each particle in animated pictures, in frames.
constexpr int preview_trail = 6;

void write_picture(const tessera::Animation& animation, const std::string& path) {
    tessera::AnimationRenderOptions options;
    options.trail = preview_trail;
    tessera::write_file_atomic(path, tessera::render_animation_png(animation, options));
}

void write_animation(const tessera::AnimatedArrangement& result, const std::string& path) {
    if (extension_of(path) == ".png")
        write_picture(result, path);
    else
        tessera::save_animation(result, result.stats, path);
}

}  // namespace

void check_dynamic_outputs(const DynamicRun& run) {
    check_output_path(run.output, "-o", {".json", ".csv", ".usda", ".png"});
    if (!run.preview.empty()) check_output_path(run.preview, "--preview", {".png"});
}

void run_dynamic(const DynamicRun& run, StatusPrinter& status,
                 const std::function<tessera::Domain(const tessera::Exemplar&)>& domain_of) {
    std::optional<InterruptScope> interrupt_scope(std::in_place);
    tessera::LoadOptions load_options;
    if (!run.input_domain.empty())
        load_options.input_domain = tessera::parse_box_domain(run.input_domain, "--input-domain");
    const tessera::Animation exemplar = status.step(
        "reading " + run.input, [&] { return tessera::load_animation(run.input, load_options); });
    if (run.options.temporal_size > exemplar.frame_count())
        fail_option("--temporal-size must be at most the exemplar's frame count (" +
                    std::to_string(exemplar.frame_count()) + "), got " + std::to_string(run.options.temporal_size));
    const tessera::Domain domain =
        status.step("building the output domain", [&] { return domain_of(exemplar.frame(0)); });
    if (!run.quiet)
        std::cerr << "synth: " << exemplar.structure.elements.size() << " elements x " << exemplar.frame_count()
                  << " frames in " << exemplar.structure.domain.describe() << " -> " << domain.describe()
                  << " (method dynamic, seed " << run.options.seed << ")" << std::endl;
    tessera::AnimatedArrangement result;
    try {
        result = tessera::synthesize_dynamic(exemplar, domain, run.options,
                                             status.progress([] { return !interrupt_requested(); }, "frame"));
    } catch (const tessera::Cancelled&) {
        throw tessera::Error(tessera::ErrorKind::cancelled, "interrupted; nothing was written");
    }
    status.flush();
    interrupt_scope.reset();
    if (!run.preview.empty()) status.step("writing " + run.preview, [&] { write_picture(result, run.preview); });
    status.step("writing " + run.output, [&] { write_animation(result, run.output); });
    if (!run.quiet) {
        char line[200];
        std::snprintf(line, sizeof line, "done: %zu elements x %d frames, %.2f s (%.1f ms per frame), final energy %.6g",
                      result.structure.elements.size(), result.frame_count(), result.stats.total_seconds,
                      1000.0 * result.stats.total_seconds / result.frame_count(), result.stats.final_energy);
        std::cerr << line << "; wrote " << run.output << (run.preview.empty() ? "" : " and " + run.preview)
                  << std::endl;
    }
}

}  // namespace tessera_cli
