// apps/tessera/cmd_metrics.cpp — `tessera metrics EXEMPLAR OUTPUT`: compares an
// output with its exemplar (pair correlation per class pair, nearest-neighbour
// statistics, hexatic order in 2D) and prints tessera::metrics_report_json as
// pretty JSON to stdout, or writes it to -o.
#include <cmath>
#include <iostream>
#include <memory>

#include "common.hpp"
#include "status_printer.hpp"

namespace tessera_cli {
namespace {

struct MetricsArgs {
    std::string exemplar, output, report, input_domain, output_domain;
    bool quiet = false;
    tessera::PcfOptions pcf;
};

void check_options(const MetricsArgs& args) {
    if (!std::isfinite(args.pcf.r_max) || args.pcf.r_max < 0.0)
        fail_option("--rmax must be > 0, or 0 for automatic; got " + format_number(args.pcf.r_max));
    if (!std::isfinite(args.pcf.bandwidth) || args.pcf.bandwidth < 0.0)
        fail_option("--bandwidth must be > 0, or 0 for automatic; got " + format_number(args.pcf.bandwidth));
    if (args.pcf.bins != 0 && args.pcf.bins < 2)
        fail_option("--bins must be >= 2, or 0 for automatic; got " + std::to_string(args.pcf.bins));
}

void run_metrics(const MetricsArgs& args) {
    StatusPrinter status("metrics", args.quiet, std::cerr);
    check_options(args);
    if (!args.report.empty()) check_output_path(args.report, "-o", {".json"});
    const tessera::Exemplar exemplar = status.step(
        "reading " + args.exemplar, [&] { return load_input(args.exemplar, args.input_domain, "--input-domain"); });
    const tessera::Exemplar output = status.step(
        "reading " + args.output, [&] { return load_input(args.output, args.output_domain, "--output-domain"); });
    const std::string report = status.step("measuring " + std::to_string(output.elements.size()) + " elements", [&] {
        return tessera::metrics_report_json(exemplar, output, args.pcf) + "\n";
    });
    if (args.report.empty())
        std::cout << report << std::flush;
    else {
        tessera::write_file_atomic(args.report, report);
        if (!args.quiet) std::cerr << "wrote " << args.report << std::endl;
    }
}

}  // namespace

Subcommand add_metrics_command(CLI::App& app) {
    auto args = std::make_shared<MetricsArgs>();
    CLI::App* cmd = app.add_subcommand(
        "metrics",
        "Compare OUTPUT with EXEMPLAR: element counts and density, nearest-neighbour distances, hexatic "
        "order |psi6| (2D), and the pair correlation g(r) of every class pair on one r grid, with their "
        "differences. Prints a JSON report (docs/metrics.md).");
    cmd->add_option("EXEMPLAR", args->exemplar, "The exemplar (.json or .csv).")
        ->required()
        ->type_name("FILE");
    cmd->add_option("OUTPUT", args->output, "The arrangement to compare with it (.json or .csv).")
        ->required()
        ->type_name("FILE");
    add_output_option(*cmd, args->report, "Write the report to this .json file instead of stdout.", false);
    cmd->add_option(
           "--rmax", args->pcf.r_max,
           "Largest r of the pair correlation; 0 = automatic (5 x the exemplar's mean nearest-neighbour "
           "distance).")
        ->capture_default_str();
    cmd->add_option(
           "--bandwidth", args->pcf.bandwidth,
           "Standard deviation of the Gaussian kernel of the pair correlation; 0 = automatic (rmax / 40).")
        ->capture_default_str();
    add_integer_option(*cmd, "--bins", args->pcf.bins, "Number of r values from 0 to rmax; 0 = automatic (101).");
    add_input_domain_option(*cmd, args->input_domain, "EXEMPLAR");
    cmd->add_option("--output-domain", args->output_domain,
                    "Like --input-domain, for OUTPUT (useful when OUTPUT is a .csv, which stores no domain).")
        ->type_name("BOX");
    add_quiet_option(*cmd, args->quiet);
    return {cmd, [args] { run_metrics(*args); }};
}

}  // namespace tessera_cli
