// apps/tessera/cmd_animate.cpp — `tessera animate STILL -o OUT`: motion for a still by
// graph synthesis (Dynamic Element Textures, section 4.3; tessera::extend_by_graph), or a
// short clip continued, on its own: particles, threads, sheets and rigid elements. `synth --method dynamic` does the same
// to a still before synthesizing it into a domain (--graph-frames) or onto a coarse motion.
// Flags from graph_motion_option_table. Writes .json, .csv, .usda, .gltf, .glb or an
// animated .png.
#include <cstdio>
#include <iostream>
#include <memory>

#include "animation_files.hpp"
#include "common.hpp"
#include "option_flags.hpp"
#include "status_printer.hpp"
#include "tessera/animation_io.hpp"
#include "tessera/graph_motion.hpp"
#include "tessera/io.hpp"

namespace tessera_cli {
namespace {

struct AnimateArgs {
    std::string input, input_domain, output;
    bool quiet = false;
    OptionFlags flags;  // GraphMotionOptions as flags, from graph_motion_option_table
};

void run(const AnimateArgs& args) {
    tessera::GraphMotionOptions options;
    args.flags.apply(tessera::graph_motion_option_table(), options);
    check_output_path(args.output, "-o", {".json", ".csv", ".usda", ".gltf", ".glb", ".png"});
    StatusPrinter status("animate", args.quiet, std::cerr);
    const tessera::LoadOptions load_options = input_load_options(args.input_domain);
    const tessera::Animation clip =
        status.step("reading " + args.input, [&] { return tessera::load_animation(args.input, load_options); });
    tessera::GraphMotionStats stats;
    const tessera::Animation out =
        status.step("graph synthesis", [&] { return tessera::extend_by_graph(clip, options, &stats); });
    status.step("writing " + args.output, [&] { write_animation_file(out, args.output); });
    if (args.quiet) return;
    for (const std::string& note : stats.notes) std::cerr << "note: " << note << "\n";
    char line[200];
    std::snprintf(line, sizeof line,
                  "%zu elements x %d frames, %d graph nodes, paths of %.1f steps on average, mean motion %.3f "
                  "spacings per frame, %.2f s",
                  clip.structure.elements.size(), out.frame_count(), stats.nodes, stats.path_steps, stats.mean_speed,
                  stats.seconds);
    std::cerr << "animate: " << line << "\nwrote " << args.output << std::endl;
}

}  // namespace

Subcommand add_animate_command(CLI::App& app) {
    auto args = std::make_shared<AnimateArgs>();
    CLI::App* cmd = app.add_subcommand(
        "animate",
        "Give a still (one frame) motion by graph synthesis (Dynamic Element Textures, section 4.3), or "
        "continue a short clip: every sample's neighbourhood walks an annealed path through the graph of the "
        "input's neighbourhoods (of all its frames); threads, sheets and rigid elements walk through the "
        "element shapes, their centroids as particles (docs/dynamic.md). The input's frames come first.");
    cmd->add_option("STILL", args->input,
                    "The still (.json or .csv), or a clip (.json or .csv with frames) to continue to --frames "
                    "frames (one of that many frames or more is written as it is).")
        ->required()
        ->type_name("FILE");
    add_output_option(
        *cmd, args->output,
        "Write the animation to this file: .json, .csv, .usda (time samples), .gltf/.glb (animation "
        "channels) or .png (animated).",
        true);
    args->flags.add(*cmd, {method_options("animate", tessera::graph_motion_option_table())});
    add_input_domain_option(*cmd, args->input_domain, "STILL");
    add_quiet_option(*cmd, args->quiet);
    return {cmd, [args] { run(*args); }};
}

}  // namespace tessera_cli
