// Tests of shaped domains in the native JSON format: a polygon with a hole round
// trips, a mesh file is found relative to the JSON file, and a wrong-dimension
// shape is an error naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tessera/error.hpp"
#include "tessera/io.hpp"

using namespace tessera;

TEST(JsonDomain, PolygonWithHoleRoundTrips) {
    const std::string text = R"({"format": "tessera", "version": 1, "dimension": 2,
        "domain": {"type": "polygon", "outer": [[0,0],[10,0],[10,10],[0,10]], "holes": [[[3,3],[3,7],[7,7],[7,3]]]},
        "elements": [{"type": "a", "position": [1, 1]}]})";
    const Exemplar ex = parse_json(text, "poly.json");
    EXPECT_EQ(ex.domain.kind(), Domain::Kind::polygon);
    EXPECT_DOUBLE_EQ(ex.domain.measure(), 84.0);
    const Exemplar back = parse_json(to_json(ex), "back.json");
    EXPECT_EQ(back.domain.kind(), Domain::Kind::polygon);
    EXPECT_DOUBLE_EQ(back.domain.measure(), 84.0);
    EXPECT_FALSE(back.domain.inside({5, 5, 0}));
}

TEST(JsonDomain, MeshIsRelativeToTheJsonFile) {
    const auto dir = std::filesystem::temp_directory_path() / "tessera_json_domain";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "cube.obj") << "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nv 0 0 2\nv 2 0 2\nv 2 2 2\nv 0 2 2\n"
                                       "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
    const std::string text = R"({"format": "tessera", "version": 1, "dimension": 3,
        "domain": {"type": "mesh", "file": "cube.obj", "resolution": 32},
        "elements": [{"type": "a", "position": [1, 1, 1]}]})";
    const Exemplar ex = parse_json(text, (dir / "scene.json").string());
    EXPECT_EQ(ex.domain.kind(), Domain::Kind::mesh);
    EXPECT_NEAR(ex.domain.measure(), 8.0, 0.5);
    const Exemplar back = parse_json(to_json(ex), "/elsewhere/back.json");
    EXPECT_NEAR(back.domain.measure(), ex.domain.measure(), 1e-12);
    std::filesystem::remove_all(dir);
}

TEST(JsonDomain, PolygonInA3DFileIsAnError) {
    const std::string text = R"({"format": "tessera", "version": 1, "dimension": 3,
        "domain": {"type": "polygon", "outer": [[0,0,0],[1,0,0],[1,1,0]]},
        "elements": [{"type": "a", "position": [1, 1, 1]}]})";
    try {
        parse_json(text, "p3.json");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("p3.json"), std::string::npos) << e.what();
    }
}
