// apps/tessera/cmd_scene.cpp — `tessera scene INPUT -o SCENE`: rebuilds the geometry of
// a saved arrangement or exemplar (tessera::save_scene: type meshes posed or deformed
// by the samples, default spheres and tubes) and writes it as .usda, .gltf, .glb, .obj or
// .mesh.ply, reporting instances, meshes, triangles and the largest rigid fit error.
#include <cmath>
#include <iostream>
#include <memory>

#include "common.hpp"
#include "status_printer.hpp"

namespace tessera_cli {
namespace {

struct SceneArgs {
    std::string input, output, input_domain, gltf_instancing = "gpu";
    bool quiet = false;
    tessera::SaveOptions options;
};

void run_scene(SceneArgs& args) {
    StatusPrinter status("scene", args.quiet, std::cerr);
    check_output_path(args.output, "-o", {".usda", ".gltf", ".glb", ".obj", ".mesh.ply", ".ply"});
    if (!tessera::is_scene_path(args.output))
        fail_option("-o " + args.output + ": a scene is .usda, .gltf, .glb, .obj or .mesh.ply (a plain .ply is the "
                    "point output of synth)");
    args.options.gltf_instancing = parse_gltf_instancing_option(args.gltf_instancing);
    const auto& o = args.options.geometry;
    if (o.sphere_subdivisions < 0 || o.sphere_subdivisions > 5)
        fail_option("--sphere-subdivisions must be 0 to 5, got " + std::to_string(o.sphere_subdivisions));
    if (o.tube_sides < 3 || o.tube_sides > 64)
        fail_option("--tube-sides must be 3 to 64, got " + std::to_string(o.tube_sides));
    if (!(o.deform_falloff > 0.0) || !std::isfinite(o.deform_falloff))
        fail_option("--deform-falloff must be a number > 0, got " + format_number(o.deform_falloff));
    const tessera::Exemplar data =
        status.step("reading " + args.input, [&] { return load_input(args.input, args.input_domain); });
    const tessera::Scene scene = status.step("building and writing " + args.output,
                                             [&] { return tessera::save_scene(data, args.output, args.options); });
    if (!args.quiet) std::cerr << "scene: " << describe_scene(scene) << "; wrote " << args.output << std::endl;
}

}  // namespace

Subcommand add_scene_command(CLI::App& app) {
    auto args = std::make_shared<SceneArgs>();
    CLI::App* cmd = app.add_subcommand(
        "scene",
        "Rebuild the geometry of INPUT (an exemplar or an output of synth or edit): each element type's mesh "
        "posed on its elements' samples (rigid types) or deformed with them (deformable types), spheres and "
        "tubes for types without a mesh; write it as one scene (docs/format.md, \"Element geometry\").");
    cmd->add_option("INPUT", args->input, "The data (.json or .csv); mesh paths are relative to a JSON file.")
        ->required()
        ->type_name("FILE");
    add_output_option(*cmd, args->output,
                      "The scene: .usda (USD layer: a PointInstancer of the instanced elements, meshes of "
                      "their own for the others), .gltf (buffer embedded) or .glb (see --gltf-instancing), "
                      ".obj, or .mesh.ply (ASCII PLY with per-face element and class).",
                      true);
    add_integer_option(*cmd, "--sphere-subdivisions", args->options.geometry.sphere_subdivisions,
                    "Subdivisions of the icosphere of single-sample elements without a mesh (0 to 5; 20 x 4^N "
                    "triangles).");
    add_integer_option(*cmd, "--tube-sides", args->options.geometry.tube_sides,
                    "Sides of the tubes of multi-sample elements without a mesh (3 to 64).");
    cmd->add_option("--deform-falloff", args->options.geometry.deform_falloff,
                    "Width of a sample's influence on a deformable mesh, times the mean distance between "
                    "consecutive reference samples (> 0; larger = smoother, less exact bends).")
        ->capture_default_str();
    add_gltf_instancing_option(*cmd, args->gltf_instancing);
    add_input_domain_option(*cmd, args->input_domain, "INPUT");
    add_quiet_option(*cmd, args->quiet);
    return {cmd, [args] { run_scene(*args); }};
}

}  // namespace tessera_cli
