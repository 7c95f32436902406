// End-to-end tests of the `tessera` command-line tool (apps/tessera/): each test runs
// the built binary (TESSERA_CLI) on the examples in a fresh temporary directory and
// checks exit codes, stdout/stderr, and the files written — or, for every error
// case, that nothing was written and stderr holds one line naming the file or flag.
// Runs use --iterations 2 (or fewer) and small scales so the suite takes seconds.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/wait.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <ostream>
#include <string>
#include <vector>

#include <stb_image_write.h>

#include "cli/cli_fixture.hpp"
#include "geometry/gltf_test_util.hpp"
#include "tessera/tessera.hpp"

namespace fs = std::filesystem;
using namespace tessera_cli_test;

namespace {

// ---- synth -------------------------------------------------------------------

class CliSynth : public CliFixture {};

TEST_F(CliSynth, WritesJsonCsvPlyAndPreview) {
    const tessera::Exemplar input = tessera::load(example("poisson_disk_2d.json"));
    for (const std::string extension : {".json", ".csv", ".ply", ".usda"}) {
        SCOPED_TRACE(extension);
        const std::string out = path("out" + extension), preview = path("preview" + extension + ".png");
        const Result r = run("synth " + q(example("poisson_disk_2d.json")) + " -o " + q(out) +
                             " --scale 1.5 --iterations 2 --seed 3 --preview " + q(preview));
        ASSERT_EQ(r.code, 0) << r.err;
        EXPECT_EQ(r.out, "");
        // Progress is rate-limited: the set-up stage and the last iteration are always shown.
        EXPECT_NE(r.err.find("init  elapsed "), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("iteration 2/2  energy "), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(" s\n"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("done: "), std::string::npos) << r.err;
        EXPECT_TRUE(is_png(preview));
        if (extension == ".ply") {  // one point per element, with Houdini's orient components
            const std::string ply = read_text(out);
            EXPECT_EQ(ply.rfind("ply\n", 0), 0u);
            EXPECT_NE(ply.find("property double orient_w\nproperty double pscale\n"), std::string::npos);
            continue;
        }
        if (extension == ".usda") {  // the default spheres as one point instancer
            const std::string usda = read_text(out);
            EXPECT_EQ(usda.rfind("#usda 1.0\n", 0), 0u);
            EXPECT_NE(usda.find("def PointInstancer \"Elements\""), std::string::npos);
            EXPECT_EQ(usda.find("def Xform \"Meshes\""), std::string::npos);
            continue;
        }
        const tessera::Exemplar output = tessera::load(out);
        EXPECT_EQ(output.dimension, 2);
        expect_count_near(output.elements.size(), input.elements.size() * 1.5 * 1.5);
        if (extension == ".json") {
            EXPECT_DOUBLE_EQ(output.domain.bounds().hi.x, 15.0);
            EXPECT_DOUBLE_EQ(output.domain.bounds().hi.y, 15.0);
            const auto json = nlohmann::json::parse(read_text(out));
            EXPECT_EQ(json["stats"]["seed"], 3);
            EXPECT_EQ(json["stats"]["energy"].size(), 2u);
        }
    }
}

TEST_F(CliSynth, PcfMethod) {
    const tessera::Exemplar input = tessera::load(example("poisson_disk_2d.json"));
    const Result r = run("synth " + q(example("poisson_disk_2d.json")) + " -o " + q(path("out.json")) +
                         " --method pcf --scale 1.2 --iterations 3 --seed 2 --threads 2");
    if (r.code == 70 && r.err.find("not part of this build") != std::string::npos)
        GTEST_SKIP() << "the PCF analysis is not in this build";
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("(method pcf, seed 2, at most 3 sweeps per class)"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("\nsweep "), std::string::npos) << r.err;  // rate-limited: at least the last sweep
    EXPECT_NE(r.err.find("done: "), std::string::npos) << r.err;
    const tessera::Exemplar output = tessera::load(path("out.json"));
    expect_count_near(output.elements.size(), input.elements.size() * 1.2 * 1.2);
    const auto json = nlohmann::json::parse(read_text(path("out.json")));
    EXPECT_EQ(json["stats"]["method"], "pcf");
    EXPECT_EQ(json["stats"]["seed"], 2);
}

TEST_F(CliSynth, ThreeDimensional) {
    const tessera::Exemplar input = tessera::load(example("spheres_3d.json"));
    const Result r = run("synth " + q(example("spheres_3d.json")) + " -o " + q(path("out.json")) +
                         " --scale 1.25 --iterations 1 --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    const tessera::Exemplar output = tessera::load(path("out.json"));
    EXPECT_EQ(output.dimension, 3);
    expect_count_near(output.elements.size(), input.elements.size() * std::pow(1.25, 3));
}

TEST_F(CliSynth, DefaultScaleIsTwo) {
    const Result r = run("synth " + q(example("hex_jittered_2d.json")) + " -o " + q(path("out.json")) +
                         " --iterations 0 --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    const tessera::Exemplar output = tessera::load(path("out.json"));
    EXPECT_DOUBLE_EQ(output.domain.bounds().lo.x, 0.0);
    EXPECT_DOUBLE_EQ(output.domain.bounds().hi.x, 20.0);
    EXPECT_DOUBLE_EQ(output.domain.bounds().hi.y, 20.0);
}

TEST_F(CliSynth, DomainBySize) {
    const tessera::Exemplar input = tessera::load(example("poisson_disk_2d.json"));
    const Result r = run("synth " + q(example("poisson_disk_2d.json")) + " -o " + q(path("out.json")) +
                         " --domain box:15,10 --iterations 2 --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    const tessera::Exemplar output = tessera::load(path("out.json"));
    const tessera::Box box = output.domain.bounds();
    EXPECT_DOUBLE_EQ(box.lo.x, 0.0);
    EXPECT_DOUBLE_EQ(box.lo.y, 0.0);
    EXPECT_DOUBLE_EQ(box.hi.x, 15.0);
    EXPECT_DOUBLE_EQ(box.hi.y, 10.0);
    expect_count_near(output.elements.size(), input.elements.size() * 1.5);
    for (const auto& e : output.elements) EXPECT_TRUE(output.domain.inside(e.position));
}

// Shaped domains from the command line: every form of --domain, the output's domain is
// the shape (saved in the JSON) and the elements lie inside it.
void expect_inside(const tessera::Exemplar& output) {
    int outside = 0;
    for (const auto& s : output.samples) outside += !output.domain.inside(s.p);
    EXPECT_LE(outside, static_cast<int>(output.samples.size() / 100));
}

TEST_F(CliSynth, DomainPolygonInlineAndFromFile) {
    Result r = run("synth " + q(example("poisson_disk_2d.json")) + " -o " + q(path("tri.json")) +
                   " --domain polygon:0,0,20,0,0,20 --iterations 2 --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    tessera::Exemplar out = tessera::load(path("tri.json"));
    EXPECT_EQ(out.domain.kind(), tessera::Domain::Kind::polygon);
    EXPECT_NEAR(out.domain.measure(), 200.0, 1e-9);
    expect_count_near(out.elements.size(), 110 * 2.0);
    expect_inside(out);
    r = run("synth " + q(example("poisson_disk_2d.json")) + " -o " + q(path("ring.json")) + " --domain polygon:" +
            q(example("domain_disk_with_hole.json")) + " --iterations 2 --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    out = tessera::load(path("ring.json"));
    expect_inside(out);
    for (const auto& e : out.elements) EXPECT_GT(tessera::norm(e.position - tessera::Vec3{15, 15, 0}), 3.0);
}

TEST_F(CliSynth, DomainMeshAndShell) {
    Result r = run("synth " + q(example("spheres_3d.json")) + " -o " + q(path("blob.json")) + " --domain mesh:" +
                   q(example("blob.obj") + ",48") + " --iterations 1 --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    tessera::Exemplar out = tessera::load(path("blob.json"));
    EXPECT_EQ(out.domain.kind(), tessera::Domain::Kind::mesh);
    expect_inside(out);
    r = run("synth " + q(example("spheres_3d.json")) + " -o " + q(path("shell.json")) + " --domain shell:" +
            q(example("blob.obj") + ",1.5,48") + " --iterations 1 --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    out = tessera::load(path("shell.json"));
    EXPECT_EQ(out.domain.kind(), tessera::Domain::Kind::shell);
    expect_inside(out);
    // Nothing deep inside the blob (centre (6, 6, 6), radius about 6): the shell is 1.5 thick.
    for (const auto& e : out.elements) EXPECT_GT(tessera::norm(e.position - tessera::Vec3{6, 6, 6}), 3.0);
}

TEST_F(CliSynth, DomainMaskFromPng) {
    // A 32 x 32 mask, the left half white (inside), stretched over [0, 20] x [0, 20].
    std::vector<unsigned char> pixels(32 * 32);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) pixels[y * 32 + x] = x < 16 ? 255 : 0;
    ASSERT_NE(stbi_write_png(path("half.png").c_str(), 32, 32, 1, pixels.data(), 32), 0);
    Result r = run("synth " + q(example("poisson_disk_2d.json")) + " -o " + q(path("half.json")) + " --domain mask:" +
                   q(path("half.png") + "@0,0,20,20") + " --iterations 2 --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    const tessera::Exemplar out = tessera::load(path("half.json"));
    EXPECT_EQ(out.domain.kind(), tessera::Domain::Kind::mask);
    expect_inside(out);
    for (const auto& e : out.elements) EXPECT_LT(e.position.x, 10.5);
    expect_count_near(out.elements.size(), 110 * 2.0);
    // An all-black mask has no inside: a domain error naming the file, nothing written.
    std::fill(pixels.begin(), pixels.end(), 0);
    ASSERT_NE(stbi_write_png(path("black.png").c_str(), 32, 32, 1, pixels.data(), 32), 0);
    r = run("synth " + q(example("poisson_disk_2d.json")) + " -o " + q(path("black.json")) + " --domain mask:" +
            q(path("black.png")) + " --quiet");
    EXPECT_EQ(r.code, 4) << r.err;
    EXPECT_NE(r.err.find("black.png"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("black.json")));
}

TEST_F(CliSynth, PreviewDrawsElementMeshesWhenTypesHaveThem) {
    const std::string carrots = std::string(TESSERA_SOURCE_DIR) + "/examples/scenes/carrots_2d.json";
    Result r = run("synth " + q(carrots) + " -o " + q(path("a.json")) + " --iterations 1 --quiet --preview " +
                   q(path("meshes.png")));
    ASSERT_EQ(r.code, 0) << r.err;
    r = run("render " + q(path("a.json")) + " -o " + q(path("disks.png")) + " --meshes off --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    r = run("render " + q(path("a.json")) + " -o " + q(path("again.png")) + " --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(is_png(path("meshes.png")));
    EXPECT_NE(read_text(path("meshes.png")), read_text(path("disks.png")));
    EXPECT_EQ(read_text(path("meshes.png")), read_text(path("again.png")));  // auto = meshes here
}

TEST_F(CliSynth, DomainByCorners) {
    const Result r = run("synth " + q(example("two_class_2d.json")) + " -o " + q(path("out.json")) +
                         " --domain box:5,-5,17,7 --iterations 1 --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    const tessera::Box box = tessera::load(path("out.json")).domain.bounds();
    EXPECT_DOUBLE_EQ(box.lo.x, 5.0);
    EXPECT_DOUBLE_EQ(box.lo.y, -5.0);
    EXPECT_DOUBLE_EQ(box.hi.x, 17.0);
    EXPECT_DOUBLE_EQ(box.hi.y, 7.0);
}

TEST_F(CliSynth, CsvInputWithInputDomain) {
    // The exemplar as a CSV table, whose window is given on the command line.
    tessera::save(tessera::load(example("poisson_disk_2d.json")), path("in.csv"));
    const Result r = run("synth " + q(path("in.csv")) + " --input-domain 0,0,10,10 -o " +
                         q(path("out.json")) + " --scale 1.5 --iterations 1 --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    const tessera::Box box = tessera::load(path("out.json")).domain.bounds();
    EXPECT_DOUBLE_EQ(box.hi.x, 15.0);
    EXPECT_DOUBLE_EQ(box.hi.y, 15.0);
}

TEST_F(CliSynth, InputDomainReplacesJsonDomain) {
    const Result r = run("synth " + q(example("poisson_disk_2d.json")) + " --input-domain -1,-1,11,11 -o " +
                         q(path("out.json")) + " --scale 1 --iterations 0 --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    const tessera::Box box = tessera::load(path("out.json")).domain.bounds();
    EXPECT_DOUBLE_EQ(box.lo.x, -1.0);
    EXPECT_DOUBLE_EQ(box.hi.y, 11.0);
}

TEST_F(CliSynth, QuietPrintsNothing) {
    const Result r = run("synth " + q(example("poisson_disk_2d.json")) + " -o " + q(path("out.csv")) +
                         " --scale 1.5 --iterations 1 --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "");
}

TEST_F(CliSynth, PictureOutput) {
    const Result r = run("synth " + q(example("sticks_2d.json")) + " -o " + q(path("out.svg")) +
                         " --scale 1.2 --iterations 1 --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(read_text(path("out.svg")).find("<svg"), std::string::npos);
}

// Same seed: byte-identical files whatever the thread count; another seed: different.
TEST_F(CliSynth, DeterministicAcrossThreads) {
    const std::string base =
        "synth " + q(example("two_class_2d.json")) + " --scale 1.5 --iterations 2 --quiet ";
    ASSERT_EQ(run(base + "--seed 7 --threads 1 -o " + q(path("a.csv"))).code, 0);
    ASSERT_EQ(run(base + "--seed 7 --threads 2 -o " + q(path("b.csv"))).code, 0);
    ASSERT_EQ(run(base + "--seed 8 --threads 2 -o " + q(path("c.csv"))).code, 0);
    ASSERT_EQ(run(base + "--seed 7 --threads 2 -o " + q(path("a.json"))).code, 0);
    ASSERT_EQ(run(base + "--seed 7 --threads 1 -o " + q(path("b.json"))).code, 0);
    const std::string a = read_text(path("a.csv"));
    EXPECT_FALSE(a.empty());
    EXPECT_EQ(a, read_text(path("b.csv")));
    EXPECT_NE(a, read_text(path("c.csv")));
    EXPECT_EQ(read_text(path("a.json")), read_text(path("b.json")));
}

// Ctrl-C stops the run at the next iteration boundary: exit 130, nothing written.
TEST_F(CliSynth, InterruptWritesNothing) {
    // 1 s: well past the start-up of a sanitizer build, well before the run's end.
    const std::string command = "timeout --preserve-status -s INT 1 '" + std::string(TESSERA_CLI) +
                                "' synth " + q(example("spheres_3d.json")) + " -o " + q(path("out.json")) +
                                " --scale 1.25 --iterations 100000 --quiet 2>" +
                                q((root_ / "capture" / "err").string());
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 130);
    EXPECT_EQ(read_text(root_ / "capture" / "err"), "tessera: error: interrupted; nothing was written\n");
    EXPECT_TRUE(work_files().empty());
}

// ---- metrics -------------------------------------------------------------------

class CliMetrics : public CliFixture {};

TEST_F(CliMetrics, PrintsJsonReport) {
    ASSERT_EQ(run("synth " + q(example("two_class_2d.json")) + " -o " + q(path("out.json")) +
                  " --scale 1.5 --iterations 1 --quiet")
                  .code,
              0);
    const Result r =
        run("metrics " + q(example("two_class_2d.json")) + " " + q(path("out.json")) + " --bins 51");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    const auto report = nlohmann::json::parse(r.out);
    for (const char* key : {"dimension", "exemplar", "output", "pcf_relative_error",
                            "nn_mean_relative_difference", "psi6_difference"})
        EXPECT_TRUE(report.contains(key)) << key;
    EXPECT_EQ(report["dimension"], 2);
    EXPECT_EQ(report["exemplar"]["elements"], 112);
    for (const char* key : {"elements", "count_per_class", "density", "nearest_neighbor", "mean_psi6", "pcf"})
        EXPECT_TRUE(report["output"].contains(key)) << key;
    EXPECT_EQ(report["exemplar"]["pcf"]["r"].size(), 51u);
    EXPECT_EQ(report["exemplar"]["pcf"]["pairs"].size(), 3u);  // two classes: aa, ab, bb
    EXPECT_GT(line_count(r.out), 10);                          // pretty-printed
}

TEST_F(CliMetrics, WritesReportFile) {
    const Result r = run("metrics " + q(example("spheres_3d.json")) + " " + q(example("spheres_3d.json")) +
                         " -o " + q(path("report.json")) + " --quiet");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out, "");
    const auto report = nlohmann::json::parse(read_text(path("report.json")));
    EXPECT_EQ(report["dimension"], 3);
    EXPECT_FALSE(report.contains("psi6_difference"));
}

// ---- render --------------------------------------------------------------------

class CliRender : public CliFixture {};

TEST_F(CliRender, WritesPngAndSvg) {
    Result r =
        run("render " + q(example("sticks_2d.json")) + " -o " + q(path("sticks.png")) + " --width 300");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(is_png(path("sticks.png")));
    r = run("render " + q(example("rods_3d.json")) + " -o " + q(path("rods.svg")) +
            " --no-domain --no-samples -q");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_NE(read_text(path("rods.svg")).find("<svg"), std::string::npos);
}

// ---- help and version ------------------------------------------------------------

class CliHelp : public CliFixture {};

TEST_F(CliHelp, EverySubcommandHasHelp) {
    for (const std::string command : {"", "synth ", "metrics ", "render "}) {
        SCOPED_TRACE(command);
        const Result r = run(command + "--help");
        EXPECT_EQ(r.code, 0);
        EXPECT_NE(r.out.find("Usage: tessera"), std::string::npos) << r.out;
    }
    const Result synth = run("synth --help");
    for (const char* flag :
         {"--scale FLOAT=2", "--seed", "--iterations INT", "--radius", "--threads", "--preview",
          "--input-domain", "--domain", "--k INT=4", "--search kcoherence|exhaustive=kcoherence", "--matching greedy|hungarian=greedy",
          "--alpha", "--lambda", "--patch-size", "--relax-sweeps INT=4", "--quiet"})
        EXPECT_NE(synth.out.find(flag), std::string::npos) << flag;
}

TEST_F(CliHelp, Version) {
    const Result r = run("--version");
    EXPECT_EQ(r.code, 0);
    EXPECT_EQ(r.out, "tessera " + std::string(tessera::version) + "\n");
}

TEST_F(CliHelp, MissingSubcommandIsUsageError) {
    const Result r = run("");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(line_count(r.err), 1) << r.err;
}

// ---- errors ----------------------------------------------------------------------

struct ErrorCase {
    std::string name;
    std::string file, content;     // an input file to create in the work directory (if any)
    std::string args;              // {work} is replaced by the work directory, {ex} by the examples
    int code;                      // expected exit code
    std::vector<std::string> say;  // substrings of the one-line message
};

// Printed in test listings (ctest names) instead of the struct's raw bytes.
void PrintTo(const ErrorCase& c, std::ostream* os) { *os << c.name; }

class CliErrors : public CliFixture, public ::testing::WithParamInterface<ErrorCase> {};

std::string expand(std::string text, const std::string& work) {
    for (const auto& [key, value] : {std::pair<std::string, std::string>{"{work}", work}, {"{ex}", examples}})
        for (size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + value.size()))
            text.replace(at, key.size(), value);
    return text;
}

TEST_P(CliErrors, FailsWithOneLineAndWritesNothing) {
    const ErrorCase& c = GetParam();
    if (!c.file.empty()) write(c.file, c.content);
    const std::set<std::string> before = work_files();
    const Result r = run(expand(c.args, (root_ / "work").string()));
    EXPECT_EQ(r.code, c.code) << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("tessera: error: ", 0), 0u) << r.err;
    for (const auto& s : c.say)
        EXPECT_NE(r.err.find(s), std::string::npos) << "'" << s << "' not in: " << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(work_files(), before) << "an output or temporary file was left behind";
}

// --quiet: the one line on stderr is then the error alone, even for errors found after loading.
const std::string synth_poisson =
    "synth '{ex}poisson_disk_2d.json' -o '{work}/out.json' --iterations 1 --quiet ";
const std::string valid_csv = "x,y\n1,1\n2,3\n5,2\n";

// clang-format off
const ErrorCase error_cases[] = {
    {"malformed_json", "bad.json", "{\"format\": \"tessera\", \"version\": 1,\n \"dimension\": 2\n \"domain\": {}}\n",
     "synth '{work}/bad.json' -o '{work}/out.json'", 3, {"bad.json", "line 3"}},
    {"malformed_csv", "bad.csv", "x,y\n1,2\n3\n", "synth '{work}/bad.csv' -o '{work}/out.json'", 3,
     {"bad.csv:3", "expected 2 fields"}},
    {"nan_in_csv", "nan.csv", "x,y\n1,2\nnan,3\n2,2\n", "synth '{work}/nan.csv' -o '{work}/out.csv'", 3,
     {"nan.csv:3", "NaN"}},
    {"empty_exemplar", "empty.csv", "x,y\n", "synth '{work}/empty.csv' -o '{work}/out.json'", 3,
     {"empty.csv", "no elements"}},
    {"input_domain_holds_no_element", "pts.csv", "x,y\n1,-0.5\n2,-0.7\n3,-0.2\n",
     "synth '{work}/pts.csv' --input-domain 0,0,4,4 -o '{work}/out.json'", 4,
     {"none of its 3 points", "pts.csv", "--input-domain 0,0,4,4"}},
    {"world_input_domain_holds_no_element", "pts.csv", "x,y\n1,-0.5\n2,-0.7\n3,-0.2\n",
     "world '{work}/pts.csv' --input-domain 0,0,4,4 --tiles 0:2,0:2 --tile-size 4 -o '{work}/out.json'", 4,
     {"none of its 3 points", "--input-domain"}},
    {"json_input_domain_holds_no_element", "two.json",
     R"({"format": "tessera", "version": 1, "dimension": 2, "domain": {"type": "box", "min": [0, 0], "max": [4, 4]},
         "types": [{"name": "dot"}], "elements": [{"type": "dot", "position": [1, 1]},
         {"type": "dot", "position": [2, 3]}]})",
     "synth '{work}/two.json' --input-domain 10,10,20,20 -o '{work}/out.json'", 4,
     {"none of the 2 elements", "two.json", "--input-domain 10,10,20,20"}},
    {"input_domain_leaves_points_out", "pts.csv", "x,y\n1,0.5\n2,0.7\n3,-0.2\n",
     "synth '{work}/pts.csv' --input-domain 0,0,4,4 -o '{work}/out.json'", 4,
     {"1 of its 3 points lie outside the input domain", "3,-0.2", "--input-domain 0,0,4,4"}},
    {"json_input_domain_leaves_elements_out", "two.json",
     R"({"format": "tessera", "version": 1, "dimension": 2, "domain": {"type": "box", "min": [0, 0], "max": [4, 4]},
         "types": [{"name": "dot"}], "elements": [{"type": "dot", "position": [1, 1]},
         {"type": "dot", "position": [2, 3]}]})",
     "synth '{work}/two.json' --input-domain 0,0,2,2 -o '{work}/out.json'", 4,
     {"1 of the 2 elements", "lie outside --input-domain 0,0,2,2", "2,3"}},
    {"unknown_type", "unk.json",
     R"({"format": "tessera", "version": 1, "dimension": 2, "domain": {"type": "box", "min": [0, 0], "max": [4, 4]},
         "types": [{"name": "dot"}], "elements": [{"type": "dot", "position": [1, 1]},
         {"type": "rock", "position": [2, 3]}]})",
     "synth '{work}/unk.json' -o '{work}/out.json'", 3, {"unk.json", "unknown element type 'rock'"}},
    {"zero_radius_in_csv", "rad.csv", "x,y,radius\n1,2,0.1\n3,4,0\n", "synth '{work}/rad.csv' -o '{work}/out.json'",
     3, {"rad.csv:3", "radius"}},
    {"negative_radius_in_csv", "rad.csv", "x,y,radius\n1,2,-0.1\n3,4,1\n",
     "synth '{work}/rad.csv' -o '{work}/out.json'", 3, {"rad.csv:2", "radius"}},
    {"zero_size_domain", "", "", synth_poisson + "--domain box:0,5", 2, {"--domain", "box:0,5"}},
    {"zero_extent_input_domain", "", "", synth_poisson + "--input-domain 0,0,0,5", 2, {"--input-domain"}},
    {"zero_extent_input_domain_csv", "in.csv", valid_csv,
     "synth '{work}/in.csv' -o '{work}/out.json' --input-domain 0,0,10,0", 2, {"--input-domain"}},
    {"zero_extent_json_domain", "flat.json",
     R"({"format": "tessera", "version": 1, "dimension": 2, "domain": {"type": "box", "min": [0, 0], "max": [4, 0]},
         "elements": [{"position": [1, 0]}, {"position": [2, 0]}]})",
     "synth '{work}/flat.json' -o '{work}/out.json'", 4, {"flat.json"}},
    {"csv_bounding_box_is_a_line", "line.csv", "x,y\n1,1\n2,1\n3,1\n", "synth '{work}/line.csv' -o '{work}/out.json'",
     4, {"line.csv", "--input-domain"}},
    {"domain_dimension_mismatch", "", "", synth_poisson + "--domain box:4,4,4", 4, {"--domain", "3D", "2D"}},
    {"input_domain_dimension_mismatch", "", "", synth_poisson + "--input-domain 0,0,10,10,0,1", 4,
     {"--input-domain", "3D", "2D"}},
    {"domain_without_box_prefix", "", "", synth_poisson + "--domain 4,4", 2, {"--domain", "box:"}},
    {"domain_too_small", "", "", synth_poisson + "--domain box:0.1,0.1", 4, {"too small"}},
    {"negative_radius_flag", "", "", synth_poisson + "--radius -1", 2, {"--radius", "-1"}},
    {"zero_scale", "", "", synth_poisson + "--scale 0", 2, {"--scale"}},
    {"nan_scale", "", "", synth_poisson + "--scale nan", 2, {"--scale"}},
    {"scale_not_a_number", "", "", synth_poisson + "--scale abc", 2, {"--scale", "abc"}},
    {"scale_and_domain", "", "", synth_poisson + "--scale 2 --domain box:4,4", 2, {"--scale", "--domain"}},
    {"negative_iterations", "", "", synth_poisson + "--iterations -1", 2, {"--iterations"}},
    {"negative_threads", "", "", synth_poisson + "--threads -1", 2, {"--threads"}},
    {"zero_k", "", "", synth_poisson + "--k 0", 2, {"--k"}},
    {"negative_relax_sweeps", "", "", synth_poisson + "--relax-sweeps -1", 2, {"--relax-sweeps"}},
    {"unknown_search", "", "", synth_poisson + "--search fast", 2, {"--search", "fast"}},
    {"unknown_matching", "", "", synth_poisson + "--matching best", 2, {"--matching", "best"}},
    {"unknown_method", "", "", synth_poisson + "--method mcmc", 2, {"--method", "mcmc"}},
    {"det_flag_with_pcf", "", "", synth_poisson + "--method pcf --k 3", 2, {"--k", "--method det"}},
    {"pcf_flag_with_det", "", "", synth_poisson + "--max-fails 3", 2, {"--max-fails", "--method pcf"}},
    {"pcf_zero_grid_cells", "", "", synth_poisson + "--method pcf --grid-cells 0", 2, {"--grid-cells", "0"}},
    {"pcf_negative_max_fails", "", "", synth_poisson + "--method pcf --max-fails -1", 2, {"--max-fails"}},
    {"pcf_zero_sigma", "", "", synth_poisson + "--method pcf --sigma 0", 2, {"--sigma"}},
    {"pcf_negative_convergence", "", "", synth_poisson + "--method pcf --convergence -1", 2, {"--convergence"}},
    {"pcf_negative_stall", "", "", synth_poisson + "--method pcf --stall -1", 2, {"--stall"}},
    {"unknown_option", "", "", synth_poisson + "--colour red", 2, {"--colour"}},
    {"unknown_output_extension", "", "", "synth '{ex}poisson_disk_2d.json' -o '{work}/out.xyz'", 2,
     {"-o", "out.xyz", ".xyz"}},
    {"unknown_preview_extension", "", "", synth_poisson + "--preview '{work}/p.gif'", 2, {"--preview", ".gif"}},
    {"missing_input", "", "", "synth '{work}/missing.json' -o '{work}/out.json'", 5, {"missing.json"}},
    {"unsupported_input_extension", "in.txt", valid_csv, "synth '{work}/in.txt' -o '{work}/out.json'", 5,
     {"in.txt", ".txt"}},
    {"missing_output_directory", "", "", "synth '{ex}poisson_disk_2d.json' -o '{work}/no/such/out.json'", 5,
     {"no/such/out.json"}},
    {"missing_output_flag", "", "", "synth '{ex}poisson_disk_2d.json'", 2, {"--output"}},
    {"metrics_dimension_mismatch", "", "", "metrics '{ex}poisson_disk_2d.json' '{ex}spheres_3d.json'", 3,
     {"2D", "3D"}},
    {"metrics_bad_bins", "", "", "metrics '{ex}poisson_disk_2d.json' '{ex}poisson_disk_2d.json' --bins 1", 2,
     {"--bins"}},
    {"metrics_negative_rmax", "", "", "metrics '{ex}poisson_disk_2d.json' '{ex}poisson_disk_2d.json' --r-max -2", 2,
     {"--r-max"}},
    {"metrics_missing_output", "", "", "metrics '{ex}poisson_disk_2d.json' '{work}/none.json'", 5, {"none.json"}},
    {"render_bad_extension", "", "", "render '{ex}poisson_disk_2d.json' -o '{work}/p.jpg'", 2, {"-o", ".jpg"}},
    {"render_zero_width", "", "", "render '{ex}poisson_disk_2d.json' -o '{work}/p.png' --width 0", 2, {"--width"}},
    {"render_huge_width", "", "", "render '{ex}poisson_disk_2d.json' -o '{work}/p.png' --width 100000", 2,
     {"--width"}},
    {"bad_boundary_side", "", "", synth_poisson + "--boundary -w --boundary-distance 0.5", 2, {"--boundary", "-w"}},
    {"boundary_without_distance", "", "", synth_poisson + "--boundary -x", 2, {"--boundary-distance"}},
    {"boundary_z_in_2d", "", "", synth_poisson + "--boundary +z --boundary-distance 0.5", 2, {"boundary side"}},
    {"render_bad_meshes", "", "", "render '{ex}poisson_disk_2d.json' -o '{work}/p.png' --meshes maybe", 2,
     {"--meshes", "maybe"}},
    {"render_meshes_in_svg", "", "", "render '{ex}poisson_disk_2d.json' -o '{work}/p.svg' --meshes on", 2,
     {"p.svg", ".png"}},
    {"render_malformed_csv", "bad.csv", "x,y\n1,2\n3,4,5\n", "render '{work}/bad.csv' -o '{work}/p.png'", 3,
     {"bad.csv:3"}},
    {"field_grid_zero_vector", "grid.json",
     R"({"format": "tessera-field", "dimension": 2, "origin": [0, 0], "spacing": [1, 1], "size": [2, 2],
         "vectors": [[1, 0], [0, 0], [1, 0], [1, 0]]})",
     synth_poisson + "--field 'grid:{work}/grid.json'", 3, {"--field", "grid.json", "vectors[1]", "(1,0)"}},
    {"field_grid_missing", "", "", synth_poisson + "--field 'grid:{work}/none.json'", 5, {"--field", "none.json"}},
    {"field_mesh_in_2d", "", "", synth_poisson + "--field 'mesh:{ex}blob.obj'", 2, {"--field", "blob.obj", "3D"}},
};
// clang-format on

INSTANTIATE_TEST_SUITE_P(Cli, CliErrors, ::testing::ValuesIn(error_cases),
                         [](const ::testing::TestParamInfo<ErrorCase>& info) { return info.param.name; });

}  // namespace

// ---- edit ------------------------------------------------------------------------

namespace {

class CliEdit : public CliFixture {};

TEST_F(CliEdit, SpreadsTheEditAndReportsTheCount) {
    const Result r = run("edit " + q(example("striped_dots_2d.json")) + " " + q(example("striped_dots_2d_edit.json")) +
                         " -o " + q(path("edited.json")));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("changed "), std::string::npos);
    const tessera::Exemplar before = tessera::load(example("striped_dots_2d.json"));
    const tessera::Exemplar after = tessera::load(path("edited.json"));
    ASSERT_EQ(before.elements.size(), after.elements.size());
    int grown = 0;
    for (size_t i = 0; i < after.elements.size(); ++i) {
        if (after.elements[i].radius == 0.3) {
            ++grown;
            EXPECT_EQ(after.types[after.elements[i].type].name, "accent");  // only the edited kind
        }
    }
    EXPECT_GT(grown, 30);
    EXPECT_LT(grown, 75);  // 5 accent rows of 15, not all of them (the row ends differ)
}

TEST_F(CliEdit, WritesInstancingFormats) {
    const std::string base = "edit " + q(example("striped_dots_2d.json")) + " " + q(example("striped_dots_2d_edit.json"));
    const tessera::Exemplar before = tessera::load(example("striped_dots_2d.json"));
    const Result usda = run(base + " -o " + q(path("edited.usda")));
    ASSERT_EQ(usda.code, 0) << usda.err;
    EXPECT_NE(usda.err.find("scene: " + std::to_string(before.elements.size()) + " instances"), std::string::npos)
        << usda.err;
    EXPECT_EQ(read_text(path("edited.usda")).rfind("#usda 1.0\n", 0), 0u);
    // The dots are spheres: with the nodes fallback, one node each.
    const Result glb = run(base + " -o " + q(path("edited.gltf")) + " --gltf-instancing nodes -q");
    ASSERT_EQ(glb.code, 0) << glb.err;
    EXPECT_EQ(gltf_test::content_nodes(nlohmann::json::parse(read_text(path("edited.gltf")))).size(),
              before.elements.size());
}

TEST_F(CliEdit, UnknownElementFailsAndWritesNothing) {
    write("bad.json", R"({"element": 99999, "offset": [1, 0]})");
    const Result r = run("edit " + q(example("striped_dots_2d.json")) + " " + q(path("bad.json")) + " -o " +
                         q(path("out.json")));
    EXPECT_EQ(r.code, 3);
    EXPECT_EQ(line_count(r.err), 1);
    EXPECT_NE(r.err.find("99999"), std::string::npos);
    EXPECT_EQ(work_files(), std::set<std::string>{"bad.json"});
}

}  // namespace
