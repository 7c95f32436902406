// apps/tessera/cmd_animate.cpp — `tessera animate STILL -o OUT`: motion for a still by
// graph synthesis (Dynamic Element Textures, section 4.3; tessera::enrich_by_graph), on its
// own: particles, threads, sheets and rigid elements. `synth --method dynamic` does the same
// to a still before synthesizing it into a domain (--graph-frames) or onto a coarse motion.
// Flags from graph_motion_option_table. Writes .json, .csv, .usda, .gltf, .glb or an
// animated .png.
#include <iostream>
#include <memory>

#include "animation_files.hpp"
#include "common.hpp"
#include "option_flags.hpp"
#include "status_printer.hpp"
#include "tessera/graph_motion.hpp"

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
    const tessera::Exemplar still =
        status.step("reading " + args.input, [&] { return load_input(args.input, args.input_domain); });
    tessera::GraphMotionStats stats;
    const tessera::Animation out =
        status.step("graph synthesis", [&] { return tessera::enrich_by_graph(still, options, &stats); });
    status.step("writing " + args.output, [&] { write_animation_file(out, args.output); });
    if (args.quiet) return;
    for (const std::string& note : stats.notes) std::cerr << "note: " << note << "\n";
    std::cerr << "animate: " << still.elements.size() << " elements x " << out.frame_count() << " frames, "
              << stats.nodes << " graph nodes, paths of " << format_number(stats.path_steps)
              << " steps on average, mean motion " << format_number(stats.mean_speed) << " spacings per frame, "
              << format_number(stats.seconds) << " s\nwrote " << args.output << std::endl;
}

}  // namespace

Subcommand add_animate_command(CLI::App& app) {
    auto args = std::make_shared<AnimateArgs>();
    CLI::App* cmd = app.add_subcommand(
        "animate",
        "Give a still (one frame) motion by graph synthesis (Dynamic Element Textures, section 4.3): every "
        "sample's neighbourhood walks an annealed path through the graph of the still's neighbourhoods; "
        "threads, sheets and rigid elements walk through the still's element shapes, their centroids as "
        "particles (docs/dynamic.md). Frame 0 is the still.");
    cmd->add_option("STILL", args->input, "The still (.json or .csv); of an animation, its first frame.")
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
