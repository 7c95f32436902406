// End-to-end tests of `tessera analyze` (apps/tessera/cmd_analyze.cpp): the model and its
// plots, the standard-convention CSV held against spatstat's reference values for every
// dataset in the shared data, and the error cases (one line on stderr, exit code by
// kind, nothing written).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "metrics/field_data.hpp"
#include "temp_dir.hpp"
#include "tessera/io.hpp"
#include "tessera/pcf_synthesis.hpp"

namespace fs = std::filesystem;

namespace {

const std::string examples = std::string(TESSERA_SOURCE_DIR) + "/examples/";
const std::string points_dir = std::string(TESSERA_SHARED_DATA_DIR) + "/points/";

struct CliRun {
    int code = -1;
    std::string out, err;
};

class PcfAnalyzeCli : public tessera::test::TempDirTest {
protected:
    // Runs `tessera analyze <args>`, capturing stdout and stderr outside the work directory.
    CliRun analyze(const std::string& args) {
        const fs::path capture = dir_.string() + "_capture";
        fs::create_directories(capture);
        const std::string command = "'" + std::string(TESSERA_CLI) + "' analyze " + args + " >'" +
                                    (capture / "out").string() + "' 2>'" + (capture / "err").string() + "'";
        const int status = std::system(command.c_str());
        CliRun r;
        r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        r.out = slurp(capture / "out");
        r.err = slurp(capture / "err");
        fs::remove_all(capture);
        return r;
    }
    static std::string slurp(const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        std::ostringstream s;
        s << in.rdbuf();
        return s.str();
    }
    std::set<std::string> files() const {
        std::set<std::string> names;
        for (const auto& e : fs::directory_iterator(dir_)) names.insert(e.path().filename().string());
        return names;
    }
    std::string q(const std::string& name) const { return "'" + path(name) + "'"; }
};

int lines(const std::string& s) {
    int n = 0;
    for (char c : s) n += c == '\n';
    return n;
}

}  // namespace

TEST_F(PcfAnalyzeCli, WritesModelAndPlots) {
    const CliRun r = analyze("'" + examples + "two_class_2d.json' -o " + q("model.json") + " --plot " + q("pcfs.png"));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find("3 PCF(s)"), std::string::npos) << r.err;
    const tessera::PcfModel m = tessera::pcf_model_from_json(read("model.json"), "model.json");
    EXPECT_EQ(m.classes, (std::vector<std::string>{"stone", "pebble"}));
    EXPECT_TRUE(m.disks);
    EXPECT_EQ(m.pcfs.size(), 3u);
    EXPECT_EQ(read("pcfs.png").compare(0, 8, "\x89PNG\r\n\x1a\n"), 0);

    const CliRun svg = analyze("'" + examples + "two_class_2d.json' --plot " + q("pcfs.svg") + " --sigma 0.2 --step 0.05 -q");
    ASSERT_EQ(svg.code, 0) << svg.err;
    EXPECT_EQ(svg.err, "");
    EXPECT_EQ(svg.out, "");  // --plot alone does not print the model
    const std::string text = read("pcfs.svg");
    EXPECT_NE(text.find("<svg"), std::string::npos);
    for (const char* title : {">stone<", ">pebble<", ">pebble | stone<"}) EXPECT_NE(text.find(title), std::string::npos) << title;
}

TEST_F(PcfAnalyzeCli, PrintsModelWithoutOutput) {
    const CliRun r = analyze("'" + points_dir + "amacrine.csv' --input-domain 0,0,1.60121,1 --extent 3 -q");
    ASSERT_EQ(r.code, 0) << r.err;
    const tessera::PcfModel m = tessera::pcf_model_from_json(r.out, "stdout");
    EXPECT_EQ(m.classes, (std::vector<std::string>{"on", "off"}));
    EXPECT_NEAR(m.area, 1.60121, 1e-12);
    EXPECT_NEAR(m.x.back(), 3.0, 1e-12);
    EXPECT_EQ(files(), std::set<std::string>{});
}

// spatstat 3.0 pcf / pcfcross on every dataset of reference/ through the CLI: within 3%
// wherever r >= 3 h and g >= 0.2, for every class pair column.
TEST_F(PcfAnalyzeCli, StandardPcfAgreesWithSpatstat) {
    namespace t = tessera::test;
    const t::CsvTable windows = t::read_csv(t::shared_data_dir() + "/points/windows.csv");
    int datasets = 0;
    for (const auto& entry : fs::directory_iterator(t::shared_data_dir() + "/reference")) {
        const std::string file = entry.path().filename().string();
        if (file.size() < 8 || file.substr(file.size() - 8) != "_pcf.csv") continue;
        const std::string name = file.substr(0, file.size() - 8);
        SCOPED_TRACE(name);
        ++datasets;
        const t::ReferenceParams params = t::reference_params(name);
        std::string window;
        for (size_t row = 0; row < windows.rows.size(); ++row)
            if (windows.rows[row][windows.column("name")] == name)
                for (const char* c : {"xmin", "ymin", "xmax", "ymax"})
                    window += (window.empty() ? "" : ",") + windows.rows[row][windows.column(c)];
        ASSERT_FALSE(window.empty());
        char args[256];
        std::snprintf(args, sizeof args, " --input-domain %s --standard-pcf --bandwidth %.17g --r-max %.17g --csv ",
                      window.c_str(), params.bandwidth, params.r_max);
        const CliRun r = analyze("'" + points_dir + name + ".csv'" + args + q(name + ".csv") + " -q");
        ASSERT_EQ(r.code, 0) << r.err;
        const t::CsvTable ours = t::read_csv(path(name + ".csv"));
        ASSERT_EQ(ours.columns, (std::vector<std::string>{"r", "class_a", "class_b", "g"}));
        const t::CsvTable ref = t::read_csv(entry.path().string());
        ASSERT_EQ(ref.rows.size(), 101u);
        for (size_t col = 1; col < ref.columns.size(); ++col) {
            const std::string& column = ref.columns[col];
            SCOPED_TRACE(column);
            std::string a, b;  // "g": one class without a class column, reported with empty names
            if (column != "g") {
                const size_t second = column.find('_', 2);  // g_A_B; these class names have no '_'
                ASSERT_NE(second, std::string::npos);
                a = column.substr(2, second - 2);
                b = column.substr(second + 1);
            }
            std::vector<size_t> rows;
            for (size_t k = 0; k < ours.rows.size(); ++k) {
                const std::string& ca = ours.rows[k][1];
                const std::string& cb = ours.rows[k][2];
                if ((ca == a && cb == b) || (ca == b && cb == a)) rows.push_back(k);
            }
            ASSERT_EQ(rows.size(), 101u);
            int checked = 0;
            for (size_t k = 0; k < 101; ++k) {
                const double r_ours = ours.number(rows[k], 0), g = ours.number(rows[k], 3);
                ASSERT_NEAR(r_ours, ref.number(k, 0), 1e-9);
                const double g_ref = ref.number(k, static_cast<int>(col));
                if (k == 0) {
                    EXPECT_TRUE(std::isinf(g));
                }
                if (r_ours < 3.0 * params.bandwidth || !(g_ref >= 0.2)) continue;
                EXPECT_NEAR(g / g_ref, 1.0, 0.03) << "r = " << r_ours;
                ++checked;
            }
            EXPECT_GT(checked, 20);
        }
    }
    EXPECT_GE(datasets, 7);
}

TEST_F(PcfAnalyzeCli, StandardPcfDefaultsToTheBoundingBoxAndNamesClasses) {
    write("pts.csv", "x,y,class\n0,0,a\n1,0,b\n0,1,a\n1,1,b\n0.5,0.5,a\n0.2,0.7,b\n");
    const CliRun r = analyze(q("pts.csv") + " --standard-pcf --r-max 0.5 --bandwidth 0.05 --bins 11 --csv " + q("g.csv"));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("wrote"), std::string::npos);
    const tessera::test::CsvTable g = tessera::test::read_csv(path("g.csv"));
    ASSERT_EQ(g.rows.size(), 33u);  // 3 class pairs x 11 values of r
    EXPECT_EQ(g.rows[0][1], "a");
    EXPECT_EQ(g.rows[0][2], "a");
    EXPECT_EQ(g.rows[11][1], "a");
    EXPECT_EQ(g.rows[11][2], "b");
    EXPECT_EQ(g.rows[0][3], "Inf");
    EXPECT_DOUBLE_EQ(g.number(10, 0), 0.5);
}

TEST_F(PcfAnalyzeCli, HelpListsTheOptions) {
    const CliRun r = analyze("--help");
    EXPECT_EQ(r.code, 0);
    for (const char* flag : {"--plot", "--sigma", "--step", "--extent", "--input-domain", "--standard-pcf",
                             "--bandwidth", "--r-max", "--bins", "--csv", "--quiet"})
        EXPECT_NE(r.out.find(flag), std::string::npos) << flag;
}

TEST_F(PcfAnalyzeCli, ErrorsAreOneLineAndWriteNothing) {
    const std::string two = "'" + examples + "two_class_2d.json'";
    write("cycle.json", R"({"format": "tessera", "version": 1, "dimension": 2,
        "domain": {"type": "box", "min": [0, 0], "max": [10, 10]},
        "types": [{"name": "tree", "depends_on": ["grass"]}, {"name": "grass", "depends_on": ["tree"]}],
        "elements": [{"type": "tree", "position": [1, 1]}, {"type": "tree", "position": [5, 5]},
                     {"type": "grass", "position": [2, 1]}, {"type": "grass", "position": [7, 3]}]})");
    write("lonely.json", R"({"format": "tessera", "version": 1, "dimension": 2,
        "domain": {"type": "box", "min": [0, 0], "max": [10, 10]}, "types": [{"name": "a"}, {"name": "b"}],
        "elements": [{"type": "a", "position": [1, 1]}, {"type": "a", "position": [5, 5]}]})");
    write("unknown.json", R"({"format": "tessera", "version": 1, "dimension": 2,
        "domain": {"type": "box", "min": [0, 0], "max": [10, 10]},
        "types": [{"name": "tree", "depends_on": ["rock"]}],
        "elements": [{"type": "tree", "position": [1, 1]}, {"type": "tree", "position": [5, 5]}]})");
    const struct {
        std::string args;
        int code;
        std::vector<std::string> say;
    } cases[] = {
        {"'" + points_dir + "cells.csv' --standard-pcf --bandwidth -1 --csv " + q("g.csv"), 2, {"--bandwidth", "-1"}},
        {"'" + points_dir + "cells.csv' --standard-pcf --bandwidth nan --csv " + q("g.csv"), 2, {"--bandwidth"}},
        {"'" + points_dir + "cells.csv' --standard-pcf --r-max -2 --csv " + q("g.csv"), 2, {"--r-max"}},
        {"'" + points_dir + "cells.csv' --standard-pcf --bins 1 --csv " + q("g.csv"), 2, {"--bins"}},
        {"'" + points_dir + "cells.csv' --standard-pcf", 2, {"--csv"}},
        {"'" + points_dir + "cells.csv' --standard-pcf --csv " + q("g.txt"), 2, {"--csv", ".txt"}},
        {"'" + points_dir + "cells.csv' --standard-pcf --plot " + q("p.svg") + " --csv " + q("g.csv"), 2,
         {"--plot", "--standard-pcf"}},
        {"'" + points_dir + "cells.csv' --bandwidth 0.1 -o " + q("m.json"), 2, {"--bandwidth", "--standard-pcf"}},
        {q("cycle.json") + " -o " + q("m.json"), 3, {"cycle", "'tree'", "'grass'"}},
        {q("unknown.json") + " -o " + q("m.json"), 3, {"unknown.json", "'tree'", "'rock'"}},
        {q("lonely.json") + " -o " + q("m.json"), 3, {"'b'", "no elements"}},
        {two + " --plot " + q("p.jpg"), 2, {"--plot", ".jpg"}},
        {two + " -o " + q("m.txt"), 2, {"-o", ".txt"}},
        {two + " -o " + q("no/such/m.json"), 5, {"no/such"}},
        {two + " --sigma 0 -o " + q("m.json"), 2, {"--sigma"}},
        {two + " --step -0.1 -o " + q("m.json"), 2, {"--step"}},
        {two + " --extent 0 -o " + q("m.json"), 2, {"--extent"}},
        {"'" + examples + "spheres_3d.json' -o " + q("m.json"), 3, {"2D"}},
        {"'" + examples + "sticks_2d.json' -o " + q("m.json"), 3, {"multi-sample"}},
        {q("missing.json") + " -o " + q("m.json"), 5, {"missing.json"}},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.args);
        const std::set<std::string> before = files();
        const CliRun r = analyze(c.args);
        EXPECT_EQ(r.code, c.code) << r.err;
        EXPECT_EQ(lines(r.err), 1) << r.err;
        EXPECT_EQ(r.err.rfind("tessera: error: ", 0), 0u) << r.err;
        for (const auto& s : c.say) EXPECT_NE(r.err.find(s), std::string::npos) << "'" << s << "' not in: " << r.err;
        EXPECT_EQ(r.out, "");
        EXPECT_EQ(files(), before);
    }
}
