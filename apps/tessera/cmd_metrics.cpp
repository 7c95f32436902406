// apps/tessera/cmd_metrics.cpp — `tessera metrics EXEMPLAR OUTPUT`: compares an
// output with its exemplar (pair correlation per class pair, nearest-neighbour
// statistics, hexatic order in 2D) and prints tessera::metrics_report_json as
// pretty JSON to stdout, or writes it to -o.
#include <cmath>
#include <iostream>
#include <memory>

#include "common.hpp"
#include "option_flags.hpp"
#include "status_printer.hpp"
#include "tessera/metrics.hpp"

namespace tessera_cli {
namespace {

struct MetricsArgs {
    std::string exemplar, output, report, input_domain, output_domain;
    bool quiet = false;
    OptionFlags estimate;  // PcfOptions as flags, from pair_correlation_option_table
    tessera::PcfOptions pcf;
};

void run_metrics(MetricsArgs& args) {
    args.estimate.apply(tessera::pair_correlation_option_table(), args.pcf);
    StatusPrinter status("metrics", args.quiet, std::cerr);
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
    args->estimate.add(*cmd, {method_options("metrics", tessera::pair_correlation_option_table())});
    add_input_domain_option(*cmd, args->input_domain, "EXEMPLAR");
    cmd->add_option("--output-domain", args->output_domain,
                    "Like --input-domain, for OUTPUT (useful when OUTPUT is a .csv, which stores no domain).")
        ->type_name("BOX");
    add_quiet_option(*cmd, args->quiet);
    return {cmd, [args] { run_metrics(*args); }};
}

}  // namespace tessera_cli
