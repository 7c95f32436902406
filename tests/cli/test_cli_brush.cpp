// `tessera brush` end to end: a session file replayed to an arrangement and a picture, the
// same bytes for any thread count, flags overriding the session's options, and one-line
// errors that write nothing.
#include "cli_fixture.hpp"
#include "tessera/tessera.hpp"

using namespace tessera_cli_test;

class CliBrush : public CliFixture {};

TEST_F(CliBrush, ReplaysASessionWithAPreviewTheSameForAnyThreadCount) {
    const std::string session = q(example("brush/design_2d.json"));
    const std::string one = path("one.json"), two = path("two.json"), preview = path("design.png");
    const Result r = run("brush " + session + " -o " + q(one) + " --threads 1 --preview " + q(preview));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("done: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("continuity"), std::string::npos) << r.err;
    ASSERT_EQ(run("brush " + session + " -o " + q(two) + " --threads 2 -q").code, 0);
    EXPECT_EQ(read_text(one), read_text(two));
    EXPECT_TRUE(is_png(preview));
    const tessera::Exemplar out = tessera::load(one);
    EXPECT_GT(out.elements.size(), 500u);
    EXPECT_GE(out.find_type("stick"), 0);
    EXPECT_GE(out.find_type("stone"), 0);
}

TEST_F(CliBrush, BadInputIsAOneLineErrorAndWritesNothing) {
    const std::string out = " -o " + q(path("o.json"));
    const std::string dots = example("poisson_disk_2d.json");
    auto session = [&](const std::string& ops) {
        return R"({"format": "tessera-brush", "canvas": "box:0,0,10,10", "palette": {"dots": ")" + dots +
               R"("}, "ops": )" + ops + "}";
    };
    write("unknown_op.json", session(R"([{"op": "splash"}])"));
    write("unknown_entry.json", session(R"([{"op": "paint", "palette": "leaves", "stroke": [[1, 1]]}])"));
    write("bad_point.json", session(R"([{"op": "direction", "stroke": [[1, 1, 1], [2, 2, 2]]}])"));
    write("not_json.json", "{");
    struct Case {
        std::string args, message;
        int code;
    };
    for (const Case& c : std::vector<Case>{
             {"brush " + q(path("unknown_op.json")) + out, "ops[0].op", 3},
             {"brush " + q(path("unknown_entry.json")) + out, "no palette entry named 'leaves'", 3},
             {"brush " + q(path("bad_point.json")) + out, "ops[0].stroke[0]", 3},
             {"brush " + q(path("not_json.json")) + out, "not valid JSON", 3},
             {"brush " + q(path("missing.json")) + out, "missing.json", 5},
             {"brush " + q(example("brush/design_2d.json")) + out + " --sigma 0", "--sigma", 2},
         }) {
        SCOPED_TRACE(c.args);
        const Result r = run(c.args);
        EXPECT_EQ(r.code, c.code) << r.err;
        EXPECT_EQ(line_count(r.err), 1) << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
        EXPECT_FALSE(std::filesystem::exists(path("o.json")));
    }
}
