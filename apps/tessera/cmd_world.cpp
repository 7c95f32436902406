// apps/tessera/cmd_world.cpp — `tessera world INPUT --tiles X0:X1,Y0:Y1[,Z0:Z1] --tile-size S
// -o DIR`: a range of an unbounded world of deterministic tiles (tessera/world.hpp,
// docs/worlds.md), one file per tile and an index, or with --merge one arrangement.
#include <cstdio>
#include <iostream>
#include <memory>

#include "common.hpp"
#include "interrupt_scope.hpp"
#include "option_flags.hpp"
#include "status_printer.hpp"
#include "tile_ranges.hpp"
#include "world_files.hpp"

namespace tessera_cli {
namespace {

struct WorldArgs {
    std::string input, output, preview, input_domain;
    std::vector<std::string> ranges;
    std::string gltf_instancing = "gpu";
    double tile_size = 0.0;
    bool merge = false, quiet = false;
    std::string method = "grow";
    tessera::GrowOptions options;
    tessera::PcfSynthOptions pcf;
    // The methods' options as flags, from their tables (tessera/option_table.hpp).
    MethodOptions grow_options = method_options("grow", tessera::grow_option_table());
    MethodOptions pcf_options = method_options("pcf", tessera::pcf_option_table());
    OptionFlags flags;
};

const FlagNames world_flags = {{"tile_size", "--tile-size"}, {"threads", "--threads"}};

// The requested tiles merged, framed by their boxes, with the tile borders drawn faintly.
void write_preview(const tessera::Arrangement& merged, double tile_size, const std::string& path) {
    tessera::RenderOptions options;
    options.width = merged.dimension == 2 ? 1600 : 1200;
    options.grid = tile_size;
    tessera::render_to_file(merged, path, options);
}

void run_world(WorldArgs& args) {
    StatusPrinter status("world", args.quiet, std::cerr);
    std::optional<InterruptScope> interrupt_scope(std::in_place);
    if (args.method != "grow" && args.method != "pcf")
        fail_option("--method must be grow or pcf, got '" + args.method + "'");
    const bool pcf = args.method == "pcf";
    for (const std::string& flag : args.flags.given_outside(pcf ? args.pcf_options : args.grow_options))
        fail_option(flag + " applies to --method " + (pcf ? "grow" : "pcf") + " only");
    if (pcf)
        args.flags.apply(tessera::pcf_option_table(), args.pcf);
    else
        args.flags.apply(tessera::grow_option_table(), args.options);
    if (args.merge) check_arrangement_output(args.output, "-o");
    if (!args.preview.empty()) check_output_path(args.preview, "--preview", {".png", ".svg"});
    tessera::SaveOptions save_options;
    save_options.gltf_instancing = parse_gltf_instancing_option(args.gltf_instancing);
    const tessera::Exemplar exemplar =
        status.step("reading " + args.input, [&] { return load_input(args.input, args.input_domain); });
    if (!pcf) args.flags.apply(tessera::grow_option_table(), args.options, exemplar.dimension);  // --field
    std::vector<TileRange> ranges;
    for (const std::string& r : args.ranges) ranges.push_back(parse_tile_range(r, exemplar.dimension, "--tiles"));
    const std::vector<tessera::TileCoord> wanted = tiles_of(ranges, "--tiles");
    // Tiles run side by side, each tile's growth on one thread (small tiles gain nothing
    // from more); the tiles are the same either way.
    tessera::WorldOptions world;
    world.tile_size = args.tile_size;
    world.grow = args.options;
    world.grow.threads = 1;
    if (pcf) {
        world.method = tessera::WorldMethod::pcf;
        world.pcf = args.pcf;
        world.pcf.threads = 1;
        world.grow.seed = args.pcf.seed;  // a world's seed is its growth's (tessera/world.hpp)
    }
    const int threads = pcf ? args.pcf.threads : args.options.threads;
    const tessera::TileMaker maker = status.step("indexing the exemplar", [&] {
        return with_flag_names(world_flags, [&] { return tessera::TileMaker(exemplar, world); });
    });
    if (!args.merge) check_world_dir(args.output, maker);
    std::map<tessera::TileCoord, tessera::Arrangement> tiles;
    try {
        tiles = tessera::make_tiles(maker, wanted, threads,
                                    status.progress([] { return !interrupt_requested(); }));
    } catch (const tessera::Cancelled&) {
        throw tessera::Error(tessera::ErrorKind::cancelled, "interrupted; nothing was written");
    }
    status.flush();
    interrupt_scope.reset();
    std::vector<const tessera::Arrangement*> parts;
    for (const tessera::TileCoord& t : wanted) parts.push_back(&tiles.at(t));
    const tessera::Arrangement merged = tessera::merge_tiles(parts, exemplar.dimension);
    if (args.merge)
        status.step("writing " + args.output, [&] { return write_arrangement(merged, args.output, save_options); });
    else
        status.step("writing " + args.output, [&] { write_world_dir(args.output, maker, args.input, wanted, tiles); });
    if (!args.preview.empty()) status.step("writing " + args.preview, [&] { write_preview(merged, args.tile_size, args.preview); });
    if (!args.quiet) {
        char line[256];
        std::snprintf(line, sizeof line, "done: %zu tiles, %zu elements (%zu more tiles made as their neighbours)",
                      wanted.size(), merged.elements.size(), tiles.size() - wanted.size());
        std::cerr << line << "; wrote " << args.output << (args.preview.empty() ? "" : " and " + args.preview) << std::endl;
    }
}

}  // namespace

Subcommand add_world_command(CLI::App& app) {
    auto args = std::make_shared<WorldArgs>();
    CLI::App* cmd = app.add_subcommand(
        "world",
        "Make tiles of an unbounded world like the exemplar INPUT (docs/worlds.md): each tile grown next to its "
        "finished neighbours, the same whatever order, thread count or machine made it.");
    cmd->add_option("INPUT", args->input, "Exemplar: a tessera .json file or a .csv table (docs/format.md).")
        ->required()
        ->type_name("FILE");
    cmd->add_option("--tiles", args->ranges,
                    "Tiles to make, X0:X1,Y0:Y1 (2D) or X0:X1,Y0:Y1,Z0:Z1 (3D), ends exclusive: 0:4,0:4 is 16 tiles. "
                    "Repeat for several ranges (they must not overlap).")
        ->required()
        ->take_all()
        ->type_name("RANGE");
    cmd->add_option("--tile-size", args->tile_size,
                    "Edge of a tile in the exemplar's units; at least the neighbourhood the growth needs (the error "
                    "says how much for this exemplar).")
        ->required()
        ->type_name("S");
    add_output_option(*cmd, args->output,
                      "A directory: one tile_X_Y[_Z].json per tile and index.json (tiles, bounds, counts, hashes). "
                      "With --merge a file: .json, .csv, .ply, .png, .svg or a scene .usda, .gltf, .glb, .obj, .mesh.ply.",
                      true);
    cmd->add_flag("--merge", args->merge, "Write the tiles as one arrangement to the file -o.");
    cmd->add_option("--preview", args->preview,
                    "Also write a picture of the tiles (.png or .svg), tile borders drawn faintly.")
        ->type_name("FILE");
    cmd->add_option("--method", args->method,
                    "grow: each tile grown by neighbourhood matching next to its neighbours (2D and 3D, any "
                    "elements); pcf: each tile synthesized by the PCF method with its neighbours' elements fixed "
                    "(2D, single-sample elements).")
        ->default_str("grow")
        ->type_name("grow|pcf");
    args->flags.add(*cmd, {args->grow_options, args->pcf_options});
    add_gltf_instancing_option(*cmd, args->gltf_instancing);
    add_input_domain_option(*cmd, args->input_domain, "INPUT");
    add_quiet_option(*cmd, args->quiet);
    return {cmd, [args] { run_world(*args); }};
}

}  // namespace tessera_cli
