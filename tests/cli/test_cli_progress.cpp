// End-to-end tests of the progress lines of `tessera synth` (apps/tessera/status_printer):
// the set-up stage and the iterations are shown, the last iteration always, at most a few
// lines per second, and nothing with --quiet.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "cli/cli_fixture.hpp"

using namespace tessera_cli_test;

namespace {

class CliProgress : public CliFixture {};

int count_of(const std::string& text, const std::string& what) {
    int n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

TEST_F(CliProgress, ShowsSetUpStagesAndTheLastIterationAtAFewLinesPerSecond) {
    const auto start = std::chrono::steady_clock::now();
    const Result r = run("synth " + q(example("poisson_disk_2d.json")) + " -o " + q(path("out.json")) +
                         " --iterations 60 --scale 1.5");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("\ninit  elapsed "), std::string::npos) << r.err;  // the set-up stage
    EXPECT_NE(r.err.find("\niteration 60/60  energy "), std::string::npos) << r.err;
    EXPECT_LT(r.err.find("iteration 60/60"), r.err.find("done: ")) << r.err;
    // At most 4 progress lines per second (plus the first and the flushed last one).
    const int progress_lines = count_of(r.err, "elapsed ");
    EXPECT_LE(progress_lines, 3 + static_cast<int>(4.0 * seconds)) << r.err;
    EXPECT_GE(progress_lines, 2);
}

TEST_F(CliProgress, PcfSweepsAndQuiet) {
    const Result pcf = run("synth " + q(example("two_class_2d.json")) + " -o " + q(path("out.json")) +
                           " --method pcf --iterations 5");
    ASSERT_EQ(pcf.code, 0) << pcf.err;
    EXPECT_NE(pcf.err.find("\nanalysis  elapsed "), std::string::npos) << pcf.err;  // the first stage
    EXPECT_NE(pcf.err.find("sweep "), std::string::npos) << pcf.err;
    const Result quiet = run("synth " + q(example("two_class_2d.json")) + " -o " + q(path("q.json")) +
                             " --method pcf --iterations 5 -q");
    ASSERT_EQ(quiet.code, 0);
    EXPECT_EQ(quiet.err, "");
}

}  // namespace
