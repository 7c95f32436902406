// apps/tessera/cmd_analyze.cpp — `tessera analyze INPUT`: the analysis stage of the PCF
// method (tessera::analyze_distribution, docs/pcf.md). Writes the model (-o model.json,
// else stdout) and draws its PCFs (--plot FILE.svg|FILE.png). With --standard-pcf it
// instead writes the standard pair correlation estimate (tessera::pair_correlation,
// spatstat's convention in physical units) of every class pair as CSV. With --decompose it
// splits an animation into its coarse motion and details instead (analyze_decompose.hpp).
#include <charconv>
#include <cmath>
#include <iostream>
#include <memory>

#include "analyze_decompose.hpp"
#include "common.hpp"
#include "option_flags.hpp"
#include "status_printer.hpp"
#include "tessera/metrics.hpp"
#include "tessera/pcf_plot.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera_cli {
namespace {

struct AnalyzeArgs {
    std::string input, model, plot, csv, input_domain, compare;
    bool quiet = false, standard = false, decompose = false;
    OptionFlags flags;  // PcfAnalysisSettings as flags, from the table (tessera/option_table.hpp)
    tessera::PcfAnalysisSettings settings;
    OptionFlags estimate;  // PcfOptions as flags (--standard-pcf's), from pair_correlation_option_table
    tessera::PcfOptions pcf;
    OptionFlags low_pass;  // LowPassOptions as flags (--decompose's), from low_pass_option_table
    tessera::LowPassOptions motion;
    std::string detail;
    // Options that belong to one mode only, to reject them in the other (the two tables'
    // own by flags.given and estimate.given).
    CLI::Option *model_opt = nullptr, *plot_opt = nullptr, *csv_opt = nullptr, *compare_opt = nullptr,
                *detail_opt = nullptr, *standard_opt = nullptr;
};

// The PCF modes refuse the flags of --decompose.
void reject_decompose_flags(const AnalyzeArgs& args) {
    if (args.detail_opt->count() > 0) fail_option("--detail needs --decompose");
    for (const auto& row : tessera::low_pass_option_table())
        if (args.low_pass.given(row.name)) fail_option(tessera::cli_flag(row) + " needs --decompose");
}

// --decompose refuses the flags of the PCF modes.
void reject_pcf_flags(const AnalyzeArgs& args) {
    const std::string why = " cannot be used with --decompose (which splits an animation's motion)";
    for (const CLI::Option* o : {args.standard_opt, args.plot_opt, args.csv_opt, args.compare_opt})
        if (o->count() > 0) fail_option(o->get_name() + why);
    for (const auto& row : tessera::pcf_analysis_option_table())
        if (args.flags.given(row.name)) fail_option(tessera::cli_flag(row) + why);
    for (const auto& row : tessera::pair_correlation_option_table())
        if (args.estimate.given(row.name)) fail_option(tessera::cli_flag(row) + why);
}

void run_motion(AnalyzeArgs& args) {
    reject_pcf_flags(args);
    args.low_pass.apply(tessera::low_pass_option_table(), args.motion);
    if (args.model.empty() || args.detail.empty())
        fail_option("--decompose needs -o COARSE and --detail DETAIL (the two animations it writes)");
    run_decompose({args.input, args.input_domain, args.model, args.detail, args.motion, args.quiet});
}

// A number as the shortest text that reads back exactly; "Inf" like R for g(0).
std::string csv_number(double v) {
    if (std::isinf(v)) return v > 0 ? "Inf" : "-Inf";
    if (std::isnan(v)) return "NaN";
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, result.ptr);
}

// A CSV field, quoted when it holds a comma, quote or line break (RFC 4180).
std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string out = "\"";
    for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

// Whether a CSV input names classes: its header has a "class" column (any case).
bool csv_has_class_column(const std::string& path) {
    const std::string text = tessera::read_file(path);
    const std::string header = text.substr(0, text.find('\n'));
    size_t start = 0;
    while (start <= header.size()) {
        size_t end = header.find(',', start);
        if (end == std::string::npos) end = header.size();
        std::string name = header.substr(start, end - start);
        std::string lower;
        for (char c : name)
            if (c != ' ' && c != '\t' && c != '\r' && c != '"')
                lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (lower == "class") return true;
        start = end + 1;
    }
    return false;
}

void run_standard(AnalyzeArgs& args) {
    reject_decompose_flags(args);
    for (const CLI::Option* o : {args.model_opt, args.plot_opt})
        if (o->count() > 0)
            fail_option(o->get_name() + " cannot be used with --standard-pcf (which writes --csv)");
    for (const auto& row : tessera::pcf_analysis_option_table())
        if (args.flags.given(row.name))
            fail_option(tessera::cli_flag(row) + " cannot be used with --standard-pcf (which writes --csv)");
    args.estimate.apply(tessera::pair_correlation_option_table(), args.pcf);
    if (args.csv.empty()) fail_option("--standard-pcf needs --csv OUT.csv");
    check_output_path(args.csv, "--csv", {".csv"});

    StatusPrinter status("analyze", args.quiet, std::cerr);
    const tessera::Exemplar data =
        status.step("reading " + args.input, [&] { return load_input(args.input, args.input_domain); });
    const tessera::PcfResult g =
        status.step("measuring the pair correlation of " + std::to_string(data.elements.size()) + " elements",
                    [&] { return tessera::pair_correlation(data, args.pcf); });
    // Without a class column the single class has no name to report.
    const bool named = extension_of(args.input) != ".csv" || csv_has_class_column(args.input);
    std::string out = "r,class_a,class_b,g\n";
    for (const tessera::PcfCurve& c : g.curves) {
        const std::string a = named ? csv_field(c.name_a) : "", b = named ? csv_field(c.name_b) : "";
        for (size_t k = 0; k < g.r.size(); ++k)
            out += csv_number(g.r[k]) + "," + a + "," + b + "," + csv_number(c.g[k]) + "\n";
    }
    tessera::write_file_atomic(args.csv, out);
    if (!args.quiet)
        std::cerr << "analyze: pair correlation of " << g.curves.size() << " class pair(s), " << g.r.size()
                  << " values of r up to " << format_number(g.r.back()) << ", bandwidth "
                  << format_number(g.bandwidth) << "\nwrote " << args.csv << std::endl;
}

void run_model(AnalyzeArgs& args) {
    reject_decompose_flags(args);
    if (args.csv_opt->count() > 0) fail_option("--csv needs --standard-pcf");
    for (const auto& row : tessera::pair_correlation_option_table())
        if (args.estimate.given(row.name)) fail_option(tessera::cli_flag(row) + " needs --standard-pcf");
    args.flags.apply(tessera::pcf_analysis_option_table(), args.settings);
    if (!args.model.empty()) check_output_path(args.model, "-o", {".json"});
    if (!args.plot.empty()) check_output_path(args.plot, "--plot", {".svg", ".png"});

    StatusPrinter status("analyze", args.quiet, std::cerr);
    const tessera::Exemplar exemplar =
        status.step("reading " + args.input, [&] { return load_input(args.input, args.input_domain); });
    const tessera::PcfModel model =
        status.step("analysing " + std::to_string(exemplar.elements.size()) + " elements",
                    [&] { return tessera::analyze_distribution(exemplar, args.settings); });
    // Everything is made before anything is written: a failure leaves no file behind.
    const std::string json = tessera::pcf_model_to_json(model);
    std::string picture;
    tessera::PcfPlotOptions plot;
    if (!args.compare.empty()) {
        if (args.plot.empty()) fail_option("--compare needs --plot");
        plot.measured = status.step("measuring " + args.compare, [&] {
            return tessera::measure_distribution(model, load_input(args.compare, ""));
        });
    }
    if (!args.plot.empty())
        picture = extension_of(args.plot) == ".png" ? tessera::pcf_plot_png(model, plot)
                                                    : tessera::pcf_plot_svg(model, plot);

    if (!args.quiet) {
        std::string classes;
        for (size_t c = 0; c < model.classes.size(); ++c)
            classes += (c ? ", " : "") + model.classes[c] + " " + std::to_string(model.counts[c]);
        std::cerr << "analyze: " << model.classes.size() << " class(es) (" << classes << "), "
                  << model.pcfs.size() << " PCF(s), " << (model.disks ? "disks" : "points") << ", r_max "
                  << format_number(model.r_max) << ", x from 0 to " << format_number(model.x.back())
                  << std::endl;
    }
    if (!args.model.empty()) {
        tessera::write_file_atomic(args.model, json);
        if (!args.quiet) std::cerr << "wrote " << args.model << std::endl;
    } else if (args.plot.empty()) {
        std::cout << json << std::flush;
    }
    if (!args.plot.empty()) {
        tessera::write_file_atomic(args.plot, picture);
        if (!args.quiet) std::cerr << "wrote " << args.plot << std::endl;
    }
}

}  // namespace

Subcommand add_analyze_command(CLI::App& app) {
    auto args = std::make_shared<AnalyzeArgs>();
    CLI::App* cmd = app.add_subcommand(
        "analyze",
        "Analyse INPUT for the PCF method (Ecormier-Nocca et al. 2019): one pair correlation function per "
        "class and per dependency (types' depends_on), with envelopes of the individual PCFs. Writes the "
        "model as JSON (-o, else stdout) and draws it (--plot). With --standard-pcf, writes the standard "
        "pair correlation g(r) of every class pair as CSV instead (docs/pcf.md). With --decompose, splits an "
        "animation into its coarse motion (-o) and details (--detail) instead (Dynamic Element Textures, "
        "section 5; docs/dynamic.md).");
    cmd->add_option("INPUT", args->input,
                    "The exemplar (.json or .csv), 2D, one point per element; with --decompose, an animation "
                    "(.json or .csv with frames).")
        ->required()
        ->type_name("FILE");
    args->model_opt = add_output_option(*cmd, args->model,
                                        "Write the model to this .json file (default: stdout, "
                                        "unless --plot is given). With --decompose: the coarse animation "
                                        "(.json, .csv or .usda).",
                                        false);
    args->plot_opt =
        cmd->add_option("--plot", args->plot,
                        "Draw every PCF (mean line over the shaded envelope) to this .svg or .png.")
            ->type_name("FILE");
    args->compare_opt =
        cmd->add_option(
               "--compare", args->compare,
               "With --plot: also draw the mean PCFs of this arrangement (e.g. a `synth --method pcf` "
               "output), measured on the model's axis, over the model's.")
            ->type_name("FILE");
    args->flags.add(*cmd, {method_options("analyze", tessera::pcf_analysis_option_table())});
    args->standard_opt = cmd->add_flag(
        "--standard-pcf", args->standard,
        "Write the standard estimate g(r) (spatstat's pcf: Gaussian kernel, translation edge "
        "correction, physical units) of every class pair to --csv instead of a model, on the r grid "
        "of --r-max, --bandwidth and --bins.");
    args->csv_opt =
        cmd->add_option("--csv", args->csv, "With --standard-pcf: the .csv to write (r,class_a,class_b,g).")
            ->type_name("FILE");
    // With --standard-pcf: --r-max, --bandwidth, --bins.
    args->estimate.add(*cmd, {method_options("standard-pcf", tessera::pair_correlation_option_table())});
    cmd->add_flag(
        "--decompose", args->decompose,
        "Split the animation INPUT into its coarse motion, a low-pass filter of its samples' positions in "
        "space and time, written to -o, and its details (the offsets input - coarse) written to "
        "--detail (Dynamic Element Textures, section 5); `tessera recombine` adds them back.");
    args->detail_opt =
        cmd->add_option("--detail", args->detail,
                        "With --decompose: the details' animation to write (.json, .csv or .usda).")
            ->type_name("FILE");
    // With --decompose: --spatial-radius, --topology-radius, --temporal-radius, --threads.
    args->low_pass.add(*cmd, {method_options("decompose", tessera::low_pass_option_table())});
    add_input_domain_option(*cmd, args->input_domain, "INPUT");
    add_quiet_option(*cmd, args->quiet);
    return {cmd, [args] {
                if (args->decompose)
                    run_motion(*args);
                else if (args->standard)
                    run_standard(*args);
                else
                    run_model(*args);
            }};
}

}  // namespace tessera_cli
