// Unit tests of the pieces the `tessera` subcommands share (apps/tessera/): the decimal
// notation of integer options, the "did you mean" suggestions, and the progress lines of
// StatusPrinter (every stage shown, at most one line per interval, the latest held event
// printed once the interval has passed, slow steps announced, nothing when quiet).
#include <gtest/gtest.h>

#include <chrono>
#include <sstream>
#include <thread>

#include "apps/tessera/common.hpp"
#include "apps/tessera/status_printer.hpp"
#include "apps/tessera/suggest.hpp"

namespace tessera_cli {
namespace {

TEST(IntegerDigits, AcceptsEveryDecimalNotationOfAnInteger) {
    EXPECT_EQ(integer_digits("1000"), "1000");
    EXPECT_EQ(integer_digits("1e3"), "1000");
    EXPECT_EQ(integer_digits("1E3"), "1000");
    EXPECT_EQ(integer_digits("1000.0"), "1000");
    EXPECT_EQ(integer_digits("1000."), "1000");
    EXPECT_EQ(integer_digits("2.5e1"), "25");
    EXPECT_EQ(integer_digits("-2.5e+1"), "-25");
    EXPECT_EQ(integer_digits("+7"), "7");
    EXPECT_EQ(integer_digits("007"), "7");
    EXPECT_EQ(integer_digits("-0"), "0");
    EXPECT_EQ(integer_digits("0e999999"), "0");
    EXPECT_EQ(integer_digits(".5e1"), "5");
    EXPECT_EQ(integer_digits("12345678901234567890123"), "12345678901234567890123");  // exact, no rounding
    EXPECT_EQ(integer_digits("18446744073709551615.000"), "18446744073709551615");
}

TEST(IntegerDigits, RefusesWhatIsNotAnIntegerInDecimal) {
    for (const char* text : {"1.5", "1e-3", "0.1e1x", "", "-", ".", "e3", "1e", "1e+", "abc", "0x10", "1,000",
                             " 1", "1 ", "inf", "nan", "--1", "1.2.3"})
        EXPECT_FALSE(integer_digits(text)) << "'" << text << "'";
}

TEST(IntegerNotation, ChecksTheRangeOfTheType) {
    CLI::Validator v = integer_notation(-2147483648LL, 2147483647ULL);
    std::string text = "2147483647";
    EXPECT_EQ(v(text), "");
    text = "2.147483648e9";
    EXPECT_NE(v(text).find("out of range (-2147483648 to 2147483647)"), std::string::npos);
    text = "-2147483648";
    EXPECT_EQ(v(text), "");
    text = "-2147483649";
    EXPECT_NE(v(text).find("out of range"), std::string::npos);
    text = "1e400";
    EXPECT_NE(v(text).find("out of range"), std::string::npos);
    text = "4e1";
    EXPECT_EQ(v(text), "");
    EXPECT_EQ(text, "40");  // handed on to CLI11 as plain digits
    text = "1.5";
    EXPECT_EQ(v(text), "1.5 is not an integer");
    text = "x";
    EXPECT_EQ(v(text), "x is not a number");
}

TEST(Suggest, ClosestCommandOrOption) {
    const std::vector<std::string> commands = {"synth", "metrics", "render", "edit", "scene", "analyze"};
    EXPECT_EQ(closest_match("synthesize", commands), "synth");
    EXPECT_EQ(closest_match("sytnh", commands), "synth");  // a swap of neighbours is one edit
    EXPECT_EQ(closest_match("analyse", commands), "analyze");
    EXPECT_EQ(closest_match("scenes", commands), "scene");
    EXPECT_EQ(closest_match("eidt", commands), "edit");
    EXPECT_FALSE(closest_match("frobnicate", commands));
    EXPECT_FALSE(closest_match("x", commands));
    const std::vector<std::string> options = {"--iterations", "--seed", "--scale", "--k", "-o", "--output"};
    EXPECT_EQ(closest_match("--iteration", options), "--iterations");
    EXPECT_EQ(closest_match("--itterations", options), "--iterations");
    EXPECT_EQ(closest_match("--outptu", options), "--output");
    EXPECT_FALSE(closest_match("--colour", options));
    EXPECT_EQ(edit_distance("kitten", "sitting"), 3);
    EXPECT_EQ(edit_distance("", "abc"), 3);
    EXPECT_EQ(edit_distance("ab", "ba"), 1);
}

tessera::ProgressEvent event(const std::string& stage, int iteration, int iterations, double elapsed = 0.5) {
    return {stage, iteration, iterations, 2.5, elapsed};
}

TEST(StatusPrinter, FormatsEveryStage) {
    EXPECT_EQ(StatusPrinter::format(event("iteration", 2, 10), "iteration"),
              "iteration 3/10  energy 2.5  elapsed 0.50 s");
    EXPECT_EQ(StatusPrinter::format(event("iteration", 0, 40), "sweep"), "sweep 1/40  energy 2.5  elapsed 0.50 s");
    // Stages the CLI does not know, with their fraction done when they carry one.
    EXPECT_EQ(StatusPrinter::format(event("index", 3, 8), "iteration"), "index 4/8 (50%)  elapsed 0.50 s");
    EXPECT_EQ(StatusPrinter::format(event("analysis", 9, 8), "iteration"), "analysis 8/8 (100%)  elapsed 0.50 s");
    EXPECT_EQ(StatusPrinter::format(event("init", -1, 10), "iteration"), "init  elapsed 0.50 s");
    EXPECT_EQ(StatusPrinter::format(event("", -1, 0), "iteration"), "working  elapsed 0.50 s");
    EXPECT_EQ(StatusPrinter::format(event("round", -1, 100), "iteration"), "growing  elapsed 0.50 s");
    EXPECT_EQ(StatusPrinter::format(event("done", 10, 10), "iteration"), "");
}

int lines_in(const std::ostringstream& out) {
    const std::string text = out.str();
    return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

TEST(StatusPrinter, ShowsAtMostOneLinePerIntervalAndNeverDropsTheLatest) {
    std::ostringstream out;
    {
        StatusPrinter printer("synth", false, out, {0.2, 100.0});
        const tessera::Progress progress = printer.progress({});
        const auto start = std::chrono::steady_clock::now();
        for (int i = 0; i < 2000; ++i) progress(event("iteration", i, 2000));  // far faster than the interval
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        EXPECT_LE(lines_in(out), 2 + static_cast<int>(seconds / 0.2)) << out.str();
        // The last event, held back, is printed by the flush that comes before a summary.
        printer.flush();
    }
    EXPECT_NE(out.str().find("iteration 2000/2000"), std::string::npos) << out.str();
    EXPECT_EQ(out.str().find("iteration 2/2000"), std::string::npos) << "the second event should be held";
}

TEST(StatusPrinter, PrintsAHeldEventOnceTheIntervalHasPassedWithoutAnotherEvent) {
    std::ostringstream out;
    StatusPrinter printer("synth", false, out, {0.05, 100.0});
    const tessera::Progress progress = printer.progress({});
    progress(event("init", -1, 10));
    progress(event("index", 0, 4));  // held: it comes right after the first line
    // A stage that sends one event and then works for a while is still shown.
    for (int wait = 0; wait < 200 && out.str().find("index 1/4") == std::string::npos; ++wait)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    EXPECT_NE(out.str().find("init  elapsed"), std::string::npos) << out.str();
    EXPECT_NE(out.str().find("index 1/4 (25%)"), std::string::npos) << out.str();
}

TEST(StatusPrinter, AnnouncesSlowStepsOnly) {
    std::ostringstream out;
    StatusPrinter printer("synth", false, out, {0.25, 0.05});
    printer.step("reading quick.csv", [] {});
    EXPECT_EQ(out.str(), "");
    printer.step("reading big.csv", [&] {
        for (int wait = 0; wait < 200 && out.str().empty(); ++wait)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
    });
    EXPECT_EQ(out.str(), "synth: reading big.csv ...\n");
    EXPECT_EQ(printer.step("computing", [] { return 42; }), 42);
}

TEST(StatusPrinter, QuietPrintsNothingAndStillAnswers) {
    std::ostringstream out;
    StatusPrinter printer("synth", true, out, {0.0, 0.0});
    bool keep_going = false;
    const tessera::Progress progress = printer.progress([&] { return keep_going; });
    EXPECT_FALSE(progress(event("init", -1, 10)));
    keep_going = true;
    EXPECT_TRUE(progress(event("iteration", 0, 10)));
    printer.step("reading big.csv", [] { std::this_thread::sleep_for(std::chrono::milliseconds(20)); });
    printer.flush();
    EXPECT_EQ(out.str(), "");
}

}  // namespace
}  // namespace tessera_cli
