// apps/tessera/main.cpp — entry point of the `tessera` command-line tool: sets up
// the subcommands (synth, metrics, render, edit, scene, analyze, recombine, grow, world, brush,
// studio; one file each), parses with CLI11, runs the chosen one, and turns every failure into
// one line on stderr and an exit code (docs/cli.md). The CLI only parses, calls the library and prints.
#include <exception>
#include <iostream>
#include <new>

#include "common.hpp"
#include "suggest.hpp"

namespace {

using namespace tessera_cli;

// Every spelling of every option of `app` ("--iterations", "-o"), in declaration order.
std::vector<std::string> option_names(const CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::Option* option : app.get_options()) {
        for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
        for (const std::string& name : option->get_snames()) names.push_back("-" + name);
    }
    return names;
}

std::string did_you_mean(const std::string& typed, const std::vector<std::string>& candidates) {
    const auto match = closest_match(typed, candidates);
    return match ? "; did you mean '" + *match + "'?" : "";
}

// What CLI11 left unmatched on the command line of `app` that looks like an option
// ("--iteraions", "--seed=3" as "--seed"), or "" when there is none.
std::string unknown_option(const CLI::App& app) {
    for (const std::string& arg : app.remaining()) {
        if (arg.size() < 2 || arg[0] != '-' || arg == "--") continue;
        if (arg[1] >= '0' && arg[1] <= '9') continue;  // a negative number, not an option
        return arg.substr(0, arg.find('='));
    }
    return "";
}

// A usage error as one line, pointing at the right --help. An unknown subcommand or
// option is named with the closest real one when one is close ("did you mean"); an
// unknown option is reported before what else is wrong, since it usually explains it.
int report_parse_error(const CLI::App& app, const CLI::ParseError& e) {
    const std::vector<CLI::App*> parsed = app.get_subcommands();
    if (parsed.empty()) {
        std::vector<std::string> commands;
        for (const CLI::App* sub : app.get_subcommands({})) commands.push_back(sub->get_name());
        for (const std::string& arg : app.remaining()) {
            if (arg.empty() || arg[0] == '-') continue;
            print_error("unknown command '" + arg + "'" + did_you_mean(arg, commands) + " (see 'tessera --help')");
            return exit_option;
        }
        if (const std::string option = unknown_option(app); !option.empty()) {
            print_error("unknown option '" + option + "'" + did_you_mean(option, option_names(app)) +
                        " (see 'tessera --help')");
            return exit_option;
        }
        std::string list;
        for (size_t k = 0; k < commands.size(); ++k)
            list += (k == 0 ? "" : k + 1 == commands.size() ? " or " : ", ") + commands[k];
        print_error("a command is required: " + list + " (see 'tessera --help')");
        return exit_option;
    }
    const CLI::App& sub = *parsed.back();
    const std::string help = "tessera " + sub.get_name() + " --help";
    if (const std::string option = unknown_option(sub); !option.empty()) {
        print_error("unknown option '" + option + "' for '" + sub.get_name() + "'" +
                    did_you_mean(option, option_names(sub)) + " (see '" + help + "')");
        return exit_option;
    }
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
                                    add_edit_command(app), add_scene_command(app), add_analyze_command(app),
                                    add_recombine_command(app), add_animate_command(app), add_grow_command(app),
                                    add_world_command(app), add_brush_command(app), add_studio_command(app)};

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
