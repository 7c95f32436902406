// Worlds of deterministic tiles (include/tessera/world.hpp): what a world builder relies on.
// A tile is the same whatever order, thread count or cache it was made with; a world asked
// for tile by tile equals the world made at once; borders show no crowding, no duplicate and
// no change of the pair correlation; class shares hold in every tile; bad input is an error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "quality_data.hpp"
#include "temp_dir.hpp"
#include "tessera/error.hpp"
#include "tessera/tessera.hpp"

using namespace tessera;
using test::example;

namespace {

WorldOptions world_options(double tile_size, int threads = 1) {
    WorldOptions o;
    o.tile_size = tile_size;
    o.grow.threads = threads;
    return o;
}

std::vector<TileCoord> block(int n) {
    std::vector<TileCoord> tiles;
    for (int x = 0; x < n; ++x)
        for (int y = 0; y < n; ++y) tiles.push_back({x, y, 0});
    return tiles;
}

std::map<TileCoord, std::string> texts(World& w, const std::vector<TileCoord>& tiles) {
    std::map<TileCoord, std::string> out;
    for (const TileCoord& t : tiles) out[t] = tile_to_json(w.tile(t));
    return out;
}

Arrangement merged(World& w, const std::vector<TileCoord>& tiles) {
    std::vector<const Arrangement*> parts;
    for (const TileCoord& t : tiles) parts.push_back(&w.tile(t));
    return merge_tiles(parts, w.maker().dimension());
}

// The elements of `a` inside the box, as an arrangement of that window.
Arrangement window(const Arrangement& a, const Vec3& lo, const Vec3& hi) {
    Arrangement out;
    out.dimension = a.dimension;
    out.types = a.types;
    out.domain = Domain::box(lo, hi, a.dimension);
    for (const Element& e : a.elements)
        if (e.position.x >= lo.x && e.position.x < hi.x && e.position.y >= lo.y && e.position.y < hi.y)
            out.add_element(e.type, {e.position}, e.radius);
    return out;
}


// The distance of the closest pair of elements in different tiles of a 2D world.
double closest_pair_across_borders(const Arrangement& all, double tile_size) {
    double across = 1e300;
    for (size_t a = 0; a < all.elements.size(); ++a)
        for (size_t b = a + 1; b < all.elements.size(); ++b) {
            const Vec3 pa = all.elements[a].position, pb = all.elements[b].position;
            if (tile_at(pa, tile_size, 2) != tile_at(pb, tile_size, 2)) across = std::min(across, norm(pa - pb));
        }
    return across;
}

// Rounded to 1e-4: a translated copy made by the same deterministic growth lands on the same
// keys; independent growth does not.
std::string position_key(int type, double x, double y) {
    return std::to_string(type) + ":" + std::to_string(std::llround(x * 1e4)) + "," + std::to_string(std::llround(y * 1e4));
}

// The largest share of a's elements that one translation maps onto elements of b. Candidate
// translations come from pairs of elements with the same nearest-neighbour offset (a copy
// keeps it), so the search is not quadratic in candidates.
double largest_translated_overlap(const Arrangement& a, const Arrangement& b) {
    auto signature = [](const Arrangement& t, size_t i) {
        size_t best = i;
        double best_d = 1e300;
        for (size_t k = 0; k < t.elements.size(); ++k)
            if (k != i) {
                const double d = norm(t.elements[k].position - t.elements[i].position);
                if (d < best_d) best_d = d, best = k;
            }
        const Vec3 v = t.elements[best].position - t.elements[i].position;
        return position_key(t.elements[i].type, v.x, v.y);
    };
    std::set<std::string> in_b;
    std::multimap<std::string, size_t> b_by_signature;
    for (size_t k = 0; k < b.elements.size(); ++k) {
        const Element& e = b.elements[k];
        in_b.insert(position_key(e.type, e.position.x, e.position.y));
        b_by_signature.emplace(signature(b, k), k);
    }
    std::set<std::string> tried;
    size_t best = 0;
    for (size_t i = 0; i < a.elements.size(); ++i) {
        const auto range = b_by_signature.equal_range(signature(a, i));
        for (auto it = range.first; it != range.second; ++it) {
            const Vec3 v = b.elements[it->second].position - a.elements[i].position;
            if (!tried.insert(position_key(0, v.x, v.y)).second) continue;
            size_t hits = 0;
            for (const Element& e : a.elements) hits += in_b.count(position_key(e.type, e.position.x + v.x, e.position.y + v.y));
            best = std::max(best, hits);
        }
    }
    return a.elements.empty() ? 0.0 : static_cast<double>(best) / static_cast<double>(a.elements.size());
}

}  // namespace

TEST(World, PhasesColourTheGridSoThatNoTwoTouchingTilesShareOne) {
    for (const int dim : {2, 3}) {
        const int dz = dim == 3 ? 1 : 0;
        for (std::int64_t x = -3; x <= 3; ++x)
            for (std::int64_t y = -3; y <= 3; ++y)
                for (std::int64_t z = -dz; z <= dz; ++z) {
                    const TileCoord t{x, y, z};
                    EXPECT_LT(tile_phase(t, dim), tile_phases(dim));
                    for (const TileCoord& d : tile_dependencies(t, dim)) {
                        EXPECT_LT(tile_phase(d, dim), tile_phase(t, dim));
                        EXPECT_LE(std::max({std::abs(d.x - t.x), std::abs(d.y - t.y), std::abs(d.z - t.z)}), 1);
                    }
                    for (std::int64_t i = -1; i <= 1; ++i)
                        for (std::int64_t j = -1; j <= 1; ++j)
                            for (std::int64_t k = -dz; k <= dz; ++k)
                                if (i || j || k) {
                                    EXPECT_NE(tile_phase({x + i, y + j, z + k}, dim), tile_phase(t, dim));
                                }
                }
    }
    EXPECT_EQ(tile_dependencies({1, 1, 0}, 2).size(), 8u);  // the last phase waits for all its neighbours
    EXPECT_EQ(tile_dependencies({0, 1, 0}, 3).size(), 8u);  // 3D, Gray order: the 8 of its own layer
    EXPECT_EQ(tile_dependencies({0, 0, 1}, 3).size(), 26u);
    EXPECT_TRUE(tile_dependencies({0, 0, 0}, 2).empty());
    EXPECT_EQ(tile_at({-0.5, 2.5, 0}, 1.0, 2), (TileCoord{-1, 2, 0}));
}

// The phases keep the chains of dependencies short: a range asks for few tiles outside it
// (3D in binary order: 203).
TEST(World, ARangeNeedsFewTilesOutsideIt) {
    std::vector<TileCoord> square, cube;
    for (std::int64_t x = 0; x < 4; ++x)
        for (std::int64_t y = 0; y < 4; ++y) square.push_back({x, y, 0});
    for (std::int64_t x = 0; x < 2; ++x)
        for (std::int64_t y = 0; y < 2; ++y)
            for (std::int64_t z = 0; z < 2; ++z) cube.push_back({x, y, z});
    EXPECT_EQ(tile_closure(square, 2).size(), 37u);
    EXPECT_EQ(tile_closure(cube, 3).size(), 95u);
}

TEST(World, ATileIsTheSameWhateverOrderAndThreadCountItWasMadeIn) {
    const Exemplar ex = example("two_class_2d");
    const std::vector<TileCoord> tiles = block(4);
    World in_order(ex, world_options(12.0, 1));
    const std::map<TileCoord, std::string> reference = texts(in_order, tiles);
    std::vector<TileCoord> shuffled = tiles;
    std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(7));
    World random_order(ex, world_options(12.0, 2));
    const std::map<TileCoord, std::string> other = texts(random_order, shuffled);
    for (const TileCoord& t : tiles) EXPECT_EQ(reference.at(t), other.at(t)) << "tile " << t.describe();
    EXPECT_EQ(in_order.made(), random_order.made());
}

TEST(World, AWorldAskedAroundMovingPointsEqualsTheWorldMadeAtOnce) {
    const Exemplar ex = example("poisson_disk_2d");
    const double size = 10.0;
    World at_once(ex, world_options(size));
    const std::vector<TileCoord> tiles = block(5);
    const Arrangement whole = merged(at_once, tiles);
    World streamed(ex, world_options(size));
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> where(0.0, 5 * size);
    for (int k = 0; k < 6; ++k) streamed.around({where(rng), where(rng), 0.0}, 0.6 * size);
    for (const TileCoord& t : tiles) EXPECT_EQ(tile_to_json(at_once.tile(t)), tile_to_json(streamed.tile(t))) << t.describe();
    EXPECT_EQ(tile_to_json(whole), tile_to_json(merged(streamed, tiles)));
}

TEST(World, FirstPhaseTilesDoNotRepeatEachOther) {
    // Tiles without neighbours start from keyed seeds; growth is deterministic once seeded,
    // so a tile whose seeding repeated another's would be a translated copy of it, a stamp a
    // world builder sees at once. No translation may map more than a patch's worth of one
    // first-phase tile onto another.
    for (const char* name : {"two_class_2d", "poisson_disk_2d", "hex_jittered_2d", "striped_dots_2d", "sticks_2d"}) {
    const Exemplar ex = example(name);
    const TileMaker maker(ex, world_options(12.0));
    std::vector<Arrangement> tiles;
    for (std::int64_t x = 0; x < 8; x += 2)
        for (std::int64_t y = 0; y < 4; y += 2) {
            ASSERT_TRUE(tile_dependencies({x, y, 0}, 2).empty());
            tiles.push_back(maker.make({x, y, 0}, {}));
        }
    double worst = 0.0;
    for (size_t i = 0; i < tiles.size(); ++i)
        for (size_t j = i + 1; j < tiles.size(); ++j)
            worst = std::max(worst, largest_translated_overlap(tiles[i], tiles[j]));
    EXPECT_LT(worst, 0.25) << "a share of one first-phase tile reappears translated in another";
    }
}

TEST(World, TilesMadePhaseByPhaseOnThreadsAreTheTilesMadeOneByOne) {
    const Exemplar ex = example("two_class_2d");
    const std::vector<TileCoord> wanted = {{1, 1, 0}, {2, 1, 0}, {1, 2, 0}, {2, 2, 0}};
    const std::vector<TileCoord> closure = tile_closure(wanted, 2);
    for (const TileCoord& t : closure)  // closed under dependencies, in phase order
        for (const TileCoord& d : tile_dependencies(t, 2)) {
            const auto at = std::find(closure.begin(), closure.end(), d);
            ASSERT_NE(at, closure.end()) << d.describe();
            EXPECT_LT(at - closure.begin(), std::find(closure.begin(), closure.end(), t) - closure.begin());
        }
    World one_by_one(ex, world_options(12.0));
    const TileMaker maker(ex, world_options(12.0));
    for (const int threads : {1, 2}) {
        const std::map<TileCoord, Arrangement> tiles = make_tiles(maker, wanted, threads);
        EXPECT_EQ(tiles.size(), closure.size());
        for (const TileCoord& t : closure) EXPECT_EQ(tile_to_json(tiles.at(t)), tile_to_json(one_by_one.tile(t))) << t.describe();
    }
    int calls = 0;
    EXPECT_THROW(make_tiles(maker, wanted, 1, [&](const ProgressEvent& e) { EXPECT_EQ(e.stage, "tile"); return ++calls < 3; }),
                 Cancelled);
    EXPECT_EQ(calls, 3);
}

class WorldCache : public test::TempDirTest {};

TEST_F(WorldCache, TilesReadBackFromTheCacheAreTheTilesMade) {
    const Exemplar ex = example("sticks_2d");
    const std::vector<TileCoord> tiles = block(3);
    std::map<TileCoord, std::string> first;
    {
        World w(ex, world_options(12.0), path("cache"));
        first = texts(w, tiles);
        EXPECT_GT(w.made(), 0);
    }
    World again(ex, world_options(12.0), path("cache"));
    EXPECT_EQ(texts(again, tiles), first);
    EXPECT_EQ(again.made(), 0) << "every tile should have been read from the cache";
    WorldOptions other = world_options(12.0);
    other.grow.seed = 2;
    EXPECT_THROW(World(ex, other, path("cache")), Error);  // the cache holds another world
}

TEST(World, ElementsBelongToOneTileAndKeepTheirShapesAcrossBorders) {
    const Exemplar ex = example("sticks_2d");
    World w(ex, world_options(12.0));
    for (const TileCoord& t : block(3)) {
        const Arrangement& a = w.tile(t);
        for (const Element& e : a.elements) EXPECT_EQ(tile_at(e.position, 12.0, 2), t);
    }
    const Arrangement all = merged(w, block(3));
    test::expect_no_crowding(ex, all, "sticks over 3 x 3 tiles");
    std::set<std::pair<double, double>> places;
    for (const Element& e : all.elements) EXPECT_TRUE(places.insert({e.position.x, e.position.y}).second);
}

TEST(World, BordersKeepThePairCorrelationAndNoPairCrowdsAcrossThem) {
    const Exemplar ex = example("poisson_disk_2d");
    const double size = 12.0, half = 4.0;
    World w(ex, world_options(size));
    const std::vector<TileCoord> tiles = block(4);
    const Arrangement all = merged(w, tiles);
    // Windows centred on the inner tile corners against windows centred in the tiles.
    double corner_error = 0.0, inside_error = 0.0;
    int corners = 0, insides = 0;
    for (int i = 1; i < 4; ++i)
        for (int j = 1; j < 4; ++j) {
            const Vec3 c{i * size, j * size, 0}, m{(i - 0.5) * size, (j - 0.5) * size, 0};
            corner_error += pcf_relative_error(ex, window(all, c - Vec3{half, half, 0}, c + Vec3{half, half, 0}));
            inside_error += pcf_relative_error(ex, window(all, m - Vec3{half, half, 0}, m + Vec3{half, half, 0}));
            ++corners, ++insides;
        }
    corner_error /= corners, inside_error /= insides;
    EXPECT_LE(corner_error, 1.25 * inside_error + 0.01) << "corners " << corner_error << ", inside " << inside_error;
    // The closest pair across a border is no closer than the exemplar's closest pair allows.
    const double closest = nearest_neighbor_distances(ex).min;
    const double across = closest_pair_across_borders(all, size);
    EXPECT_GE(across, 0.95 * closest) << "closest pair across a border " << across << ", exemplar " << closest;
    test::expect_no_crowding(ex, all, "Poisson disks over 4 x 4 tiles");
    EXPECT_LE(largest_empty_circle(window(all, {size * 0.5, size * 0.5, 0}, {size * 3.5, size * 3.5, 0})).radius,
              1.3 * largest_empty_circle(ex).radius);
}

// A random pattern's holes run deeper than a hard-core pattern's, and a tile's rounds fill
// only enclosed ones; the covered pass fills those closed toward the tile's faces too (a
// 4 x 4 world of Japanese pines kept one 1.9x the exemplar's largest inside a tile).
TEST(World, ARandomPatternsTilesLeaveNoDeepHoleInside) {
    const Exemplar ex = test::field_pattern("japanesepines");
    const double size = ex.domain.bounds().size().x;
    World w(ex, world_options(size, 2));
    const Arrangement all = merged(w, block(4));
    // Away from the world's outer faces (open toward tiles not made).
    const Arrangement inner = window(all, {size * 0.5, size * 0.5, 0}, {size * 3.5, size * 3.5, 0});
    EXPECT_LE(largest_empty_circle(inner).radius, 1.3 * largest_empty_circle(ex).radius);
    test::expect_no_crowding(ex, all, "Japanese pines over 4 x 4 tiles");
}

// Growth overfills an inhibited pattern in every tile (the cells: 1.15x their density over a
// 4 x 4-tile world); a tile's count is final once it is made, and it is thinned to its share.
TEST(World, AnInhibitedPatternsTilesKeepItsDensity) {
    for (const char* name : {"cells", "swedishpines"}) {
        const Exemplar ex = test::field_pattern(name);
        const double size = ex.domain.bounds().size().x;
        World w(ex, world_options(size, 2));
        const Arrangement all = merged(w, block(4));
        const double ratio = (all.elements.size() / (16 * size * size)) / (ex.elements.size() / ex.domain.measure());
        EXPECT_LT(ratio, 1.06) << name << ": " << all.elements.size() << " elements";
        EXPECT_GT(ratio, 0.94) << name << ": " << all.elements.size() << " elements";
        test::expect_no_crowding(ex, all, name);
    }
}

TEST(World, EveryTileKeepsTheClassShares) {
    const Exemplar ex = example("striped_dots_2d");
    World w(ex, world_options(14.0));
    double exemplar_share = 0.0;
    for (const Element& e : ex.elements) exemplar_share += e.type == 0 ? 1.0 / ex.elements.size() : 0.0;
    for (const TileCoord& t : block(3)) {
        const Arrangement& a = w.tile(t);
        double share = 0.0;
        for (const Element& e : a.elements) share += e.type == 0 ? 1.0 / a.elements.size() : 0.0;
        const double noise = std::sqrt(exemplar_share * (1 - exemplar_share) / a.elements.size());
        EXPECT_NEAR(share, exemplar_share, 0.02 + 3.0 * noise) << "tile " << t.describe() << " of " << a.elements.size();
    }
}

// A first-phase tile is grown with nothing beyond its borders: its minority type (the
// two-class stones, completed by growth's step 6) must not line those borders, or the
// later tiles' seams are left without any.
TEST(World, FirstPhaseTilesDoNotLineTheirBordersWithTheMinorityType) {
    const Exemplar ex = example("two_class_2d");
    const double size = 12.0, band = 1.0;
    World w(ex, world_options(size, 2));
    int stones_near = 0, stones = 0;
    for (int x = 0; x < 6; x += 2)
        for (int y = 0; y < 6; y += 2) {  // 9 tiles of phase 0
            for (const Element& e : w.tile({x, y, 0}).elements) {
                if (ex.types[e.type].name != "stone") continue;
                const double u = e.position.x - x * size, v = e.position.y - y * size;
                ++stones;
                stones_near += std::min({u, v, size - u, size - v}) < band;
            }
        }
    const double band_area = size * size - (size - 2 * band) * (size - 2 * band);
    const double near_density = stones_near / (9 * band_area), density = stones / (9 * size * size);
    // 1.34 before the open faces counted in the completion's clearance; noise about 0.11.
    EXPECT_LT(near_density, 1.25 * density) << stones_near << " of " << stones << " stones within " << band;
    EXPECT_GT(near_density, 0.75 * density) << stones_near << " of " << stones << " stones within " << band;
}

TEST(World, ThreeDimensionalTilesMeetWithoutCrowding) {
    const Exemplar ex = example("spheres_3d");
    World w(ex, world_options(1.2 * TileMaker(ex, world_options(100.0)).min_tile_size()));
    std::vector<const Arrangement*> parts;
    for (std::int64_t x = 0; x < 2; ++x)
        for (std::int64_t y = 0; y < 2; ++y)
            for (std::int64_t z = 0; z < 2; ++z) parts.push_back(&w.tile({x, y, z}));
    const Arrangement all = merge_tiles(parts, 3);
    EXPECT_GT(all.elements.size(), 0u);
    test::expect_no_crowding(ex, all, "spheres over 2 x 2 x 2 tiles");
}

TEST(World, BadInputIsAClearError) {
    const Exemplar ex = example("poisson_disk_2d");
    auto message = [](auto&& f) {
        try {
            f();
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message([&] { TileMaker(ex, world_options(0.0)); }).find("tile_size"), std::string::npos);
    EXPECT_NE(message([&] { TileMaker(ex, world_options(1.0)); }).find("smaller than the neighbourhood"), std::string::npos);
    const TileMaker maker(ex, world_options(10.0));
    EXPECT_NE(message([&] { maker.make({1, 0, 0}, {}); }).find("is not given"), std::string::npos);
    const Arrangement t00 = maker.make({0, 0, 0}, {});
    EXPECT_NE(message([&] { maker.make({1, 0, 0}, {{{0, 0, 0}, &t00}, {{0, 0, 0}, &t00}}); }).find("tile"),
              std::string::npos);
    EXPECT_NE(message([&] { maker.make({0, 0, 1}, {}); }).find("z = 0"), std::string::npos);
}

// ---- tiles made by the PCF method -------------------------------------------------------

static WorldOptions pcf_world_options(double tile_size, int threads = 1) {
    WorldOptions o = world_options(tile_size);
    o.method = WorldMethod::pcf;
    o.pcf.threads = threads;
    return o;
}

TEST(WorldPcf, TilesKeepTheDensityAndThePairCorrelationAcrossBorders) {
    const Exemplar ex = example("poisson_disk_2d");
    const double size = 12.0, half = 4.0;
    World w(ex, pcf_world_options(size));
    const Arrangement all = merged(w, block(3));
    const double expected = ex.elements.size() / ex.domain.measure() * 9 * size * size;
    EXPECT_NEAR(all.elements.size(), expected, 0.03 * expected);
    double corner_error = 0.0, inside_error = 0.0;
    for (int i = 1; i < 3; ++i)
        for (int j = 1; j < 3; ++j) {
            const Vec3 c{i * size, j * size, 0};
            corner_error += pcf_relative_error(ex, window(all, c - Vec3{half, half, 0}, c + Vec3{half, half, 0})) / 4;
        }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const Vec3 m{(i + 0.5) * size, (j + 0.5) * size, 0};
            inside_error += pcf_relative_error(ex, window(all, m - Vec3{half, half, 0}, m + Vec3{half, half, 0})) / 9;
        }
    EXPECT_LE(corner_error, 1.25 * inside_error + 0.01) << "corners " << corner_error << ", inside " << inside_error;
    const double closest = nearest_neighbor_distances(ex).min;
    const double across = closest_pair_across_borders(all, size);
    EXPECT_GE(across, 0.95 * closest) << "closest pair across a border " << across << ", exemplar " << closest;
    test::expect_no_crowding(ex, all, "PCF Poisson disks over 3 x 3 tiles");
}

TEST(WorldPcf, ATileIsTheSameWhateverTheOrderAndTheThreads) {
    const Exemplar ex = example("poisson_disk_2d");
    World in_order(ex, pcf_world_options(10.0, 1));
    World shuffled(ex, pcf_world_options(10.0, 2));
    std::vector<TileCoord> tiles = block(3);
    const auto reference = texts(in_order, tiles);
    std::shuffle(tiles.begin(), tiles.end(), std::mt19937(11));
    for (const TileCoord& t : tiles) EXPECT_EQ(tile_to_json(shuffled.tile(t)), reference.at(t)) << t.describe();
}

TEST(WorldPcf, ThreeDimensionalExemplarsAreRefused) {
    try {
        TileMaker(example("spheres_3d"), pcf_world_options(10.0));
        FAIL() << "a 3D PCF world was accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::option);
        EXPECT_NE(std::string(e.what()).find("method: the PCF method makes 2D worlds"), std::string::npos) << e.what();
    }
}
