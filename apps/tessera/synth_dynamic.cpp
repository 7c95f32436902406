// apps/tessera/synth_dynamic.cpp — the dynamic method of `tessera synth`.
#include "synth_dynamic.hpp"

#include <cstdio>
#include <iostream>

#include "animation_files.hpp"
#include "common.hpp"
#include "interrupt_scope.hpp"
#include "status_printer.hpp"
#include "tessera/animation_io.hpp"
#include "tessera/graph_motion.hpp"

namespace tessera_cli {

namespace {

// The output with its run statistics (.json keeps them), or an animated PNG.
void write_animation(const tessera::AnimatedArrangement& result, const std::string& path) {
    if (extension_of(path) == ".png")
        write_animation_picture(result, path);
    else
        tessera::save_animation(result, result.stats, path);
}

void write_outputs(const DynamicRun& run, const tessera::AnimatedArrangement& result, StatusPrinter& status) {
    if (!run.preview.empty())
        status.step("writing " + run.preview, [&] { write_animation_picture(result, run.preview); });
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

// --coarse: the exemplar's detail motion laid on the coarse motion of the file's elements.
tessera::AnimatedArrangement run_on_coarse(const DynamicRun& run, const tessera::Animation& exemplar,
                                           StatusPrinter& status) {
    const tessera::Animation coarse =
        status.step("reading " + run.coarse, [&] { return tessera::load_animation(run.coarse); });
    if (!run.quiet)
        std::cerr << "synth: " << exemplar.structure.elements.size() << " elements x " << exemplar.frame_count()
                  << " frames -> " << coarse.structure.elements.size() << " elements x " << coarse.frame_count()
                  << " frames on the coarse motion of " << run.coarse << " (method dynamic, all frames, seed "
                  << run.options.seed << ")" << std::endl;
    return tessera::synthesize_on_coarse(exemplar, coarse, run.options,
                                         status.progress([] { return !interrupt_requested(); }, "iteration"));
}

}  // namespace

void check_dynamic_outputs(const DynamicRun& run) {
    check_output_path(run.output, "-o", {".json", ".csv", ".usda", ".gltf", ".glb", ".png"});
    if (!run.preview.empty()) check_output_path(run.preview, "--preview", {".png"});
}

void run_dynamic(const DynamicRun& run, StatusPrinter& status,
                 const std::function<tessera::Domain(const tessera::Exemplar&)>& domain_of) {
    std::optional<InterruptScope> interrupt_scope(std::in_place);
    const tessera::LoadOptions load_options = input_load_options(run.input_domain);
    const tessera::Animation exemplar = status.step(
        "reading " + run.input, [&] { return tessera::load_animation(run.input, load_options); });
    // A still gets its frames from graph synthesis (--graph-frames) before the window applies,
    // also on a coarse motion (its detail motion then comes from the enriched still).
    const int graph_frames = tessera::graph_frames_for(exemplar, run.options);
    const int frames = graph_frames > 0 ? graph_frames : exemplar.frame_count();
    if (run.options.temporal_size > frames)
        fail_option("--temporal-size must be at most the exemplar's frame count (" + std::to_string(frames) +
                    "), got " + std::to_string(run.options.temporal_size));
    tessera::AnimatedArrangement result;
    if (!run.coarse.empty()) {
        try {
            result = run_on_coarse(run, exemplar, status);
        } catch (const tessera::Cancelled&) {
            throw tessera::Error(tessera::ErrorKind::cancelled, "interrupted; nothing was written");
        }
        status.flush();
        interrupt_scope.reset();
        return write_outputs(run, result, status);
    }
    const tessera::Domain domain =
        status.step("building the output domain", [&] { return domain_of(exemplar.frame(0)); });
    if (!run.quiet)
        std::cerr << "synth: " << exemplar.structure.elements.size() << " elements x " << exemplar.frame_count()
                  << " frames in " << exemplar.structure.domain.describe() << " -> " << domain.describe()
                  << " (method dynamic, seed " << run.options.seed
                  << (graph_frames > 0 ? ", motion by graph synthesis: " + std::to_string(graph_frames) + " frames" : "")
                  << ")" << std::endl;
    try {
        result = tessera::synthesize_dynamic(exemplar, domain, run.options,
                                             status.progress([] { return !interrupt_requested(); }, "frame"));
    } catch (const tessera::Cancelled&) {
        throw tessera::Error(tessera::ErrorKind::cancelled, "interrupted; nothing was written");
    }
    status.flush();
    interrupt_scope.reset();
    if (!run.quiet)
        for (const std::string& note : result.stats.notes) std::cerr << "synth: note: " << note << std::endl;
    write_outputs(run, result, status);
}

}  // namespace tessera_cli
