// apps/tessera/main.cpp — entry point of the `tessera` command-line tool: sets up
// the subcommands (synth, metrics, render, edit, scene, analyze; one file each), parses with CLI11,
// runs the chosen one, and turns every failure into one line on stderr and an
// exit code (docs/cli.md). The CLI only parses, calls the library and prints.
#include <exception>
#include <iostream>
#include <new>

#include "common.hpp"

namespace {

using namespace tessera_cli;

// The usage error of CLI11 as one line, pointing at the right --help.
int report_parse_error(const CLI::App& app, const CLI::ParseError& e) {
    std::string help = "tessera --help";
    for (const CLI::App* sub : app.get_subcommands()) help = "tessera " + sub->get_name() + " --help";
    print_error(std::string(e.what()) + " (see '" + help + "')");
    return exit_option;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"tessera " + std::string(tessera::version) +
                     " — synthesizes arrangements of discrete elements (points, disks, sticks, "
                     "rods, spheres...) that look like a small exemplar, in a domain of any size "
                     "(Discrete Element Textures, Ma, Wei and Tong 2011). See docs/cli.md.",
                 "tessera"};
    app.set_version_flag("--version", "tessera " + std::string(tessera::version),
                         "Print the version and exit.");
    app.require_subcommand(1);
    app.footer(
        "Run 'tessera SUBCOMMAND --help' for the options of a subcommand.\n"
        "Exit codes: 0 ok, 2 bad option, 3 invalid input, 4 invalid domain, 5 file error, "
        "70 internal error, 130 interrupted.");

    const Subcommand commands[] = {add_synth_command(app), add_metrics_command(app), add_render_command(app),
                                    add_edit_command(app), add_scene_command(app), add_analyze_command(app)};

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success))
            return app.exit(e);  // --help, --version
        return report_parse_error(app, e);
    }

    try {
        for (const Subcommand& command : commands)
            if (command.app->parsed()) command.run();
        return exit_ok;
    } catch (const tessera::Error& e) {
        print_error(e.what());
        return exit_code(e.kind());
    } catch (const std::bad_alloc&) {
        print_error("out of memory");
        return exit_internal;
    } catch (const std::exception& e) {
        print_error(std::string("internal error: ") + e.what());
        return exit_internal;
    }
}
