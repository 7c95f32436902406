// The "color" of an element type in the native JSON (docs/format.md, "Element types"):
// read as written ("#rrggbb" or a colour name), written back only when set, so files
// without colours stay byte-identical, and refused with the JSON path when unreadable.
#include <gtest/gtest.h>

#include <string>

#include "tessera/error.hpp"
#include "tessera/io.hpp"

using namespace tessera;

namespace {

std::string document(const std::string& types) {
    return R"({"format": "tessera", "version": 1, "dimension": 2,
               "domain": {"type": "box", "min": [0, 0], "max": [4, 4]}, "types": )" +
           types + R"(, "elements": [{"type": "banana", "position": [1, 1]}, {"type": "leaf", "position": [2, 2]}]})";
}

}  // namespace

TEST(JsonColor, ReadAndWrittenBackAsGiven) {
    const Exemplar ex = parse_json(document(R"([{"name": "banana", "color": "#E0B030"},
                                                 {"name": "leaf", "color": "Dark Green"}])"),
                                   "c.json");
    EXPECT_EQ(ex.types[0].color, "#E0B030");
    EXPECT_EQ(ex.types[1].color, "Dark Green");
    const std::string json = to_json(ex);
    EXPECT_NE(json.find(R"("mesh":"","color":"#E0B030")"), std::string::npos) << json;
    const Exemplar again = parse_json(json, "again.json");
    EXPECT_EQ(again.types[0].color, "#E0B030");
    EXPECT_EQ(again.types[1].color, "Dark Green");
    EXPECT_EQ(to_json(again), json);
}

TEST(JsonColor, AbsentColorIsNotWritten) {
    const Exemplar ex = parse_json(document(R"([{"name": "banana"}, {"name": "leaf"}])"), "c.json");
    EXPECT_EQ(ex.types[0].color, "");
    EXPECT_EQ(to_json(ex).find("color"), std::string::npos);
}

TEST(JsonColor, UnreadableColorNamesFileAndPath) {
    for (const std::string bad : {R"("blurple")", R"("#12345")", "12", R"("")"}) {
        SCOPED_TRACE(bad);
        try {
            parse_json(document(R"([{"name": "banana"}, {"name": "leaf", "color": )" + bad + "}]"), "c.json");
            FAIL() << "expected an error";
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::input);
            const std::string what = e.what();
            EXPECT_NE(what.find("c.json"), std::string::npos) << what;
            EXPECT_NE(what.find("types[1].color"), std::string::npos) << what;
        }
    }
}
