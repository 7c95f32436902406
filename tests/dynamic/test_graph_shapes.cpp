// Graph synthesis of stills with multi-sample elements (dynamic/graph_shapes.hpp): threads
// keep their sample spacing, sheets their grid, rigid elements their shape; elements move
// and do not run into each other; frame 0 is the still; the same bits for any thread count;
// and a still of threads dresses a coarse motion (the paper's Figure 12 case).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "tessera/animation_io.hpp"
#include "tessera/dynamic.hpp"
#include "tessera/error.hpp"
#include "tessera/graph_motion.hpp"
#include "tessera/io.hpp"

namespace {

using namespace tessera;

Exemplar still(const std::string& path) { return load(std::string(TESSERA_SOURCE_DIR) + "/examples/" + path); }

Animation enriched(const Exemplar& s, int threads = 2) {
    GraphMotionOptions o;
    o.threads = threads;
    return enrich_by_graph(s, o);
}

// Largest |length / rest - 1| over the consecutive samples of every element at every frame.
double worst_strain(const Animation& a) {
    double worst = 0.0;
    for (const Element& e : a.structure.elements)
        for (int k = 0; k + 1 < e.sample_count; ++k) {
            const int s = e.first_sample + k;
            const double rest = norm(a.at(0, s + 1) - a.at(0, s));
            for (int f = 1; f < a.frame_count(); ++f)
                worst = std::max(worst, std::abs(norm(a.at(f, s + 1) - a.at(f, s)) / rest - 1.0));
        }
    return worst;
}

// Closest distance between samples of different elements at frame f.
double closest_between_elements(const Animation& a, int f) {
    double best = INFINITY;
    const std::vector<Element>& el = a.structure.elements;
    for (size_t i = 0; i < el.size(); ++i)
        for (size_t j = i + 1; j < el.size(); ++j)
            for (int p = 0; p < el[i].sample_count; ++p)
                for (int q = 0; q < el[j].sample_count; ++q)
                    best = std::min(best, norm(a.at(f, el[i].first_sample + p) - a.at(f, el[j].first_sample + q)));
    return best;
}

// Pairs of segments (consecutive samples) of two different elements that cross at frame f
// (2D): noodles passing through each other between their samples.
int crossings(const Animation& a, int f) {
    const auto side = [](const Vec3& p, const Vec3& q, const Vec3& r) {
        return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
    };
    int count = 0;
    const std::vector<Element>& el = a.structure.elements;
    for (size_t i = 0; i < el.size(); ++i)
        for (size_t j = i + 1; j < el.size(); ++j)
            for (int p = 0; p + 1 < el[i].sample_count; ++p)
                for (int q = 0; q + 1 < el[j].sample_count; ++q) {
                    const Vec3 &a0 = a.at(f, el[i].first_sample + p), &a1 = a.at(f, el[i].first_sample + p + 1);
                    const Vec3 &b0 = a.at(f, el[j].first_sample + q), &b1 = a.at(f, el[j].first_sample + q + 1);
                    count += side(a0, a1, b0) * side(a0, a1, b1) < 0 && side(b0, b1, a0) * side(b0, b1, a1) < 0;
                }
    return count;
}

// Mean displacement of the samples per frame.
double mean_speed(const Animation& a) {
    double travelled = 0.0;
    for (int f = 1; f < a.frame_count(); ++f)
        for (int s = 0; s < a.sample_count(); ++s) travelled += norm(a.at(f, s) - a.at(f - 1, s));
    return travelled / ((a.frame_count() - 1.0) * a.sample_count());
}

TEST(GraphShapes, AStillOfNoodlesMovesWithItsThreadsKeptWhole) {
    const Exemplar noodles = still("noodles_2d.json");
    const Animation a = enriched(noodles);
    ASSERT_EQ(a.frame_count(), 24);
    for (int s = 0; s < a.sample_count(); ++s) ASSERT_EQ(a.at(0, s), noodles.samples[s].p) << "frame 0 is the still";
    const double strain = worst_strain(a), speed = mean_speed(a);
    const double apart = closest_between_elements(a, 0);
    double closest = INFINITY;
    int crossed = 0;
    for (int f = 1; f < a.frame_count(); ++f) {
        closest = std::min(closest, closest_between_elements(a, f));
        crossed += crossings(a, f);
    }
    EXPECT_EQ(crossings(a, 0), 0) << "the still";
    EXPECT_EQ(crossed, 0) << "noodles passing through each other";
    std::printf("noodles by graph synthesis: worst strain %.4f, mean speed %.4f per frame, closest between "
                "noodles %.3f (still %.3f)\n",
                strain, speed, closest, apart);
    EXPECT_LT(strain, 0.05) << "thread samples keep their spacing within 5%";
    EXPECT_GT(speed, 0.01) << "the noodles move";
    EXPECT_GT(closest, 0.3 * apart) << "noodles do not run into each other";
}

TEST(GraphShapes, RigidSticksKeepTheirShapeAndTurn) {
    const Exemplar sticks = still("sticks_2d.json");
    const Animation a = enriched(sticks);
    double worst = 0.0, turned = 0.0;
    for (const Element& e : a.structure.elements) {
        const int first = e.first_sample, last = first + e.sample_count - 1;
        const Vec3 axis0 = a.at(0, last) - a.at(0, first);
        for (int f = 1; f < a.frame_count(); ++f) {
            for (int p = 0; p < e.sample_count; ++p)
                for (int q = p + 1; q < e.sample_count; ++q)
                    worst = std::max(worst, std::abs(norm(a.at(f, first + q) - a.at(f, first + p)) -
                                                     norm(a.at(0, first + q) - a.at(0, first + p))));
            const Vec3 axis = a.at(f, last) - a.at(f, first);
            turned = std::max(turned, std::acos(std::clamp(dot(axis, axis0) / (norm(axis) * norm(axis0)), -1.0, 1.0)));
        }
    }
    EXPECT_LT(worst, 1e-9) << "a rigid element is its own shape at every frame";
    EXPECT_GT(turned, 0.05) << "some stick turns";
}

TEST(GraphShapes, SheetsKeepTheirGridWithoutFlippedQuads) {
    const Exemplar paper = load_animation(std::string(TESSERA_SOURCE_DIR) + "/examples/dynamic/paper_3d.json").frame(0);
    const Animation a = enriched(paper);
    const int columns = a.structure.types[0].sheet_columns;
    int flipped = 0, quads = 0;
    for (int f = 1; f < a.frame_count(); ++f)
        for (const Element& e : a.structure.elements)
            for (int r = 0; r + 1 < e.sample_count / columns; ++r)
                for (int c = 0; c + 1 < columns; ++c) {
                    const int s = e.first_sample + r * columns + c;
                    const auto normal = [&](int frame) {
                        return cross(a.at(frame, s + 1) - a.at(frame, s), a.at(frame, s + columns) - a.at(frame, s));
                    };
                    flipped += dot(normal(f), normal(0)) <= 0.0;
                    ++quads;
                }
    EXPECT_EQ(flipped, 0) << "of " << quads;
    EXPECT_LT(worst_strain(a), 0.05);
    EXPECT_GT(mean_speed(a), 0.0);
}

TEST(GraphShapes, SameBitsForEveryThreadCount) {
    const Exemplar noodles = still("noodles_2d.json");
    EXPECT_TRUE(enriched(noodles, 1).positions == enriched(noodles, 2).positions);
    EXPECT_TRUE(enriched(noodles, 1).positions == enriched(noodles, 3).positions);
}

TEST(GraphShapes, OneElementIsRefused) {
    Exemplar one = still("noodles_2d.json");
    one.elements.resize(1);
    one.samples.resize(one.elements[0].sample_count);
    try {
        enrich_by_graph(one, {});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("at least 2 elements"), std::string::npos) << e.what();
    }
}

// The paper's Figure 12: a still of traced branches, animated. Here the still noodles get
// their detail motion by graph synthesis and dress the swinging coarse noodles.
TEST(GraphShapes, AStillOfThreadsDressesACoarseMotion) {
    const Animation given = animation_from_exemplar(still("noodles_2d.json"));
    const Animation coarse = load_animation(std::string(TESSERA_SOURCE_DIR) + "/examples/dynamic/noodles_coarse_2d.json");
    DynamicOptions o;
    o.threads = 2;
    const AnimatedArrangement out = synthesize_on_coarse(given, coarse, o);
    EXPECT_EQ(out.frame_count(), coarse.frame_count());
    EXPECT_LT(worst_strain(out), 0.05);
    ASSERT_FALSE(out.stats.notes.empty());
    EXPECT_NE(out.stats.notes.front().find("graph synthesis"), std::string::npos) << out.stats.notes.front();
}

}  // namespace
