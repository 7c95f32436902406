// Every option of the library's tables (tessera/option_table.hpp) as the CLI shows it: a
// flag in `tessera synth --help` / `tessera grow --help` with the table's default, a row in
// docs/cli.md's section of the command, and a value outside its check refused naming the flag.
#include <gtest/gtest.h>

#include <cmath>

#include "cli_fixture.hpp"
#include "tessera/det.hpp"
#include "tessera/dynamic.hpp"
#include "tessera/graph_motion.hpp"
#include "tessera/grow.hpp"
#include "tessera/motion_analysis.hpp"
#include "tessera/option_table.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera_cli_test {
namespace {

class CliOptions : public CliFixture {
protected:
    // The command's section of docs/cli.md.
    static std::string docs_section(const std::string& command) {
        const std::string docs = read_text(std::string(TESSERA_SOURCE_DIR) + "/docs/cli.md");
        const size_t start = docs.find("## `tessera " + command + "`");
        EXPECT_NE(start, std::string::npos) << command;
        const size_t end = docs.find("\n## ", start + 1);
        return docs.substr(start, end == std::string::npos ? std::string::npos : end - start);
    }

    // A value the option's check refuses, or "" when its kind accepts every value.
    static std::string refused_value(const tessera::OptionInfo& info) {
        if (info.kind == tessera::OptionKind::choice) return "nonsense";
        if (info.kind != tessera::OptionKind::integer && info.kind != tessera::OptionKind::number) return "";
        if (std::isfinite(info.lo)) return tessera::format_option_value(info.lo - 1.0);
        if (std::isfinite(info.hi)) return tessera::format_option_value(info.hi + 1.0);
        return "";
    }

    template <class Options>
    void walk(const tessera::OptionTable<Options>& table, const std::string& command, const std::string& target) {
        const Result help = run(command + " --help");
        ASSERT_EQ(help.code, 0);
        const std::string docs = docs_section(command);
        const Options defaults{};
        for (const auto& spec : table) {
            SCOPED_TRACE(spec.name);
            const std::string flag = tessera::cli_flag(spec);
            const size_t line = help.out.find("  " + flag + " ");
            ASSERT_NE(line == std::string::npos ? help.out.find("  " + flag + "\n") : line, std::string::npos);
            const std::string shown = tessera::format_option_value(spec.get(defaults));
            const bool has_default = spec.kind != tessera::OptionKind::flag && !shown.empty() && spec.name != "iterations";
            if (has_default) {
                EXPECT_NE(help.out.find("=" + shown, line), std::string::npos) << help.out.substr(line, 80);
            }
            EXPECT_NE(docs.find("| `" + flag), std::string::npos) << "docs/cli.md has no row for " << flag;
            const std::string bad = refused_value(spec);
            if (bad.empty()) continue;
            const Result r = run(command + " '" + example("two_class_2d.json") + "' -o '" + path("out.json") + "' " +
                                 target + " " + flag + " " + bad);
            EXPECT_EQ(r.code, 2) << r.err;
            EXPECT_EQ(r.err.rfind("tessera: error: " + flag + " must be " + tessera::describe_accepted(spec), 0), 0u)
                << r.err;
            EXPECT_TRUE(work_files().empty());
        }
    }
};

TEST_F(CliOptions, EveryDetOptionIsAFlagWithItsDefaultDocsAndCheck) {
    walk(tessera::det_option_table(), "synth", "--method det");
}

TEST_F(CliOptions, EveryPcfOptionIsAFlagWithItsDefaultDocsAndCheck) {
    walk(tessera::pcf_option_table(), "synth", "--method pcf");
}

TEST_F(CliOptions, EveryDynamicOptionIsAFlagWithItsDefaultDocsAndCheck) {
    walk(tessera::dynamic_option_table(), "synth", "--method dynamic");
}

TEST_F(CliOptions, EveryLowPassOptionIsAFlagWithItsDefaultDocsAndCheck) {
    walk(tessera::low_pass_option_table(), "analyze", "--decompose");
}

TEST_F(CliOptions, EveryGraphMotionOptionIsAFlagWithItsDefaultDocsAndCheck) {
    walk(tessera::graph_motion_option_table(), "animate", "");
}

TEST_F(CliOptions, EveryGrowOptionIsAFlagWithItsDefaultDocsAndCheck) {
    walk(tessera::grow_option_table(), "grow", "--region box:20,20");
}

TEST_F(CliOptions, AFlagOfTheOtherMethodIsRefused) {
    const Result r = run("synth '" + example("two_class_2d.json") + "' -o '" + path("out.json") + "' --max-fails 3");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--max-fails applies to --method pcf only"), std::string::npos) << r.err;
    const Result d = run("synth '" + example("two_class_2d.json") + "' -o '" + path("out.json") + "' --matches 3");
    EXPECT_EQ(d.code, 2);
    EXPECT_NE(d.err.find("--matches applies to --method dynamic only"), std::string::npos) << d.err;
}

}  // namespace
}  // namespace tessera_cli_test
