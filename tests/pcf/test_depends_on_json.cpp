// Tests of the exemplar JSON's "depends_on" for element types (docs/format.md): read,
// written back only when set (an empty list included), and unknown names rejected with
// the type named.
#include <gtest/gtest.h>

#include "tessera/error.hpp"
#include "tessera/io.hpp"
#include "tessera/pcf_synthesis.hpp"

using namespace tessera;

namespace {

std::string document(const std::string& types) {
    return R"({"format": "tessera", "version": 1, "dimension": 2,
               "domain": {"type": "box", "min": [0, 0], "max": [10, 10]},
               "types": )" + types + R"(,
               "elements": [{"type": "tree", "position": [1, 1]}, {"type": "tree", "position": [5, 5]},
                            {"type": "shrub", "position": [2, 1]}, {"type": "shrub", "position": [7, 3]},
                            {"type": "grass", "position": [4, 8]}, {"type": "grass", "position": [8, 8]}]})";
}

}  // namespace

TEST(PcfDependsOnJson, ReadAndWrittenBack) {
    const Exemplar ex = parse_json(document(R"([{"name": "grass", "depends_on": ["tree"]},
        {"name": "tree", "depends_on": []}, {"name": "shrub"}])"), "ex.json");
    ASSERT_EQ(ex.types.size(), 3u);
    ASSERT_TRUE(ex.types[0].depends_on);
    EXPECT_EQ(*ex.types[0].depends_on, std::vector<std::string>{"tree"});
    ASSERT_TRUE(ex.types[1].depends_on);
    EXPECT_TRUE(ex.types[1].depends_on->empty());
    EXPECT_FALSE(ex.types[2].depends_on);
    const std::string text = to_json(ex);
    EXPECT_NE(text.find("\"depends_on\":[\"tree\"]"), std::string::npos) << text;
    EXPECT_NE(text.find("\"depends_on\":[]"), std::string::npos) << text;
    const Exemplar back = parse_json(text, "back.json");
    for (size_t t = 0; t < 3; ++t) EXPECT_EQ(back.types[t].depends_on, ex.types[t].depends_on);
    EXPECT_EQ(to_json(back), text);
    // The analysis follows the file's graph: grass on tree, tree on nothing, shrub on both earlier.
    const PcfModel m = analyze_distribution(ex);
    EXPECT_EQ(m.parents, (std::vector<std::vector<int>>{{1}, {}, {0, 1}}));
    EXPECT_EQ(m.order, (std::vector<int>{1, 0, 2}));
}

TEST(PcfDependsOnJson, UnknownNameIsAnInputErrorNamingTheType) {
    try {
        parse_json(document(R"([{"name": "grass", "depends_on": ["rock"]}, {"name": "tree"}, {"name": "shrub"}])"),
                   "ex.json");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::input);
        const std::string m = e.what();
        EXPECT_NE(m.find("ex.json"), std::string::npos) << m;
        EXPECT_NE(m.find("types[0].depends_on[0]"), std::string::npos) << m;
        EXPECT_NE(m.find("'grass'"), std::string::npos) << m;
        EXPECT_NE(m.find("'rock'"), std::string::npos) << m;
    }
    EXPECT_THROW(parse_json(document(R"([{"name": "grass", "depends_on": "tree"}, {"name": "tree"}, {"name": "shrub"}])"),
                            "ex.json"),
                 Error);
    EXPECT_THROW(parse_json(document(R"([{"name": "grass", "depends_on": ["tree", "tree"]}, {"name": "tree"},
                                         {"name": "shrub"}])"),
                            "ex.json"),
                 Error);
}
