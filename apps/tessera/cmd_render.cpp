// apps/tessera/cmd_render.cpp — `tessera render FILE -o PICTURE`: draws an exemplar
// or arrangement as a .png or .svg (tessera::render_to_file): 2D elements as disks
// or polylines coloured by class, 3D as a shaded orthographic view.
#include <iostream>
#include <memory>

#include "common.hpp"

namespace tessera_cli {
namespace {

struct RenderArgs {
    std::string input, output, input_domain, meshes = "auto";
    bool no_domain = false, no_samples = false, quiet = false;
    tessera::RenderOptions render;
};

void run_render(RenderArgs& args) {
    if (args.render.width < 1)
        fail_option("--width must be a number of pixels >= 1, got " + std::to_string(args.render.width));
    check_output_path(args.output, "-o", {".png", ".svg"});
    const tessera::Exemplar data = load_input(args.input, args.input_domain);
    args.render.show_domain = !args.no_domain;
    args.render.show_samples = !args.no_samples;
    args.render.meshes = parse_meshes_option(args.meshes);
    try {
        tessera::render_to_file(data, args.output, args.render);
    } catch (const tessera::Error& e) {
        // The extension was checked above, so an option error here is about the size.
        if (e.kind() == tessera::ErrorKind::option) fail_option(std::string("--width: ") + e.what());
        throw;
    }
    if (!args.quiet) std::cerr << "wrote " << args.output << std::endl;
}

}  // namespace

Subcommand add_render_command(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand(
        "render",
        "Draw FILE (an exemplar or an output) as a picture: 2D elements as disks or polylines coloured by "
        "class, 3D as an orthographic view with depth shading.");
    cmd->add_option("FILE", args->input, "The data to draw (.json or .csv).")->required()->type_name("FILE");
    add_output_option(*cmd, args->output, "The picture to write: .png or .svg.", true);
    cmd->add_option("--width", args->render.width,
                    "Picture width in pixels (16 to 16384); the height follows the "
                    "domain's aspect ratio.")
        ->capture_default_str();
    cmd->add_flag("--no-domain", args->no_domain, "Do not draw the domain outline.");
    cmd->add_flag("--no-samples", args->no_samples, "Do not mark the samples of multi-sample elements.");
    add_meshes_option(*cmd, args->meshes);
    add_input_domain_option(*cmd, args->input_domain, "FILE");
    add_quiet_option(*cmd, args->quiet);
    return {cmd, [args] { run_render(*args); }};
}

}  // namespace tessera_cli
