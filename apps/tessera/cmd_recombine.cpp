// apps/tessera/cmd_recombine.cpp — `tessera recombine COARSE DETAIL -o OUT`: the coarse
// motion of one animation with the details of another (Dynamic Element Textures, section 5,
// Figures 6-7; tessera::recombine_motion), both as `tessera analyze --decompose` writes them.
// Writes .json, .csv, .usda, .gltf, .glb or an animated .png.
#include <iostream>
#include <memory>

#include "animation_files.hpp"
#include "common.hpp"
#include "status_printer.hpp"
#include "tessera/animation_io.hpp"
#include "tessera/motion_analysis.hpp"

namespace tessera_cli {
namespace {

struct RecombineArgs {
    std::string coarse, detail, output;
    bool quiet = false;
};

// recombine_motion's input errors are about the detail not fitting the coarse animation:
// the message names both files.
tessera::Animation recombine(const RecombineArgs& args, const tessera::Animation& coarse,
                             const tessera::Animation& detail) {
    try {
        return tessera::recombine_motion(coarse, detail);
    } catch (const tessera::Error& e) {
        if (e.kind() != tessera::ErrorKind::input) throw;
        throw tessera::Error(e.kind(), args.detail + ": " + e.what() + " (coarse: " + args.coarse + ")");
    }
}

void run(const RecombineArgs& args) {
    check_output_path(args.output, "-o", {".json", ".csv", ".usda", ".gltf", ".glb", ".png"});
    StatusPrinter status("recombine", args.quiet, std::cerr);
    const tessera::Animation coarse =
        status.step("reading " + args.coarse, [&] { return tessera::load_animation(args.coarse); });
    const tessera::Animation detail =
        status.step("reading " + args.detail, [&] { return tessera::load_animation(args.detail); });
    const tessera::Animation out = recombine(args, coarse, detail);
    status.step("writing " + args.output, [&] { write_animation_file(out, args.output); });
    if (!args.quiet)
        std::cerr << "recombine: " << out.structure.elements.size() << " elements x " << out.frame_count()
                  << " frames (details from " << detail.structure.elements.size() << " elements x "
                  << detail.frame_count() << " frames)\nwrote " << args.output << std::endl;
}

}  // namespace

Subcommand add_recombine_command(CLI::App& app) {
    auto args = std::make_shared<RecombineArgs>();
    CLI::App* cmd = app.add_subcommand(
        "recombine",
        "Recombine the coarse motion of one animation with the details of another (Dynamic Element Textures, "
        "section 5): COARSE + DETAIL, both as `tessera analyze --decompose` writes them. Frames cycle "
        "through "
        "DETAIL's frames, elements through DETAIL's elements of the same kind (particles, threads, sheets), "
        "and "
        "threads and sheets of another sample count are resampled along their index (docs/dynamic.md).");
    cmd->add_option("COARSE", args->coarse,
                    "The coarse animation (.json or .csv with frames): its elements, "
                    "their coarse motion and the frames' times.")
        ->required()
        ->type_name("FILE");
    cmd->add_option("DETAIL", args->detail,
                    "The details (offsets, .json or .csv with frames), of the same "
                    "animation or another.")
        ->required()
        ->type_name("FILE");
    add_output_option(
        *cmd, args->output,
        "Write the animation to this file: .json, .csv, .usda (time samples), .gltf/.glb (animation "
        "channels) or .png (animated).",
        true);
    add_quiet_option(*cmd, args->quiet);
    return {cmd, [args] { run(*args); }};
}

}  // namespace tessera_cli
