// `tessera world` end to end: a directory of tiles with an index whose hashes are the tiles',
// the same files for any thread count, --merge into one arrangement, a preview, and one-line
// errors that write nothing.
#include <nlohmann/json.hpp>

#include "cli_fixture.hpp"
#include "tessera/tessera.hpp"

using namespace tessera_cli_test;

class CliWorld : public CliFixture {};

TEST_F(CliWorld, WritesATileDirectoryWithAnIndexOfHashesAndCounts) {
    const std::string dir = path("world"), preview = path("world.png");
    const Result r = run("world " + q(example("two_class_2d.json")) + " --tiles 0:3,0:2 --tile-size 12 -o " + q(dir) +
                         " --preview " + q(preview));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("done: 6 tiles"), std::string::npos) << r.err;
    const nlohmann::json index = nlohmann::json::parse(read_text(dir + "/index.json"));
    EXPECT_EQ(index["format"], "tessera-world");
    EXPECT_EQ(index["tile_size"], 12.0);
    ASSERT_EQ(index["tiles"].size(), 6u);
    std::size_t total = 0;
    for (const auto& t : index["tiles"]) {
        const std::string file = dir + "/" + t["file"].get<std::string>();
        tessera::Arrangement tile;
        static_cast<tessera::Exemplar&>(tile) = tessera::load(file);
        EXPECT_EQ(t["hash"], tessera::tile_hash(tile)) << file;
        EXPECT_EQ(t["elements"], tile.elements.size()) << file;
        const double x0 = t["bounds"]["lo"][0], y0 = t["bounds"]["lo"][1];
        for (const tessera::Element& e : tile.elements) {  // every element in the tile that holds its centre
            EXPECT_GE(e.position.x, x0);
            EXPECT_LT(e.position.x, x0 + 12.0);
            EXPECT_GE(e.position.y, y0);
            EXPECT_LT(e.position.y, y0 + 12.0);
        }
        total += tile.elements.size();
    }
    EXPECT_EQ(index["elements"], total);
    EXPECT_TRUE(is_png(preview));
}

TEST_F(CliWorld, TheSameTilesForAnyThreadCountAndAsOneMergedFile) {
    const std::string world = "world " + q(example("poisson_disk_2d.json")) + " --tile-size 10 --seed 5 -q ";
    ASSERT_EQ(run(world + "--tiles 0:3,0:3 --threads 1 -o " + q(path("one"))).code, 0);
    ASSERT_EQ(run(world + "--tiles 0:3,0:3 --threads 2 -o " + q(path("two"))).code, 0);
    for (const auto& entry : fs::directory_iterator(path("one")))
        EXPECT_EQ(read_text(entry.path()), read_text(path("two") + "/" + entry.path().filename().string()))
            << entry.path().filename();
    // Two ranges that together are the same 3 x 3 tiles give the same tiles.
    ASSERT_EQ(run(world + "--tiles 0:3,0:1 --tiles 0:3,1:3 -o " + q(path("ranges"))).code, 0);
    EXPECT_EQ(read_text(path("one") + "/tile_2_2.json"), read_text(path("ranges") + "/tile_2_2.json"));
    ASSERT_EQ(run(world + "--tiles 0:3,0:3 --merge -o " + q(path("all.csv"))).code, 0);
    const nlohmann::json index = nlohmann::json::parse(read_text(path("one") + "/index.json"));
    EXPECT_EQ(tessera::load(path("all.csv")).elements.size(), index["elements"].get<std::size_t>());
}

TEST_F(CliWorld, MoreOfTheSameWorldJoinsItsIndexAnotherWorldIsRefused) {
    const std::string world = "world " + q(example("poisson_disk_2d.json")) + " --tile-size 10 -q -o " + q(path("w"));
    ASSERT_EQ(run(world + " --tiles 0:2,0:2").code, 0);
    ASSERT_EQ(run(world + " --tiles 2:3,0:2").code, 0);
    const nlohmann::json index = nlohmann::json::parse(read_text(path("w") + "/index.json"));
    EXPECT_EQ(index["tiles"].size(), 6u);
    const std::string before = read_text(path("w") + "/index.json");
    const Result other = run(world + " --tiles 3:4,0:2 --seed 2");
    EXPECT_EQ(other.code, 2);
    EXPECT_NE(other.err.find("another world"), std::string::npos) << other.err;
    EXPECT_EQ(read_text(path("w") + "/index.json"), before);
    EXPECT_FALSE(fs::exists(path("w") + "/tile_3_0.json"));
}

TEST_F(CliWorld, BadInputIsAOneLineErrorAndWritesNothing) {
    const std::string in = q(example("two_class_2d.json")), out = " -o " + q(path("w"));
    struct Case {
        std::string args, message;
    };
    for (const Case& c : std::vector<Case>{
             {"world " + in + out + " --tile-size 12 --tiles 0:0,0:2", "holds no tile"},
             {"world " + in + out + " --tile-size 12 --tiles 0:2,0:2 --tiles 1:3,1:3", "overlap"},
             {"world " + in + out + " --tile-size 12 --tiles 0:2", "X0:X1,Y0:Y1"},
             {"world " + in + out + " --tile-size 12 --tiles 0:2,a:b", "not an integer"},
             {"world " + in + out + " --tile-size 1 --tiles 0:2,0:2", "--tile-size"},
             {"world " + in + " -o " + q(path("w.txt")) + " --merge --tile-size 12 --tiles 0:2,0:2", "-o"},
         }) {
        SCOPED_TRACE(c.args);
        const Result r = run(c.args);
        EXPECT_EQ(r.code, 2) << r.err;
        EXPECT_EQ(line_count(r.err), 1) << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
        EXPECT_TRUE(work_files().empty());
    }
}
