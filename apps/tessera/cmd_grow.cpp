// apps/tessera/cmd_grow.cpp — `tessera grow INPUT -o OUTPUT (--region SHAPE | --elements N)`:
// grows an arrangement outward along its horizon (tessera::Grower, docs/grow.md), from a
// patch of the exemplar or next to the elements of --from, which stay where they are.
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "common.hpp"
#include "interrupt_scope.hpp"
#include "option_flags.hpp"
#include "status_printer.hpp"

namespace tessera_cli {
namespace {

struct GrowArgs {
    std::string input, output, region, from, preview, rounds_dir, input_domain;
    std::string gltf_instancing = "gpu";
    int elements = 0;
    bool quiet = false;
    tessera::GrowOptions options;
    OptionFlags flags;  // GrowOptions as flags, from the table (tessera/option_table.hpp)
    CLI::Option* region_option = nullptr;
    CLI::Option* elements_option = nullptr;
};

// The library's errors about a grow call's target name its parameters; the CLI names its flags.
const FlagNames grow_flags = {{"elements", "--elements"}, {"region", "--region"}};

// A picture of the arrangement after each round, all framed by `frame`, and a contact
// sheet of them side by side.
class RoundPictures {
public:
    RoundPictures(std::string dir, tessera::Domain frame) : dir_(std::move(dir)), frame_(std::move(frame)) {}
    void add(const tessera::Arrangement& a) {
        tessera::Arrangement shot = a;
        shot.domain = frame_;
        std::ostringstream name;
        name << dir_ << "/round_" << std::setw(3) << std::setfill('0') << shots_.size() << ".png";
        tessera::render_to_file(shot, name.str());
        shots_.push_back(std::move(shot));
    }
    // The rounds laid out on a grid of frames with a gap, drawn as one arrangement.
    void write_sheet() const {
        if (shots_.empty()) return;
        const tessera::Box b = frame_.bounds();
        const tessera::Vec3 size = b.hi - b.lo;
        const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(shots_.size()))));
        const int rows = (static_cast<int>(shots_.size()) + columns - 1) / columns;
        const double gap = 0.15 * std::max(size.x, size.y);
        tessera::Exemplar sheet;
        sheet.dimension = 2;
        sheet.types = shots_.front().types;
        for (size_t k = 0; k < shots_.size(); ++k) {
            const double dx = (k % columns) * (size.x + gap) - b.lo.x;
            const double dy = (rows - 1 - static_cast<int>(k) / columns) * (size.y + gap) - b.lo.y;
            for (const tessera::Element& e : shots_[k].elements) {
                std::vector<tessera::Vec3> samples;
                for (int s = 0; s < e.sample_count; ++s) {
                    const tessera::Vec3 p = shots_[k].samples[e.first_sample + s].p;
                    samples.push_back({p.x + dx, p.y + dy, 0.0});
                }
                sheet.add_element(e.type, samples, e.radius);
            }
        }
        sheet.domain = tessera::Domain::box({0, 0, 0}, {columns * (size.x + gap) - gap, rows * (size.y + gap) - gap, 0}, 2);
        tessera::RenderOptions options;
        options.width = 1600;
        tessera::render_to_file(sheet, dir_ + "/contact_sheet.png", options);
    }

private:
    std::string dir_;
    tessera::Domain frame_;
    std::vector<tessera::Arrangement> shots_;
};

void run_grow(GrowArgs& args) {
    StatusPrinter status("grow", args.quiet, std::cerr);
    std::optional<InterruptScope> interrupt_scope(std::in_place);
    const bool by_region = args.region_option->count() > 0, by_count = args.elements_option->count() > 0;
    if (by_region == by_count) fail_option("give one of --region SHAPE or --elements N");
    if (by_count && args.elements <= 0) fail_option("--elements must be > 0, got " + std::to_string(args.elements));
    if (by_region) tessera::check_domain_spec(args.region, "--region");
    args.flags.apply(tessera::grow_option_table(), args.options);
    check_arrangement_output(args.output, "-o");
    if (!args.preview.empty()) check_output_path(args.preview, "--preview", {".png", ".svg"});
    tessera::SaveOptions save_options;
    save_options.gltf_instancing = parse_gltf_instancing_option(args.gltf_instancing);
    const tessera::Exemplar exemplar =
        status.step("reading " + args.input, [&] { return load_input(args.input, args.input_domain); });
    std::optional<tessera::Arrangement> existing;
    if (!args.from.empty()) {
        tessera::Arrangement a;
        static_cast<tessera::Exemplar&>(a) = status.step("reading " + args.from, [&] { return load_input(args.from, ""); });
        existing = std::move(a);
    }
    args.flags.apply(tessera::grow_option_table(), args.options, exemplar.dimension);  // --field
    std::optional<tessera::Domain> region;
    if (by_region) region = tessera::parse_output_domain(args.region, exemplar, 1.0, "--region");
    if (!args.rounds_dir.empty() && (exemplar.dimension != 2 || !region))
        fail_option("--round-pictures needs a 2D exemplar and --region");
    tessera::Grower grower = status.step("indexing the exemplar", [&] {
        return with_flag_names(grow_flags, [&] { return tessera::Grower(exemplar, args.options); });
    });
    if (existing) grower.set_arrangement(*existing);
    std::optional<RoundPictures> pictures;
    if (!args.rounds_dir.empty()) {
        std::error_code error;
        std::filesystem::create_directories(args.rounds_dir, error);
        if (error) throw tessera::Error(tessera::ErrorKind::io, "--round-pictures: cannot create " + args.rounds_dir);
        pictures.emplace(args.rounds_dir, *region);
    }
    tessera::Progress progress = status.progress([] { return !interrupt_requested(); }, "round");
    int pictured = -2;  // the last round pictured: a round's event is re-sent while the next one runs
    grower.set_progress([&](const tessera::ProgressEvent& e) {
        if (pictures && e.stage == "round" && e.iteration != pictured) {
            pictures->add(grower.arrangement());
            pictured = e.iteration;
        }
        return progress(e);
    });
    tessera::GrowReport report;
    try {
        report = with_flag_names(grow_flags, [&] { return region ? grower.grow(*region) : grower.grow(args.elements); });
    } catch (const tessera::Cancelled&) {
        throw tessera::Error(tessera::ErrorKind::cancelled, "interrupted; nothing was written");
    }
    status.flush();
    interrupt_scope.reset();
    if (pictures) pictures->write_sheet();
    const tessera::Arrangement& result = grower.arrangement();
    if (!args.preview.empty())
        status.step("writing " + args.preview, [&] { tessera::render_to_file(result, args.preview); });
    status.step("writing " + args.output, [&] { return write_arrangement(result, args.output, save_options); });
    if (!args.quiet) {
        char line[256];
        std::snprintf(line, sizeof line, "done: %zu elements (%d grown in %d rounds), %.2f s, final energy %.6g",
                      result.elements.size(), report.added, report.rounds, report.seconds, report.energy);
        std::cerr << line;
        if (report.bound_hit) std::cerr << "; stopped by --max-rounds " << args.options.max_rounds;
        if (report.uncovered > 0)
            std::cerr << "; " << report.uncovered << " of them filled in where the horizon stopped";
        if (report.rare > 0)
            std::cerr << "; " << report.rare << " of a rare type added where it fell short of its share";
        if (report.thinned > 0)
            std::cerr << "; " << report.thinned << " removed where the region held more than the exemplar's density";
        std::cerr << "; wrote " << args.output << (args.preview.empty() ? "" : " and " + args.preview) << std::endl;
    }
}

}  // namespace

Subcommand add_grow_command(CLI::App& app) {
    auto args = std::make_shared<GrowArgs>();
    CLI::App* cmd = app.add_subcommand(
        "grow",
        "Grow an arrangement like the exemplar INPUT outward along its horizon (on-demand synthesis, "
        "docs/grow.md): over a region, or by about N elements, from a patch of the exemplar or next to the "
        "elements of --from, which never move.");
    cmd->add_option("INPUT", args->input, "Exemplar: a tessera .json file or a .csv table (docs/format.md).")
        ->required()
        ->type_name("FILE");
    add_output_option(*cmd, args->output,
                      "The grown arrangement: .json, .csv, .ply, .png, .svg, or a scene .usda, .gltf, .glb, .obj "
                      "or .mesh.ply.",
                      true);
    args->region_option = cmd->add_option("--region", args->region,
                                          "Grow until this region is covered: the --domain forms of 'tessera synth' "
                                          "(box:W,H, box:xmin,ymin,xmax,ymax, polygon:..., mask:..., mesh:...).")
                              ->type_name("SHAPE");
    args->elements_option =
        add_integer_option(*cmd, "--elements", args->elements, "Grow by about this many elements (> 0).")
            ->type_name("N");
    args->region_option->excludes(args->elements_option);
    cmd->add_option("--from", args->from,
                    "Start from this arrangement (.json or .csv): its elements are locked and growth continues "
                    "next to them.")
        ->type_name("FILE");
    cmd->add_option("--preview", args->preview, "Also write a picture of the result (.png or .svg).")
        ->type_name("FILE");
    cmd->add_option("--round-pictures", args->rounds_dir,
                    "2D with --region: write a picture after each round (round_NNN.png) and a contact sheet "
                    "(contact_sheet.png) into this directory.")
        ->type_name("DIR");
    args->flags.add(*cmd, {method_options("grow", tessera::grow_option_table())});
    add_gltf_instancing_option(*cmd, args->gltf_instancing);
    add_input_domain_option(*cmd, args->input_domain, "INPUT");
    add_quiet_option(*cmd, args->quiet);
    return {cmd, [args] { run_grow(*args); }};
}

}  // namespace tessera_cli
