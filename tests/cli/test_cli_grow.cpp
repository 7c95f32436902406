// `tessera grow` end to end: a region or a count, a start arrangement whose elements stay
// where they are, a picture per round and a contact sheet, and one-line errors that write
// nothing.
#include <map>

#include "cli_fixture.hpp"
#include "tessera/tessera.hpp"

using namespace tessera_cli_test;

class CliGrow : public CliFixture {};

TEST_F(CliGrow, GrowsARegionWithAPreviewAndRoundPictures) {
    const std::string out = path("grown.json"), preview = path("grown.png"), rounds = path("rounds");
    const Result r = run("grow " + q(example("two_class_2d.json")) + " -o " + q(out) +
                         " --region box:0,0,20,20 --seed 4 --preview " + q(preview) + " --round-pictures " + q(rounds));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("done: "), std::string::npos) << r.err;
    const tessera::Exemplar input = tessera::load(example("two_class_2d.json"));
    const tessera::Exemplar grown = tessera::load(out);
    expect_count_near(grown.elements.size(), input.elements.size() * 4.0);
    for (const tessera::Element& e : grown.elements) {
        EXPECT_GE(e.position.x, 0.0);
        EXPECT_LE(e.position.x, 20.0);
    }
    EXPECT_TRUE(is_png(preview));
    EXPECT_TRUE(is_png(rounds + "/round_001.png"));
    EXPECT_TRUE(is_png(rounds + "/contact_sheet.png"));
}

TEST_F(CliGrow, GrowsByACountFromAnExistingArrangementThatStaysPut) {
    const std::string start = path("start.json"), out = path("more.json");
    ASSERT_EQ(run("synth " + q(example("poisson_disk_2d.json")) + " -o " + q(start) + " --scale 1 -q").code, 0);
    const Result r = run("grow " + q(example("poisson_disk_2d.json")) + " -o " + q(out) + " --from " + q(start) +
                         " --elements 200 -q");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    const tessera::Exemplar before = tessera::load(start), after = tessera::load(out);
    EXPECT_NEAR(static_cast<double>(after.elements.size()), before.elements.size() + 200.0, 40.0);
    std::map<std::uint64_t, tessera::Vec3> at;
    for (const tessera::Element& e : after.elements) at[e.id] = e.position;
    for (const tessera::Element& e : before.elements) {
        ASSERT_TRUE(at.count(e.id)) << "element " << e.id << " is gone";
        EXPECT_NEAR(at[e.id].x, e.position.x, 1e-9);
        EXPECT_NEAR(at[e.id].y, e.position.y, 1e-9);
    }
}

TEST_F(CliGrow, TheSameSeedGivesByteIdenticalOutputForAnyThreadCount) {
    const std::string a = path("a.json"), b = path("b.json");
    const std::string grow = "grow " + q(example("two_class_2d.json")) + " --region box:0,0,15,15 --seed 9 -q ";
    ASSERT_EQ(run(grow + "--threads 1 -o " + q(a)).code, 0);
    ASSERT_EQ(run(grow + "--threads 2 -o " + q(b)).code, 0);
    EXPECT_EQ(read_text(a), read_text(b));
}

TEST_F(CliGrow, BadInputIsAOneLineErrorAndWritesNothing) {
    const std::string in = q(example("two_class_2d.json")), out = " -o " + q(path("o.json"));
    struct Case {
        std::string args, message;
        int code;
    };
    write("other.json", "");
    ASSERT_EQ(run("synth " + q(example("poisson_disk_2d.json")) + " -o " + q(path("dots.json")) + " --scale 1 -q").code, 0);
    ASSERT_EQ(run("synth " + in + " -o " + q(path("stones.json")) + " --scale 1 -q").code, 0);
    for (const Case& c : std::vector<Case>{
             {"grow " + in + out + " --elements 0", "--elements", 2},
             {"grow " + in + out + " --region box:0,0,0,5", "--region", 2},
             {"grow " + in + out + " --elements 10 --energy-factor 0.5", "--energy-factor", 2},
             {"grow " + in + out, "--region SHAPE or --elements N", 2},
             {"grow " + in + out + " --from " + q(path("dots.json")) + " --elements 10", "type", 3},
             {"grow " + in + out + " --from " + q(path("stones.json")) + " --region box:100,100,110,110", "touch", 3},
         }) {
        SCOPED_TRACE(c.args);
        const Result r = run(c.args);
        EXPECT_EQ(r.code, c.code) << r.err;
        EXPECT_EQ(line_count(r.err), 1) << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
        EXPECT_EQ(work_files(), (std::set<std::string>{"other.json", "dots.json", "stones.json"}));
    }
}
