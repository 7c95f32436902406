// End-to-end tests of how the `tessera` tool treats what a user types wrong or writes in
// another notation: an unknown subcommand or option is named with the closest real one,
// every integer option takes an integral value in any decimal notation (1e3, 1000.0) and
// refuses other values naming the option and the value.
#include <gtest/gtest.h>

#include <sstream>
#include <set>
#include <string>
#include <vector>

#include "cli/cli_fixture.hpp"

using namespace tessera_cli_test;

namespace {

class CliUsage : public CliFixture {};

// The long option a line of CLI11's --help declares with an INT or UINT value
// ("  --iterations INT=10  ...", "  -k,--k INT"), or "". (No std::regex: GCC 12 warns
// falsely inside it in sanitizer builds.)
std::string integer_option_of(const std::string& line) {
    std::istringstream words(line);
    std::string name, type;
    if (!(words >> name >> type) || name.rfind("-", 0) != 0) return "";
    name = name.substr(name.rfind(',') == std::string::npos ? 0 : name.rfind(',') + 1);
    const bool integer = type.rfind("INT", 0) == 0 || type.rfind("UINT", 0) == 0;
    const size_t after = type.rfind("UINT", 0) == 0 ? 4 : 3;
    if (!integer || (type.size() > after && type[after] != '=' && type[after] != ':')) return "";
    return name.rfind("--", 0) == 0 ? name : "";
}

void expect_one_line_error(const Result& r, const std::string& text) {
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(text), std::string::npos) << "'" << text << "' not in: " << r.err;
    EXPECT_EQ(r.out, "");
}

TEST_F(CliUsage, UnknownCommandSuggestsTheClosest) {
    expect_one_line_error(run("synthesize in.json -o out.json"),
                          "unknown command 'synthesize'; did you mean 'synth'?");
    expect_one_line_error(run("rendr in.json -o out.png"), "unknown command 'rendr'; did you mean 'render'?");
    expect_one_line_error(run("analyse in.json"), "did you mean 'analyze'?");
    expect_one_line_error(run("metric a.json b.json"), "did you mean 'metrics'?");
}

TEST_F(CliUsage, UnknownCommandFarFromAllHasNoSuggestion) {
    const Result r = run("frobnicate in.json");
    expect_one_line_error(r, "unknown command 'frobnicate'");
    EXPECT_EQ(r.err.find("did you mean"), std::string::npos) << r.err;
}

TEST_F(CliUsage, MissingCommandListsThem) {
    expect_one_line_error(run(""), "a command is required: synth, metrics, render, edit, scene, analyze, recombine, animate, grow, world, brush or studio");
}

TEST_F(CliUsage, UnknownOptionSuggestsTheClosest) {
    const std::string synth = "synth " + q(example("poisson_disk_2d.json")) + " -o " + q(path("o.json")) + " ";
    expect_one_line_error(run(synth + "--iteration 2"),
                          "unknown option '--iteration' for 'synth'; did you mean '--iterations'?");
    expect_one_line_error(run(synth + "--iteraitons=2"), "did you mean '--iterations'?");
    expect_one_line_error(run(synth + "--sead 3"), "did you mean '--seed'?");
    expect_one_line_error(run("render " + q(example("poisson_disk_2d.json")) + " -o " + q(path("p.png")) +
                              " --no-legnd"),
                          "did you mean '--no-legend'?");
    // The unknown option is named even when a required one is missing too.
    expect_one_line_error(run("synth " + q(example("poisson_disk_2d.json")) + " --iteration 2"),
                          "did you mean '--iterations'?");
    const Result far = run(synth + "--colour red");
    expect_one_line_error(far, "unknown option '--colour'");
    EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
    EXPECT_TRUE(work_files().empty());
}

TEST_F(CliUsage, IntegerOptionsTakeAnyDecimalNotationOfAnInteger) {
    // The same run written three ways gives byte-identical output.
    const std::string synth = "synth " + q(example("poisson_disk_2d.json")) + " --scale 1.5 -q ";
    std::string first;
    for (const char* notation : {"--iterations 2 --seed 7", "--iterations 2e0 --seed 7.0",
                                        "--iterations 2.000 --seed 0.7e1"}) {
        SCOPED_TRACE(notation);
        const Result r = run(synth + notation + " -o " + q(path("out.json")));
        ASSERT_EQ(r.code, 0) << r.err;
        const std::string text = read_text(path("out.json"));
        if (first.empty()) first = text;
        EXPECT_EQ(text, first);
    }
}

TEST_F(CliUsage, NonIntegralOrOutOfRangeIntegersNameOptionAndValue) {
    const std::string synth = "synth " + q(example("poisson_disk_2d.json")) + " -o " + q(path("o.json")) + " ";
    expect_one_line_error(run(synth + "--iterations 1.5"), "--iterations: 1.5 is not an integer");
    expect_one_line_error(run(synth + "--iterations 1e-3"), "--iterations: 1e-3 is not an integer");
    expect_one_line_error(run(synth + "--iterations 1e10"), "--iterations: 1e10 is out of range");
    expect_one_line_error(run(synth + "--iterations ten"), "--iterations: ten is not a number");
    expect_one_line_error(run(synth + "--seed -1"), "--seed: -1 is out of range (0 to 18446744073709551615)");
    expect_one_line_error(run(synth + "--seed 1e20"), "--seed: 1e20 is out of range");
    expect_one_line_error(run("render " + q(example("poisson_disk_2d.json")) + " -o " + q(path("p.png")) +
                              " --width 400.5"),
                          "--width: 400.5 is not an integer");
    EXPECT_TRUE(work_files().empty());
}

// Every option whose --help shows an INT or UINT value goes through the shared integer
// parsing: each refuses 2.5 with its message (before any work, so no operands are needed).
TEST_F(CliUsage, EveryIntegerOptionOfEverySubcommandSharesTheParsing) {
    int checked = 0;
    for (const std::string command : {"synth", "metrics", "render", "edit", "scene", "analyze"}) {
        const Result help = run(command + " --help");
        ASSERT_EQ(help.code, 0) << help.err;
        std::istringstream lines(help.out);
        for (std::string line; std::getline(lines, line);) {
            const std::string option = integer_option_of(line);
            if (option.empty()) continue;
            SCOPED_TRACE(command + " " + option);
            expect_one_line_error(run(command + " " + option + " 2.5"), option + ": 2.5 is not an integer");
            ++checked;
        }
    }
    EXPECT_GE(checked, 15);  // synth alone has 10
}

}  // namespace
