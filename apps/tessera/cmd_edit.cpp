// apps/tessera/cmd_edit.cpp — `tessera edit INPUT EDIT.json -o OUTPUT`: applies one
// element's change (EDIT.json, see docs/format.md) to that element and to every
// element whose neighbourhood is similar (tessera::edit_elements, section 6.3 of
// the paper), and reports how many changed.
#include <cmath>
#include <iostream>
#include <memory>

#include "common.hpp"
#include "option_flags.hpp"
#include "status_printer.hpp"

namespace tessera_cli {
namespace {

struct EditArgs {
    std::string input, edit, output, input_domain, gltf_instancing = "gpu";
    bool quiet = false;
    OptionFlags flags;  // EditOptions as flags, from the table (tessera/option_table.hpp)
    tessera::EditOptions options;
};

void run_edit(EditArgs& args) {
    StatusPrinter status("edit", args.quiet, std::cerr);
    args.flags.apply(tessera::edit_option_table(), args.options);
    check_arrangement_output(args.output, "-o");
    tessera::SaveOptions save_options;
    save_options.gltf_instancing = parse_gltf_instancing_option(args.gltf_instancing);
    const tessera::Exemplar data =
        status.step("reading " + args.input, [&] { return load_input(args.input, args.input_domain); });
    if (tessera::is_scene_path(args.output))  // meshes checked before the edit
        status.step("checking the element meshes", [&] { tessera::build_scene(data); });
    const tessera::ElementEdit edit = tessera::parse_edit_json(tessera::read_file(args.edit), args.edit);
    tessera::EditReport report;
    const tessera::Exemplar result =
        status.step("comparing the neighbourhoods of " + std::to_string(data.elements.size()) +
                        " elements with the edited one's",
                    [&] { return tessera::edit_elements(data, edit, args.options, &report); });
    const std::string scene = status.step(
        "writing " + args.output, [&] { return write_arrangement(result, args.output, save_options); });
    if (!args.quiet && !scene.empty()) std::cerr << "scene: " << scene << std::endl;
    if (!args.quiet)
        std::cerr << "edit: changed " << report.changed.size() << " of " << data.elements.size()
                  << " elements (threshold " << report.threshold << "); wrote " << args.output << std::endl;
}

}  // namespace

Subcommand add_edit_command(CLI::App& app) {
    auto args = std::make_shared<EditArgs>();
    CLI::App* cmd = app.add_subcommand(
        "edit",
        "Change one element as EDIT.json says (move it, change its type, radius, angle or attributes) and "
        "propagate the change to every element whose neighbourhood is similar (Eq. 1 within --threshold).");
    cmd->add_option("INPUT", args->input, "The arrangement to edit (.json or .csv).")
        ->required()
        ->type_name("FILE");
    cmd->add_option("EDIT", args->edit, "The edit: a JSON file (docs/format.md, \"Edit files\").")
        ->required()
        ->type_name("FILE");
    add_output_option(*cmd, args->output,
                      "The edited arrangement: .json, .csv, .ply (one point per element), .png, .svg, or a "
                      "scene .usda, .gltf, .glb, .obj or .mesh.ply.",
                      true);
    args->flags.add(*cmd, {method_options("edit", tessera::edit_option_table())});
    add_gltf_instancing_option(*cmd, args->gltf_instancing);
    add_input_domain_option(*cmd, args->input_domain, "INPUT");
    add_quiet_option(*cmd, args->quiet);
    return {cmd, [args] { run_edit(*args); }};
}

}  // namespace tessera_cli
