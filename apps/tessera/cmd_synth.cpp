// apps/tessera/cmd_synth.cpp — `tessera synth INPUT -o OUTPUT`: loads an exemplar,
// builds the output domain (--scale or --domain), runs tessera::synthesize_det (--method
// det, the DetOptions given as flags of the same names) or tessera::synthesize_pcf
// (--method pcf, the PcfSynthOptions likewise), prints progress to stderr, and writes the
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
#include "status_printer.hpp"
#include "tessera/option_text.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera_cli {
namespace {


struct SynthArgs {
    std::string input, output, preview, input_domain, domain, field, gravity, boundary, meshes = "auto";
    std::string gltf_instancing = "gpu";
    double scale = 2.0;
    std::string method = "det";
    std::string search, matching;
    bool quiet = false;
    tessera::DetOptions det;    // --seed, --threads and --iterations land here for both methods
    tessera::PcfSynthOptions pcf;
    CLI::App* command = nullptr;
    CLI::Option* scale_option = nullptr;
    CLI::Option* domain_option = nullptr;
};

// The flags that belong to one method only.
const std::vector<std::string> det_only_flags = {
    "--radius", "--k",       "--search",           "--matching", "--alpha",   "--lambda",        "--patch-size",
    "--patch-candidates", "--physics", "--physics-substeps", "--gravity", "--floor-distance", "--field",
    "--boundary", "--boundary-distance"};
const std::vector<std::string> pcf_only_flags = {"--max-fails",      "--grid-cells", "--epsilon0",
                                                 "--epsilon-step",   "--convergence", "--stall", "--outlier-rounds",
                                                 "--sigma",          "--step",        "--extent"};

tessera::Domain output_domain(const SynthArgs& args, const tessera::Exemplar& exemplar) {
    if (args.domain_option->count() == 0) return exemplar.domain.scaled(args.scale);
    return tessera::parse_output_domain(args.domain, exemplar, args.scale, "--domain");
}

// Checks every flag that does not need the input, naming the flag and its value.
void check_options(SynthArgs& args) {
    const tessera::DetOptions& d = args.det;
    if (args.method != "det" && args.method != "pcf")
        fail_option("--method must be det or pcf, got '" + args.method + "'");
    const bool pcf = args.method == "pcf";
    for (const std::string& flag : pcf ? det_only_flags : pcf_only_flags)
        if (args.command->count(flag) > 0) fail_option(flag + " applies to --method " + (pcf ? "det" : "pcf") + " only");
    args.det.search = tessera::parse_search_mode(args.search, "--search");
    args.det.matching = tessera::parse_matching(args.matching, "--matching");
    if (!std::isfinite(args.scale) || !(args.scale > 0.0))
        fail_option("--scale must be a number > 0, got " + format_number(args.scale));
    if (d.iterations < 0) fail_option("--iterations must be >= 0, got " + std::to_string(d.iterations));
    if (!std::isfinite(d.radius) || d.radius < 0.0)
        fail_option("--radius must be > 0, or 0 for automatic; got " + format_number(d.radius));
    if (d.threads < 0)
        fail_option("--threads must be >= 0 (0 = all hardware threads), got " + std::to_string(d.threads));
    if (d.k < 1) fail_option("--k must be >= 1, got " + std::to_string(d.k));
    if (!std::isfinite(d.alpha)) fail_option("--alpha must be a finite number (negative = automatic)");
    if (!std::isfinite(d.lambda)) fail_option("--lambda must be a finite number (negative = automatic)");
    if (!std::isfinite(d.patch_size) || d.patch_size < 0.0)
        fail_option("--patch-size must be > 0, or 0 for automatic; got " + format_number(d.patch_size));
    if (d.patch_candidates < 1)
        fail_option("--patch-candidates must be >= 1, got " + std::to_string(d.patch_candidates));
    if (d.relax_sweeps < 0 || d.relax_sweeps > 1000)
        fail_option("--relax-sweeps must be from 0 to 1000, got " + std::to_string(d.relax_sweeps));

    // --method pcf: the shared flags go into PcfSynthOptions; --iterations bounds the
    // refinement sweeps per class (default 100 there).
    tessera::PcfSynthOptions& p = args.pcf;
    p.seed = d.seed;
    p.threads = d.threads;
    if (args.command->count("--iterations") > 0) p.max_iterations = d.iterations;
    p.relax_sweeps = d.relax_sweeps;
    const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
    const auto non_negative = [](double v) { return std::isfinite(v) && v >= 0.0; };
    if (p.max_fails < 0) fail_option("--max-fails must be >= 0, got " + std::to_string(p.max_fails));
    if (p.grid_cells < 1 || p.grid_cells > 4096)
        fail_option("--grid-cells must be from 1 to 4096, got " + std::to_string(p.grid_cells));
    if (!non_negative(p.epsilon0)) fail_option("--epsilon0 must be a number >= 0, got " + format_number(p.epsilon0));
    if (!non_negative(p.epsilon_step))
        fail_option("--epsilon-step must be a number >= 0, got " + format_number(p.epsilon_step));
    if (!non_negative(p.convergence))
        fail_option("--convergence must be a number >= 0, got " + format_number(p.convergence));
    if (!non_negative(p.stall)) fail_option("--stall must be a number >= 0, got " + format_number(p.stall));
    if (p.outlier_rounds < 0) fail_option("--outlier-rounds must be >= 0, got " + std::to_string(p.outlier_rounds));
    if (!positive(p.analysis.sigma)) fail_option("--sigma must be a number > 0, got " + format_number(p.analysis.sigma));
    if (!positive(p.analysis.step)) fail_option("--step must be a number > 0, got " + format_number(p.analysis.step));
    if (!positive(p.analysis.extent))
        fail_option("--extent must be a number > 0, got " + format_number(p.analysis.extent));
}

void run_synth(SynthArgs& args) {
    std::optional<InterruptScope> interrupt_scope(std::in_place);
    StatusPrinter status("synth", args.quiet, std::cerr);
    check_options(args);
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
    if (!args.field.empty()) args.det.field = tessera::OrientationField::parse(args.field, exemplar.dimension, "--field");
    if (!args.gravity.empty()) args.det.gravity = tessera::parse_axis_direction(args.gravity, "--gravity");
    if (!args.boundary.empty()) {
        args.det.boundary_sides = tessera::parse_boundary_sides(args.boundary, "--boundary");
        if (!(args.det.boundary_distance > 0.0)) fail_option("--boundary needs --boundary-distance D > 0");
    }
    const bool pcf = args.method == "pcf";
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
    args->search = tessera::to_string(args->det.search);
    args->matching = tessera::to_string(args->det.matching);
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
    cmd->add_option("--method", args->method,
                    "Synthesis method: det (neighbourhood matching, Discrete Element Textures) or pcf "
                    "(2D disks from pair correlation functions, docs/pcf_synthesis.md).")
        ->capture_default_str();
    add_seed_option(*cmd, args->det.seed);
    add_integer_option(*cmd, "--iterations", args->det.iterations,
                    "det: iterations of search + assignment (0 = the patch-copy initialization only). "
                    "pcf: at most this many refinement sweeps per class (default 100; 0 = no refinement).");
    cmd->add_option(
           "--radius", args->det.radius,
           "Neighbourhood radius in the exemplar's units; 0 = automatic (mean nearest-neighbour distance "
           "x 2 in 2D, x 1.5 in 3D).")
        ->capture_default_str();
    add_threads_option(*cmd, args->det.threads);
    add_integer_option(*cmd, "--k", args->det.k,
                    "Size of each exemplar sample's similarity set for k-coherence search (>= 1).");
    cmd->add_option("--search", args->search,
                    "Candidate search: kcoherence (fast, the paper's) or exhaustive (every exemplar sample).")
        ->capture_default_str();
    cmd->add_option("--matching", args->matching,
                    "Pairing of neighbourhood samples: greedy (the paper's) or hungarian (exact, slower).")
        ->capture_default_str();
    cmd->add_option("--alpha", args->det.alpha,
                    "Weight of the attribute (type) term, in squared length units; negative = automatic "
                    "(mean nearest-neighbour distance squared).")
        ->capture_default_str();
    cmd->add_option("--lambda", args->det.lambda,
                    "Weight of the domain boundary term, in squared length units; negative = automatic "
                    "(mean nearest-neighbour distance squared).")
        ->capture_default_str();
    cmd->add_option("--patch-size", args->det.patch_size,
                    "Side of the patches copied at initialization; 0 = automatic: 2 x radius, or twice the "
                    "distance over which the exemplar's pair correlation shows structure when that is "
                    "larger (clusters, lattices; not with --field), at most half the exemplar's smallest "
                    "extent (docs/det.md).")
        ->capture_default_str();
    add_integer_option(*cmd, "--patch-candidates", args->det.patch_candidates,
                    "Random candidate patches tried per cell at initialization (>= 1).");
    add_integer_option(*cmd, "--relax-sweeps", args->det.relax_sweeps,
                       "Sweeps of the pair-correlation relaxation at the end (det: exemplars of single-sample "
                       "elements; pcf: synthesis from an exemplar): small moves towards the exemplar's pair "
                       "correlation of every class pair; 0 = off, at most 1000.");
    cmd->add_flag("--physics", args->det.physics,
                  "Interleaved physics: after every iteration, rigid-body steps (Bullet) resolve "
                  "interpenetration and let elements settle under gravity; reports interpenetration and "
                  "floating elements before and after.");
    add_integer_option(*cmd, "--physics-substeps", args->det.physics_options.substeps,
                    "Rigid-body steps per iteration with --physics.");
    cmd->add_option("--gravity", args->gravity,
                    "Direction of gravity, an axis with its sign (-x, +x, -y, +y, -z, +z). Default: -y in 2D, "
                    "-z in 3D.");
    cmd->add_option("--floor-distance", args->det.floor_distance,
                    "Constrained selection at the floor: elements whose lowest sample is within this distance of "
                    "the domain boundary below them (and elements of types marked floor) are floor elements; "
                    "output floor elements copy only input floor elements and keep their elevation. "
                    "0 = only types marked floor.")
        ->capture_default_str();
    cmd->add_option("--boundary", args->boundary,
                    "Constrained selection at other boundaries than the floor: sides such as -x,+x (walls) or +y "
                    "(a ceiling). Elements within --boundary-distance of the domain's boundary on a listed side "
                    "copy only input elements touching the same sides; interior elements only interior ones.")
        ->type_name("SIDES");
    cmd->add_option("--boundary-distance", args->det.boundary_distance,
                    "Distance from a --boundary side within which an element touches it (data units, > 0 with "
                    "--boundary).")
        ->capture_default_str();
    cmd->add_option("--field", args->field,
                    "Local orientation field of the output (Eq. 7): constant:DX,DY[,DZ] (one direction), "
                    "radial:CX,CY[,CZ] (away from a centre; in 3D from the vertical axis through it) or "
                    "vortex:CX,CY[,CZ] (circling a centre counter-clockwise about +z), polyline:X1,Y1[,Z1],X2,Y2[,Z2],... "
                    "(tangent of the nearest segment) or trefoil:CX,CY,CZ,SCALE (3D). The exemplar's +x axis "
                    "follows the field. From files (docs/fields.md): grid:FILE.json (vectors at grid nodes, "
                    "interpolated) or mesh:FILE.ply|FILE.obj (3D, a direction per vertex). "
                    "Default: none (the exemplar's frame everywhere).");
    // --method pcf: the fields of tessera::PcfSynthOptions.
    add_integer_option(*cmd, "--max-fails", args->pcf.max_fails,
                    "pcf: successive rejected candidates after which a class's remaining elements are placed by "
                    "grid search (>= 0; 0 = grid search from the start).");
    add_integer_option(*cmd, "--grid-cells", args->pcf.grid_cells,
                    "pcf: cells of the grid search along the longer side of the domain (1 to 4096).");
    cmd->add_option("--epsilon0", args->pcf.epsilon0,
                    "pcf: error threshold of the first candidate of a class (Algorithm 1), >= 0.")
        ->capture_default_str();
    cmd->add_option("--epsilon-step", args->pcf.epsilon_step,
                    "pcf: increase of the threshold with every successive rejection, >= 0.")
        ->capture_default_str();
    cmd->add_option("--convergence", args->pcf.convergence,
                    "pcf: a class's refinement stops when a sweep moves its elements by less than this x r_max in "
                    "total, >= 0 (0: never).")
        ->capture_default_str();
    cmd->add_option("--stall", args->pcf.stall,
                    "pcf: a class's refinement also stops when its lowest PCF error falls by less than this "
                    "fraction per sweep over 10 sweeps, >= 0 (0: never).")
        ->capture_default_str();
    add_integer_option(*cmd, "--outlier-rounds", args->pcf.outlier_rounds,
                    "pcf: rounds of re-placing elements whose individual PCFs leave the validity region, >= 0.");
    cmd->add_option("--sigma", args->pcf.analysis.sigma,
                    "pcf: width of the Gaussian kernel on the normalised distance axis, > 0.")
        ->capture_default_str();
    cmd->add_option("--step", args->pcf.analysis.step,
                    "pcf: spacing of the PCF's values on the normalised distance axis, > 0.")
        ->capture_default_str();
    cmd->add_option("--extent", args->pcf.analysis.extent,
                    "pcf: neighbourhood of the PCFs on the normalised axis (points up to extent, disks up to "
                    "3 + extent), > 0.")
        ->capture_default_str();
    add_quiet_option(*cmd, args->quiet);
    args->command = cmd;
    return {cmd, [args] { run_synth(*args); }};
}

}  // namespace tessera_cli
