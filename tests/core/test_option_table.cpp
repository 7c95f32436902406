// The option tables (tessera/option_table.hpp): the checks every front end goes through,
// the text forms the CLI reads and shows, and the library entry points refusing a bad
// struct by the option's name. The walk over every option against the CLI's --help,
// docs/cli.md and Python's keywords is python/tests/test_option_table.py, and
// tests/cli/test_cli_options.cpp for the CLI alone.
#include <gtest/gtest.h>

#include "tessera/det.hpp"
#include "tessera/edit.hpp"
#include "tessera/error.hpp"
#include "tessera/grow.hpp"
#include "tessera/metrics.hpp"
#include "tessera/motion_analysis.hpp"
#include "tessera/dynamic.hpp"
#include "tessera/option_table.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace tessera {
namespace {

std::string message_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::option) << e.what();
        return e.what();
    }
    ADD_FAILURE() << "accepted";
    return "";
}

template <class Options>
void expect_unique_snake_case_names(const OptionTable<Options>& table) {
    for (size_t i = 0; i < table.size(); ++i) {
        EXPECT_EQ(table[i].name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_"), std::string::npos)
            << table[i].name;
        EXPECT_FALSE(table[i].doc.empty()) << table[i].name;
        for (size_t j = i + 1; j < table.size(); ++j) EXPECT_NE(table[i].name, table[j].name);
    }
}

TEST(OptionTable, NamesAreUniqueSnakeCaseAndSpelledPerFrontEnd) {
    expect_unique_snake_case_names(det_option_table());
    expect_unique_snake_case_names(pcf_option_table());
    expect_unique_snake_case_names(grow_option_table());
    expect_unique_snake_case_names(edit_option_table());
    expect_unique_snake_case_names(pcf_analysis_option_table());
    expect_unique_snake_case_names(pair_correlation_option_table());
    expect_unique_snake_case_names(dynamic_option_table());
    expect_unique_snake_case_names(low_pass_option_table());
    EXPECT_EQ(cli_flag(*find_option(pair_correlation_option_table(), "r_max")), "--r-max");
    const auto& det = det_option_table();
    EXPECT_EQ(cli_flag(*find_option(det, "patch_size")), "--patch-size");
    EXPECT_EQ(python_keyword(*find_option(det, "patch_size")), "patch_size");
    EXPECT_EQ(python_keyword(*find_option(det, "lambda")), "lambda_");
    EXPECT_EQ(find_option(det, "no_such_option"), nullptr);
}

TEST(OptionTable, ValuesAreCheckedAgainstTheirRowNamingTheOptionAsWritten) {
    const auto& grow = grow_option_table();
    const OptionSpec<GrowOptions>& threshold = *find_option(grow, "threshold");
    EXPECT_EQ(describe_accepted(threshold), "a number > 0 and <= 1");
    EXPECT_EQ(message_of([&] { check_option_value(threshold, 0.0, "--threshold"); }),
              "--threshold must be a number > 0 and <= 1, got 0");
    EXPECT_EQ(std::get<double>(check_option_value(threshold, std::int64_t{1}, "threshold")), 1.0);  // an integer is a number
    const OptionSpec<GrowOptions>& solves = *find_option(grow, "solves");
    EXPECT_EQ(message_of([&] { check_option_value(solves, 2.5, "solves"); }),
              "solves must be an integer from 0 to 100, got 2.5");
    EXPECT_EQ(message_of([&] { check_option_value(solves, std::int64_t{5000000000}, "solves"); }),
              "solves must be an integer from 0 to 100, got 5000000000");
    const OptionSpec<GrowOptions>& choice = *find_option(grow, "choice");
    EXPECT_EQ(message_of([&] { check_option_value(choice, std::string("tree"), "--choice"); }),
              "--choice must be patch or mcts, got 'tree'");
    const OptionSpec<GrowOptions>& seed = *find_option(grow, "seed");
    EXPECT_NE(message_of([&] { check_option_value(seed, std::int64_t{-1}, "seed"); }).find("unsigned 64-bit"),
              std::string::npos);
}

TEST(OptionTable, CommandLineTextIsReadByKind) {
    const auto& det = det_option_table();
    const auto& k = *find_option(det, "k");
    EXPECT_EQ(std::get<std::int64_t>(parse_option_text(k, "+7", "--k")), 7);
    EXPECT_EQ(message_of([&] { parse_option_text(k, "seven", "--k"); }), "--k must be an integer >= 1, got 'seven'");
    const auto& radius = *find_option(det, "radius");
    EXPECT_EQ(std::get<double>(parse_option_text(radius, "1.5e0", "--radius")), 1.5);
    EXPECT_EQ(message_of([&] { parse_option_text(radius, "nan", "--radius"); }),
              "--radius must be a number >= 0, got nan");
    EXPECT_EQ(message_of([&] { parse_option_text(radius, "2x", "--radius"); }), "--radius must be a number >= 0, got '2x'");
    const auto& seed = *find_option(det, "seed");
    EXPECT_EQ(std::get<std::uint64_t>(parse_option_text(seed, "18446744073709551615", "--seed")),
              18446744073709551615ULL);
}

TEST(OptionTable, DefaultsAreShownInTheShortestFormThatReadsBack) {
    EXPECT_EQ(format_option_value(0.001), "0.001");
    EXPECT_EQ(format_option_value(-1.0), "-1");
    EXPECT_EQ(format_option_value(1000.0), "1000");
    EXPECT_EQ(format_option_value(0.1), "0.1");
    EXPECT_EQ(format_option_value(1.0 / 3.0), "0.3333333333333333");
    EXPECT_EQ(format_option_value(true), "true");
    EXPECT_EQ(format_option_value(std::int64_t{-4}), "-4");
}

TEST(OptionTable, SettersStoreCheckedValuesAndParseTextForms) {
    DetOptions o;
    const auto& det = det_option_table();
    set_option(*find_option(det, "search"), o, std::string("exhaustive"), {"search", 2});
    EXPECT_EQ(o.search, SearchMode::exhaustive);
    set_option(*find_option(det, "boundary"), o, std::string("-x,+y"), {"boundary", 2});
    ASSERT_EQ(o.boundary_sides.size(), 2u);
    EXPECT_EQ(o.boundary_sides[1].axis, 1);
    set_option(*find_option(det, "gravity"), o, std::string("0,0,-1"), {"gravity", 3});
    EXPECT_EQ(o.gravity, (Vec3{0, 0, -1}));
    set_option(*find_option(det, "field"), o, std::string("vortex:5,5"), {"field", 2});
    EXPECT_TRUE(o.field.active());
    EXPECT_NE(message_of([&] { set_option(*find_option(det, "gravity"), o, std::string("down"), {"--gravity", 2}); })
                  .find("--gravity"),
              std::string::npos);
    // Every row reads back the default it was given.
    const DetOptions defaults;
    for (const auto& spec : det) {
        DetOptions copy;
        spec.set(copy, spec.get(defaults), {spec.name, 2});
        EXPECT_EQ(format_option_value(spec.get(copy)), format_option_value(spec.get(defaults))) << spec.name;
    }
}

TEST(OptionTable, LibraryEntryPointsNameTheBadField) {
    GrowOptions g;
    g.energy_factor = 0.5;
    Exemplar ex;
    ex.dimension = 2;
    ex.domain = Domain::box({0, 0, 0}, {4, 4, 0}, 2);
    for (int i = 0; i < 9; ++i) ex.add_element(0, {Vec3{0.5 + i % 3, 0.5 + i / 3, 0}});
    ex.types.resize(1);
    ex.types[0].name = "dot";
    EXPECT_EQ(message_of([&] { Grower(ex, g); }), "energy_factor must be a number > 1, got 0.5");
    DetOptions d;
    d.patch_candidates = 0;
    EXPECT_EQ(message_of([&] { synthesize_det(ex, ex.domain, d); }), "patch_candidates must be an integer >= 1, got 0");
    EditOptions e;
    e.radius = -1.0;
    ElementEdit edit;
    edit.element = ex.elements[4].id;
    EXPECT_EQ(message_of([&] { edit_elements(ex, edit, e); }), "radius must be a number >= 0, got -1");
    PcfOptions p;
    p.bins = 1;  // 0 (automatic) or at least 2
    EXPECT_EQ(message_of([&] { pair_correlation(ex, p); }),
              "bins must be an integer from 2 to 1000000, or 0 (automatic), got 1");
    p.bins = 0;
    EXPECT_EQ(pair_correlation(ex, p).r.size(), 101u);
}

}  // namespace
}  // namespace tessera
