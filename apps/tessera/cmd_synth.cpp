// apps/tessera/cmd_synth.cpp — `tessera synth INPUT -o OUTPUT`: loads an exemplar,
// builds the output domain (--scale or --domain), runs tessera::synthesize_det (--method
// det, the DetOptions given as flags of the same names) or tessera::synthesize_pcf
// (--method pcf, the PcfSynthOptions likewise) or tessera::synthesize_dynamic (--method
// dynamic, synth_dynamic.cpp), prints progress to stderr, and writes the
// output (data, a picture, or a scene of the elements' geometry) and an optional
// --preview picture.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common.hpp"
#include "interrupt_scope.hpp"
#include "option_flags.hpp"
#include "status_printer.hpp"
#include "synth_dynamic.hpp"
#include "tessera/animation_io.hpp"
#include "tessera/option_text.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera_cli {
namespace {


struct SynthArgs {
    std::string input, output, preview, input_domain, domain, meshes = "auto", coarse;
    std::string gltf_instancing = "gpu";
    double scale = 2.0;
    std::string method = "det";
    bool quiet = false;
    // The methods' options, as flags made from their tables (tessera/option_table.hpp).
    MethodOptions det_options = method_options("det", tessera::det_option_table());
    MethodOptions pcf_options = method_options("pcf", tessera::pcf_option_table());
    MethodOptions dynamic_options = method_options("dynamic", tessera::dynamic_option_table());
    OptionFlags flags;
    tessera::DetOptions det;
    tessera::PcfSynthOptions pcf;
    tessera::DynamicOptions dynamic;
    CLI::App* command = nullptr;
    CLI::Option* method_option = nullptr;
    CLI::Option* scale_option = nullptr;
    CLI::Option* domain_option = nullptr;
    CLI::Option* coarse_option = nullptr;
};

tessera::Domain output_domain(const SynthArgs& args, const tessera::Exemplar& exemplar) {
    if (args.domain_option->count() == 0) return exemplar.domain.scaled(args.scale);
    return tessera::parse_output_domain(args.domain, exemplar, args.scale, "--domain");
}

// The methods that have the flag `flag` (as typed), "det or pcf".
std::string methods_with(const SynthArgs& args, const std::string& flag) {
    std::string names;
    for (const MethodOptions* m : {&args.det_options, &args.pcf_options, &args.dynamic_options}) {
        const std::vector<std::string> outside = args.flags.given_outside(*m);
        if (std::find(outside.begin(), outside.end(), flag) != outside.end()) continue;
        names += (names.empty() ? "" : " or ") + m->method;
    }
    return names;
}

// Checks every flag that does not need the input, naming the flag and its value, and
// stores the method's options.
void check_options(SynthArgs& args) {
    // An INPUT with frames is animated, and --coarse asks for motion: the dynamic method,
    // unless --method says otherwise.
    if (args.method_option->count() == 0 && (tessera::has_frames(args.input) || !args.coarse.empty()))
        args.method = "dynamic";
    if (args.method != "det" && args.method != "pcf" && args.method != "dynamic")
        fail_option("--method must be det, pcf or dynamic, got '" + args.method + "'");
    const MethodOptions& method = args.method == "pcf"       ? args.pcf_options
                                  : args.method == "dynamic" ? args.dynamic_options
                                                             : args.det_options;
    for (const std::string& flag : args.flags.given_outside(method))
        fail_option(flag + " applies to --method " + methods_with(args, flag) + " only");
    if (!std::isfinite(args.scale) || !(args.scale > 0.0))
        fail_option("--scale must be a number > 0, got " + format_number(args.scale));
    if (args.method == "pcf")
        args.flags.apply(tessera::pcf_option_table(), args.pcf);
    else if (args.method == "dynamic")
        args.flags.apply(tessera::dynamic_option_table(), args.dynamic);
    else
        args.flags.apply(tessera::det_option_table(), args.det);
    if (!args.det.boundary_sides.empty() && !(args.det.boundary_distance > 0.0))
        fail_option("--boundary needs --boundary-distance D > 0");
}

void run_synth_dynamic(SynthArgs& args, StatusPrinter& status) {
    const DynamicRun run{args.input, args.input_domain, args.output, args.preview, args.coarse, args.dynamic,
                         args.quiet};
    check_dynamic_outputs(run);
    if (!args.coarse.empty() && (args.domain_option->count() > 0 || args.scale_option->count() > 0))
        fail_option("--coarse gives the output's elements and where they go: --domain and --scale do not apply");
    if (args.domain_option->count() > 0) tessera::check_domain_spec(args.domain, "--domain");
    run_dynamic(run, status, [&](const tessera::Exemplar& first) { return output_domain(args, first); });
}

void run_synth(SynthArgs& args) {
    std::optional<InterruptScope> interrupt_scope(std::in_place);
    StatusPrinter status("synth", args.quiet, std::cerr);
    check_options(args);
    if (!args.coarse.empty() && args.method != "dynamic")
        fail_option("--coarse belongs to --method dynamic, not " + args.method);
    if (args.method == "dynamic") {
        interrupt_scope.reset();  // run_dynamic has its own
        return run_synth_dynamic(args, status);
    }
    if (args.domain_option->count() > 0) tessera::check_domain_spec(args.domain, "--domain");
    check_arrangement_output(args.output, "-o");
    tessera::RenderOptions preview_options;
    preview_options.meshes = parse_meshes_option(args.meshes);
    if (!args.preview.empty()) {
        check_output_path(args.preview, "--preview", {".png", ".svg"});
        check_meshes_for_picture(preview_options.meshes, args.preview);
    }
    tessera::SaveOptions save_options;
    save_options.gltf_instancing = parse_gltf_instancing_option(args.gltf_instancing);

    const tessera::Exemplar exemplar =
        status.step("reading " + args.input, [&] { return load_input(args.input, args.input_domain); });
    // A scene output needs the types' meshes and reference layouts: check them (by
    // building the exemplar's scene) before the synthesis rather than after it.
    const bool preview_meshes =
        !args.preview.empty() && preview_options.meshes != tessera::RenderOptions::Meshes::off &&
        std::any_of(exemplar.types.begin(), exemplar.types.end(), [](const auto& t) { return !t.mesh.empty(); });
    if (tessera::is_scene_path(args.output) || preview_meshes)
        status.step("checking the element meshes", [&] { tessera::build_scene(exemplar); });
    const tessera::Domain domain =
        status.step("building the output domain", [&] { return output_domain(args, exemplar); });
    if (!args.quiet && !domain.notes().empty()) std::cerr << "synth: note: " << domain.notes() << std::endl;
    const bool pcf = args.method == "pcf";
    if (!pcf) args.flags.apply(tessera::det_option_table(), args.det, exemplar.dimension);  // --field
    if (!args.quiet) {
        std::cerr << "synth: " << exemplar.elements.size() << " elements in " << exemplar.domain.describe()
                  << " -> " << domain.describe();
        if (pcf)
            std::cerr << " (method pcf, seed " << args.pcf.seed << ", at most " << args.pcf.max_iterations
                      << " sweeps per class)" << std::endl;
        else
            std::cerr << " (method det, seed " << args.det.seed << ", " << args.det.iterations << " iterations"
                      << (args.det.field.active() ? ", field " + args.det.field.describe() : std::string()) << ")"
                      << std::endl;
    }

    tessera::Arrangement result;
    const auto keep_going = [] { return !interrupt_requested(); };
    try {
        if (pcf)
            result = tessera::synthesize_pcf(exemplar, domain, args.pcf, status.progress(keep_going, "sweep"));
        else
            result = tessera::synthesize_det(exemplar, domain, args.det, status.progress(keep_going, "iteration"));
    } catch (const tessera::Cancelled&) {
        throw tessera::Error(tessera::ErrorKind::cancelled, "interrupted; nothing was written");
    }
    status.flush();
    interrupt_scope.reset();  // from here Ctrl-C stops the command the usual way (writes are atomic)

    // The preview goes first: when OUTPUT exists, the whole command succeeded. Its width
    // is fixed, so a picture too large for it is the preview's fault.
    if (!args.preview.empty())
        status.step("writing " + args.preview, [&] {
            with_flag_names({{"width", "--preview"}, {"meshes", "--meshes"}},
                            [&] { tessera::render_to_file(result, args.preview, preview_options); });
        });
    const std::string scene =
        status.step("writing " + args.output, [&] { return write_arrangement(result, args.output, save_options); });
    if (!args.quiet) {
        char line[256];
        std::snprintf(line, sizeof line, "done: %zu elements, %.2f s, final energy %.6g",
                      result.elements.size(), result.stats.total_seconds, result.stats.final_energy);
        std::cerr << line << "; wrote " << args.output << (args.preview.empty() ? "" : " and " + args.preview)
                  << std::endl;
        if (!scene.empty()) std::cerr << "scene: " << scene << std::endl;
        const tessera::RunStats& st = result.stats;
        for (const std::string& note : st.notes) std::cerr << "synth: note: " << note << std::endl;
        if (st.physics) {
            std::snprintf(line, sizeof line,
                          "physics: interpenetrating pairs %d -> %d, deepest overlap %.4g -> %.4g, floating %d -> %d",
                          st.penetrations_before, st.penetrations_after, st.max_depth_before, st.max_depth_after,
                          st.floating_before, st.floating_after);
            std::cerr << line << std::endl;
        }
    }
}

}  // namespace

Subcommand add_synth_command(CLI::App& app) {
    auto args = std::make_shared<SynthArgs>();
    CLI::App* cmd = app.add_subcommand(
        "synth",
        "Synthesize an arrangement like the exemplar INPUT in a new domain and write it to OUTPUT. "
        "Progress goes to stderr: the set-up stages and the iterations, at most 4 lines per second.");
    cmd->add_option("INPUT", args->input, "Exemplar: a tessera .json file or a .csv table (docs/format.md).")
        ->required()
        ->type_name("FILE");
    add_output_option(
        *cmd, args->output,
        "Output file, by extension: .json (with run statistics), .csv, .ply (one point per element "
        "with orient, pscale, class, id for instancing), a picture .png/.svg, or the elements' geometry "
        "as a scene: .usda (USD PointInstancer), .gltf/.glb (see --gltf-instancing), .obj, .mesh.ply "
        "(docs/format.md). Written only when the run succeeds.",
        true);
    args->scale_option =
        cmd->add_option(
               "--scale", args->scale,
               "Output domain = the input domain scaled by this factor on every axis, keeping its lower "
               "corner (2 = twice as wide and tall, about 4x the elements in 2D). Used when --domain is "
               "not given.")
            ->capture_default_str();
    args->domain_option =
        cmd->add_option(
               "--domain", args->domain,
               "Output domain: box:W,H (2D) or box:W,H,D (3D) = a box of that size from the input domain's "
               "lower corner; box:xmin,ymin,xmax,ymax or box:xmin,ymin,xmax,ymax,zmin,zmax = explicit "
               "corners; polygon:FILE.json or polygon:x1,y1,x2,y2,... (2D, holes in the file form); "
               "mask:FILE.png[@xmin,ymin,xmax,ymax] (2D, white = inside); mesh:FILE[,resolution] (3D closed "
               "OBJ/PLY mesh); shell:FILE,thickness[,resolution] (3D band under a mesh surface). Its "
               "dimension must be the input's.")
            ->type_name("SPEC");
    args->scale_option->excludes(args->domain_option);
    add_input_domain_option(*cmd, args->input_domain, "INPUT");
    cmd->add_option(
           "--preview", args->preview,
           "Also write a picture of the output (.png or .svg, 800 pixels wide). It is written before "
           "OUTPUT, so an existing OUTPUT means the whole command succeeded.")
        ->type_name("FILE");
    add_meshes_option(*cmd, args->meshes);
    add_gltf_instancing_option(*cmd, args->gltf_instancing);
    args->method_option =
        cmd->add_option("--method", args->method,
                        "Synthesis method: det (neighbourhood matching, Discrete Element Textures), pcf "
                        "(2D disks from pair correlation functions, docs/pcf_synthesis.md) or dynamic (elements "
                        "in space and time from an exemplar with frames, docs/dynamic.md; the default when INPUT "
                        "has frames).")
            ->capture_default_str();
    args->coarse_option =
        cmd->add_option("--coarse", args->coarse,
                        "Dynamic method: an animation (.json or .csv with frames) giving the output's elements "
                        "and their coarse motion: threads, sheets or particles; the exemplar's detail motion is "
                        "laid on it, all frames together (docs/dynamic.md). The output has its elements, frames "
                        "and times.")
            ->type_name("FILE");
    // Every option of the methods, from their tables: shared ones (--seed, --iterations) once.
    args->flags.add(*cmd, {args->det_options, args->pcf_options, args->dynamic_options});
    add_quiet_option(*cmd, args->quiet);
    args->command = cmd;
    return {cmd, [args] { run_synth(*args); }};
}

}  // namespace tessera_cli
