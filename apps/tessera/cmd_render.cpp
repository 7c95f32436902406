// apps/tessera/cmd_render.cpp — `tessera render FILE -o PICTURE`: draws an exemplar
// or arrangement as a .png or .svg (tessera::render_to_file): 2D elements as disks
// or polylines coloured by class, 3D as a shaded orthographic view, with a legend of
// the class names below. Every error names the flag or file at fault.
#include <iostream>
#include <memory>

#include "common.hpp"
#include "status_printer.hpp"
#include "tessera/animation_io.hpp"
#include "tessera/animation_render.hpp"

namespace tessera_cli {
namespace {

struct RenderArgs {
    std::string input, output, input_domain, meshes = "auto";
    bool no_domain = false, no_samples = false, no_legend = false, quiet = false;
    tessera::RenderOptions render;
    int trail = 6;
    CLI::Option* frame_option = nullptr;
    int frame = -1;
};

// An animated FILE (docs/dynamic.md): an animated PNG of every frame, or with --frame one
// still frame; either with each particle's path over --trail frames behind it.
void render_animation(RenderArgs& args, StatusPrinter& status) {
    if (args.trail < 0) fail_option("--trail must be an integer >= 0, got " + std::to_string(args.trail));
    if (extension_of(args.output) != ".png") fail_option("-o must be a .png for an animated FILE (an animated PNG)");
    const tessera::LoadOptions load_options = input_load_options(args.input_domain);
    const tessera::Animation data =
        status.step("reading " + args.input, [&] { return tessera::load_animation(args.input, load_options); });
    tessera::AnimationRenderOptions options;
    options.picture = args.render;
    options.trail = args.trail;
    const bool still = args.frame_option->count() > 0;
    if (still && (args.frame >= data.frame_count() || args.frame < -data.frame_count()))
        fail_option("--frame must be within the " + std::to_string(data.frame_count()) + " frames (negative: from the end), got " +
                    std::to_string(args.frame));
    status.step("drawing " + args.output, [&] {
        with_flag_names({{"width", "--width"}}, [&] {
            tessera::write_file_atomic(args.output, still ? tessera::render_trails_png(data, args.frame, options)
                                                          : tessera::render_animation_png(data, options));
        });
    });
}

void run_render(RenderArgs& args) {
    StatusPrinter status("render", args.quiet, std::cerr);
    check_output_path(args.output, "-o", {".png", ".svg"});
    args.render.meshes = parse_meshes_option(args.meshes);
    check_meshes_for_picture(args.render.meshes, args.output);
    args.render.show_domain = !args.no_domain;
    args.render.show_samples = !args.no_samples;
    args.render.show_legend = !args.no_legend;
    // The width's range is checked before the input is read; the picture's height, which
    // the data decide, when it is drawn.
    const FlagNames flags = {{"width", "--width"}, {"meshes", "--meshes"}};
    with_flag_names(flags, [&] { tessera::check_render_options(args.render); });
    if (tessera::has_frames(args.input)) {
        render_animation(args, status);
        if (!args.quiet) std::cerr << "wrote " << args.output << std::endl;
        return;
    }
    const tessera::Exemplar data =
        status.step("reading " + args.input, [&] { return load_input(args.input, args.input_domain); });
    status.step("drawing " + args.output, [&] {
        with_flag_names(flags, [&] { tessera::render_to_file(data, args.output, args.render); });
    });
    if (!args.quiet) std::cerr << "wrote " << args.output << std::endl;
}

}  // namespace

Subcommand add_render_command(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand(
        "render",
        "Draw FILE (an exemplar or an output) as a picture: 2D elements as disks or polylines coloured by "
        "class, 3D as an orthographic view with depth shading. A FILE with frames (an animation) is drawn as "
        "an animated PNG, or one frame with --frame.");
    cmd->add_option("FILE", args->input, "The data to draw (.json or .csv).")->required()->type_name("FILE");
    add_output_option(*cmd, args->output, "The picture to write: .png or .svg.", true);
    add_integer_option(*cmd, "--width", args->render.width,
                    "Picture width in pixels (16 to 16384); the height follows the "
                    "domain's aspect ratio, plus the legend strip.");
    cmd->add_flag("--no-domain", args->no_domain, "Do not draw the domain outline.");
    cmd->add_flag("--no-samples", args->no_samples, "Do not mark the samples of multi-sample elements.");
    cmd->add_flag("--no-legend", args->no_legend,
                  "Do not draw the legend (a swatch and the name of every class, in a strip below the picture).");
    add_meshes_option(*cmd, args->meshes);
    add_integer_option(*cmd, "--trail", args->trail,
                       "Animated FILE (with frames): frames of path drawn behind each particle (0 = its whole "
                       "path with --frame, none without).");
    args->frame_option = add_integer_option(
        *cmd, "--frame", args->frame,
        "Animated FILE: draw this one frame (negative: from the end, -1 = the last) instead of an animated PNG "
        "of them all.");
    add_input_domain_option(*cmd, args->input_domain, "FILE");
    add_quiet_option(*cmd, args->quiet);
    return {cmd, [args] { run_render(*args); }};
}

}  // namespace tessera_cli
