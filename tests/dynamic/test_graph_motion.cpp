// Graph synthesis (section 4.3): motion paths minimise Eq. 13 and run from s_a to s_b; the
// spline blend interpolates the nodes; the enriched animation starts at the still, keeps its
// spacing, moves smoothly and visibly, the same bits for any thread count; bad options are
// refused by name; synthesize_dynamic runs it on a one-frame exemplar.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/rng.hpp"
#include "dynamic/dynamic_fixtures.hpp"
#include "dynamic/graph_nodes.hpp"
#include "dynamic/graph_path.hpp"
#include "dynamic/path_blend.hpp"
#include "tessera/animation_io.hpp"
#include "tessera/dynamic.hpp"
#include "tessera/error.hpp"
#include "tessera/graph_motion.hpp"
#include "tessera/io.hpp"
#include "tessera/metrics.hpp"

namespace {

using namespace tessera;
using namespace tessera::dynamic;

Exemplar poisson_still() {
    static const Exemplar still = load(std::string(TESSERA_SOURCE_DIR) + "/examples/poisson_disk_2d.json");
    return still;
}

// The graph of the still as enrich_by_graph builds it with the default options.
struct StillGraph {
    Animation animation;
    StParams params;
    InputFrames frames;
    NeighbourhoodGraph graph;

    static StParams params_of(const Exemplar& still) {
        StParams p;
        p.temporal = 1;
        p.spacing = nearest_neighbor_distances(still, 1).mean;
        p.radius = 1.5 * p.spacing;
        p.input_radius = p.radius + p.spacing;
        p.cap2 = p.alpha = p.spacing * p.spacing;
        return p;
    }
    explicit StillGraph(const Exemplar& still)
        : animation(animation_from_exemplar(still)),
          params(params_of(still)),
          frames(animation, params, 2),
          graph(frames, params, 512, 8, 1, 2) {}
};

const StillGraph& still_graph() {
    static const StillGraph g(poisson_still());
    return g;
}

double closest_pair(const Exemplar& e) { return nearest_neighbor_distances(e, 1).min; }

TEST(GraphMotion, Eq13IsTheSmoothStepsPlusTheDiversityTerm) {
    const NeighbourhoodGraph& g = still_graph().graph;
    const std::vector<int> path{0, 5, 9};
    const double d01 = g.weight(0, 5), d12 = g.weight(5, 9), d02 = g.weight(0, 9), delta = g.delta();
    // n = 2: ordered pairs i != j are 6 = n (n + 1).
    const double expected = (d01 + d12) / delta + 0.5 * (1.0 - 2.0 * (d01 + d12 + d02) / (delta * 2 * 3));
    EXPECT_NEAR(path_energy(g, path, 0.5), expected, 1e-12);
    EXPECT_GT(delta, 0.0);
    EXPECT_DOUBLE_EQ(g.weight(0, 5), g.weight(5, 0));
}

TEST(GraphMotion, PathsRunFromTheSampleToItsFarthestImmediateNeighbour) {
    const NeighbourhoodGraph& g = still_graph().graph;
    const AnnealSettings settings;
    for (int a = 0; a < g.samples(); ++a) {
        const std::vector<int>& near = g.nearest(a);
        ASSERT_EQ(near.size(), 8u);
        // s_b: of the k nearest nodes, the one with the largest edge weight.
        for (int b : near) EXPECT_LE(g.weight(a, b), g.weight(a, g.far_neighbour(a)));
        const MotionPath p = anneal_path(g, a, settings);
        ASSERT_GE(p.nodes.size(), 2u);
        EXPECT_EQ(p.nodes.front(), a);
        EXPECT_EQ(p.nodes.back(), g.far_neighbour(a));
        EXPECT_LE(static_cast<int>(p.nodes.size()) - 1, settings.max_steps);
        std::vector<int> sorted = p.nodes;
        std::sort(sorted.begin(), sorted.end());
        EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << "a node twice on path " << a;
        EXPECT_NEAR(p.energy, path_energy(g, p.nodes, settings.alpha), 1e-12);
    }
}

// Random paths a -> s_b of `steps` steps through distinct nodes drawn from the whole graph.
double best_random_energy(const NeighbourhoodGraph& g, int a, int steps, int tries) {
    const core::KeyedRng rng(7, core::Purpose::test, static_cast<std::uint64_t>(a));
    std::uint64_t counter = 0;
    const int b = g.far_neighbour(a);
    double best = std::numeric_limits<double>::infinity();
    for (int t = 0; t < tries; ++t) {
        std::vector<int> path{a};
        while (static_cast<int>(path.size()) < steps) {
            const int node = g.nodes()[rng.below(counter++, g.nodes().size())];
            if (node != b && std::find(path.begin(), path.end(), node) == path.end()) path.push_back(node);
        }
        path.push_back(b);
        best = std::min(best, path_energy(g, path, 0.5));
    }
    return best;
}

TEST(GraphMotion, AnnealedPathsHaveLowerEnergyThanRandomPathsOfTheirLength) {
    const NeighbourhoodGraph& g = still_graph().graph;
    double annealed = 0.0, random = 0.0, direct = 0.0;
    int below_random = 0;
    for (int a = 0; a < g.samples(); ++a) {
        const MotionPath p = anneal_path(g, a, AnnealSettings{});
        ASSERT_EQ(p.nodes.size(), 7u);  // n = 6, fixed
        const double r = best_random_energy(g, a, 6, 200);
        below_random += p.energy < r ? 1 : 0;
        annealed += p.energy, random += r, direct += p.direct_energy;
    }
    const int n = g.samples();
    std::printf("Eq. 13 means over %d paths of 6 steps: annealed %.4f, best of 200 random %.4f (direct path, 1 "
                "step: %.4f); annealed below the best random for %d\n",
                n, annealed / n, random / n, direct / n, below_random);
    EXPECT_LT(annealed, 0.8 * random);
    EXPECT_GE(below_random, 0.95 * n);
}

// A still whose spacing grows smoothly along x (0.7 to 1.3 over 40 columns, 8 rows): its
// neighbourhoods change gradually, so nodes lie between s_a and s_b and a path through them
// is smoother than the direct step. With free lengths the annealing must find them.
Exemplar graded_still() {
    Exemplar ex;
    const int type = ex.type_index("dot");
    const core::KeyedRng rng(11, core::Purpose::test);
    std::uint64_t c = 0;
    double x = 0.0;
    for (int i = 0; i < 40; ++i, x += 0.7 + 0.6 * i / 39.0)
        for (int j = 0; j < 8; ++j)
            ex.add_element(type, {{x + 0.02 * (rng.uniform(c++) - 0.5), 0.9 * j + 0.02 * (rng.uniform(c++) - 0.5), 0}});
    ex.domain = Domain::box({-0.5, -0.5, 0}, {x + 0.5, 7.0, 0}, 2);
    return ex;
}

TEST(GraphMotion, WithFreeLengthsTheAnnealingBeatsTheDirectPathWhereNodesLieBetween) {
    const Exemplar still = graded_still();
    const Animation animation = animation_from_exemplar(still);
    const StParams params = StillGraph::params_of(still);
    const InputFrames frames(animation, params, 2);
    const NeighbourhoodGraph g(frames, params, 512, 24, 1, 2);
    AnnealSettings free;
    free.min_steps = 1;
    int below = 0;
    double annealed = 0.0, direct = 0.0, steps = 0.0;
    for (int a = 0; a < g.samples(); ++a) {
        const MotionPath p = anneal_path(g, a, free);
        EXPECT_LE(p.energy, p.direct_energy + 1e-12);
        below += p.energy < p.direct_energy - 1e-9 ? 1 : 0;
        annealed += p.energy, direct += p.direct_energy;
        steps += static_cast<double>(p.nodes.size() - 1);
    }
    std::printf("graded still, free lengths: Eq. 13 means annealed %.4f, direct %.4f (alpha %.1f); below direct for %d "
                "of %d; %.2f steps on average\n",
                annealed / g.samples(), direct / g.samples(), free.alpha, below, g.samples(), steps / g.samples());
    EXPECT_GE(below, 0.75 * g.samples());
    // Eq. 13 is alpha plus a small excess here (delta is set by the cut neighbourhoods at the
    // box's edge): the paths at least halve the direct step's excess.
    EXPECT_LT(annealed / g.samples() - free.alpha, 0.5 * (direct / g.samples() - free.alpha));
}

TEST(GraphMotion, SplineBlendPassesThroughTheNodesAndKeepsLinesStraight) {
    for (int nodes : {1, 2, 3, 5, 7, 17}) {
        const SplineBlend spline(nodes);
        std::vector<double> w(nodes);
        for (int i = 0; i < nodes; ++i) {
            spline.weights(i, w.data());
            for (int j = 0; j < nodes; ++j) EXPECT_NEAR(w[j], i == j ? 1.0 : 0.0, 1e-12) << nodes << " " << i << " " << j;
        }
        for (double u = 0.0; u <= nodes - 1; u += 0.125) {
            spline.weights(u, w.data());
            EXPECT_NEAR(std::accumulate(w.begin(), w.end(), 0.0), 1.0, 1e-12);
            // Linear data (d_j = 3 j + 1) come out linear: the natural ends add no curvature.
            double value = 0.0;
            for (int j = 0; j < nodes; ++j) value += w[j] * (3.0 * j + 1.0);
            if (nodes > 1) {
                EXPECT_NEAR(value, 3.0 * u + 1.0, 1e-12) << nodes << " at " << u;
            }
        }
    }
}

TEST(GraphMotion, TracksFollowPairedEntriesOfEachNode) {
    const StillGraph& s = still_graph();
    MetricScratch scratch;
    int paired = 0, total = 0;
    for (int a = 0; a < s.graph.samples(); a += 7) {
        const MotionPath p = anneal_path(s.graph, a, AnnealSettings{});
        const StNeighbourhood own = spatial_neighbourhood(s.frames, a, s.params.radius);
        const PathTracks t = path_tracks(s.frames, own, p.nodes, s.params, scratch);
        ASSERT_EQ(t.tracks(), static_cast<int>(own.entries.size()));
        for (int k = 0; k < t.tracks(); ++k) {
            EXPECT_EQ(t.neighbour[k], own.entries[k].sample);
            EXPECT_EQ(t.offset[k * t.nodes], own.entries[k].offset);
        }
        // At each node a track is on one of the node's entries or at its place in the still,
        // never two on one entry, and never further than a spacing from that place (the
        // pairing's cap), so consecutive nodes move it by less than two.
        for (int i = 1; i < t.nodes; ++i) {
            const int id = s.frames.id(p.nodes[i], 0);
            const StEntry* node = s.frames.entries(id);
            const int count = s.frames.group_start(id)[1];
            std::vector<int> used;
            for (int k = 0; k < t.tracks(); ++k) {
                const Vec3 o = t.offset[k * t.nodes + i], rest = own.entries[k].offset;
                ++total;
                for (int e = 0; e < count; ++e)
                    if (node[e].offset == o && o != rest) used.push_back(e), ++paired;
                EXPECT_LT(norm(o - rest), s.params.spacing);
            }
            std::sort(used.begin(), used.end());
            EXPECT_EQ(std::adjacent_find(used.begin(), used.end()), used.end());
        }
    }
    EXPECT_GT(paired, total / 2);  // most neighbours do move with the nodes
}

// --- The enriched animation ---

const Animation& enriched(int threads = 2) {
    static std::vector<Animation> made(4);
    if (made[threads].positions.empty()) {
        GraphMotionOptions o;
        o.threads = threads;
        made[threads] = enrich_by_graph(poisson_still(), o);
    }
    return made[threads];
}

TEST(GraphMotion, FrameZeroIsTheStill) {
    const Exemplar still = poisson_still();
    const Animation& a = enriched();
    ASSERT_EQ(a.frame_count(), 24);
    ASSERT_EQ(a.sample_count(), static_cast<int>(still.samples.size()));
    for (int s = 0; s < a.sample_count(); ++s) EXPECT_EQ(a.at(0, s), still.samples[s].p);
    EXPECT_EQ(a.times[1] - a.times[0], 1.0);  // as a one-frame exemplar's output frames
    for (size_t e = 0; e < still.elements.size(); ++e) EXPECT_EQ(a.structure.elements[e].id, still.elements[e].id);
}

TEST(GraphMotion, EveryFrameKeepsTheStillsSpacing) {
    const Exemplar still = poisson_still();
    const NearestNeighborStats in = nearest_neighbor_distances(still, 1);
    const Animation& a = enriched();
    for (int f = 1; f < a.frame_count(); ++f) {
        const Exemplar frame = a.frame(f);
        const NearestNeighborStats out = nearest_neighbor_distances(frame, 1);
        EXPECT_NEAR(out.mean, in.mean, 0.1 * in.mean) << "frame " << f;
        EXPECT_LT(out.stddev, 2.0 * in.stddev + 0.05 * in.mean) << "frame " << f;
        EXPECT_GT(out.min, 0.5 * in.min) << "frame " << f;  // no collapse, no overlap
        for (const Sample& s : frame.samples) EXPECT_TRUE(still.domain.inside(s.p)) << "frame " << f;
    }
}

TEST(GraphMotion, MotionIsVisibleAndSmooth) {
    const Animation& a = enriched();
    const double spacing = nearest_neighbor_distances(poisson_still(), 1).mean;
    double speed = 0.0, acceleration = 0.0, farthest = 0.0;
    int moving = 0;
    for (int s = 0; s < a.sample_count(); ++s) {
        double away = 0.0;
        for (int f = 1; f < a.frame_count(); ++f) {
            speed += norm(a.at(f, s) - a.at(f - 1, s));
            if (f >= 2) acceleration += norm(a.at(f, s) - 2.0 * a.at(f - 1, s) + a.at(f - 2, s));
            away = std::max(away, norm(a.at(f, s) - a.at(0, s)));
        }
        farthest = std::max(farthest, away);
        moving += away > 0.05 * spacing ? 1 : 0;
    }
    speed /= a.sample_count() * (a.frame_count() - 1.0);
    acceleration /= a.sample_count() * (a.frame_count() - 2.0);
    std::printf("graph motion: mean speed %.4f spacings/frame, mean |acceleration| / mean speed %.3f, %d of %d "
                "samples leave their place by > 0.05 spacing, the farthest by %.3f spacing\n",
                speed / spacing, acceleration / speed, moving, a.sample_count(), farthest / spacing);
    EXPECT_GT(speed, 0.005 * spacing);
    EXPECT_GT(moving, a.sample_count() / 2);
    // Random jitter gives |a| / |v| of 1.4 (a random walk) to 1.7 (independent positions); the
    // spline through 7 nodes in 24 frames about 0.55.
    EXPECT_LT(acceleration, 0.75 * speed);
}

TEST(GraphMotion, SameBitsForEveryThreadCount) {
    EXPECT_TRUE(enriched(1).positions == enriched(2).positions);
    EXPECT_TRUE(enriched(1).positions == enriched(3).positions);
}

TEST(GraphMotion, BadOptionsAreRefusedByName) {
    const auto message = [](const GraphMotionOptions& o) {
        try {
            enrich_by_graph(poisson_still(), o);
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::option);
            return std::string(e.what());
        }
        return std::string("no error");
    };
    GraphMotionOptions o;
    o.frames = 1;
    EXPECT_EQ(message(o).rfind("frames must be", 0), 0u) << message(o);
    o = {}, o.path_length = 0;
    EXPECT_EQ(message(o).rfind("path_length must be", 0), 0u) << message(o);
    o = {}, o.alpha = -1;
    EXPECT_EQ(message(o).rfind("alpha must be", 0), 0u) << message(o);
    o = {}, o.neighbours = 0;
    EXPECT_EQ(message(o).rfind("neighbours must be", 0), 0u) << message(o);
    o = {}, o.anneal_iterations = 0;
    EXPECT_EQ(message(o).rfind("anneal_iterations must be", 0), 0u) << message(o);
    o = {}, o.sweeps = 0;
    EXPECT_EQ(message(o).rfind("sweeps must be", 0), 0u) << message(o);
    o = {}, o.radius = -1;
    EXPECT_EQ(message(o).rfind("radius must be", 0), 0u) << message(o);
    o = {}, o.frames = 0;
    EXPECT_EQ(message(o).find('\n'), std::string::npos);

    DynamicOptions d;
    d.graph_frames = 1;
    try {
        synthesize_dynamic(animation_from_exemplar(poisson_still()), poisson_still().domain, d);
        ADD_FAILURE() << "graph_frames 1 accepted";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "graph_frames must be -1 (automatic), 0 (off) or an integer >= 2, got 1");
    }
}

TEST(GraphMotion, ThreeDimensionalStillMovesWithoutCollapse) {
    const Exemplar ex = dynamic_test::jittered_cubic_lattice(5, 0.3);
    GraphMotionOptions o;
    o.frames = 12;
    const Animation a = enrich_by_graph(ex, o);
    const double closest = closest_pair(ex);
    double moved = 0.0;
    for (int f = 1; f < a.frame_count(); ++f) {
        EXPECT_GT(closest_pair(a.frame(f)), 0.5 * closest) << "frame " << f;
        for (int s = 0; s < a.sample_count(); ++s) moved = std::max(moved, norm(a.at(f, s) - a.at(0, s)));
    }
    EXPECT_GT(moved, 0.05);
}

// Paths chained end to end: a long enrichment keeps the pace of a short one (one path
// stretched over 96 frames walked a quarter as fast) and the still's spacing.
TEST(GraphMotion, ALongEnrichmentChainsPathsAndKeepsItsPace) {
    const Exemplar still = poisson_still();
    GraphMotionOptions o;
    o.threads = 2;
    o.frames = 96;
    GraphMotionStats stats;
    const Animation a = enrich_by_graph(still, o, &stats);
    const Animation& short_one = enriched();
    const auto pace = [](const Animation& x) {
        double travelled = 0.0;
        for (int f = 1; f < x.frame_count(); ++f)
            for (int s = 0; s < x.sample_count(); ++s) travelled += norm(x.at(f, s) - x.at(f - 1, s));
        return travelled / ((x.frame_count() - 1.0) * x.sample_count());
    };
    EXPECT_NEAR(stats.path_steps, 24.0, 1.0) << "4 chained paths of 6 steps";
    EXPECT_NEAR(pace(a), pace(short_one), 0.3 * pace(short_one));
    for (int f = 1; f < a.frame_count(); f += 5)
        EXPECT_GT(closest_pair(a.frame(f)), 0.5 * closest_pair(still)) << "frame " << f;
}

// --- A short clip ---

// The first `frames` frames of the swirling particles (113 particles circling in place).
Animation swirl_clip(int frames) {
    Animation a = load_animation(std::string(TESSERA_SOURCE_DIR) + "/examples/dynamic/swirl_particles_2d.json");
    a.times.resize(frames);
    a.positions.resize(static_cast<size_t>(frames) * a.sample_count());
    return a;
}

TEST(GraphMotion, AShortClipIsContinuedFromItsLastFrameThroughTheNeighbourhoodsOfAllItsFrames) {
    const Animation clip = swirl_clip(4);
    GraphMotionOptions o;
    o.frames = 24;
    o.threads = 2;
    GraphMotionStats stats;
    const Animation a = extend_by_graph(clip, o, &stats);
    ASSERT_EQ(a.frame_count(), 24);
    for (size_t i = 0; i < clip.positions.size(); ++i) ASSERT_EQ(a.positions[i], clip.positions[i]) << "the clip's own";
    const double interval = clip.times[3] - clip.times[2];
    EXPECT_NEAR(a.times[23] - a.times[3], 20 * interval, 1e-9);
    EXPECT_EQ(stats.nodes, 4 * clip.sample_count()) << "every frame's neighbourhoods are nodes";
    const Exemplar last = clip.frame(3);
    const NearestNeighborStats in = nearest_neighbor_distances(last, 1);
    double step = 0.0, junction = 0.0;
    for (int f = 4; f < a.frame_count(); ++f) {
        const NearestNeighborStats out = nearest_neighbor_distances(a.frame(f), 1);
        EXPECT_NEAR(out.mean, in.mean, 0.1 * in.mean) << "frame " << f;
        EXPECT_GT(out.min, 0.5 * in.min) << "frame " << f;
        for (int s = 0; s < a.sample_count(); ++s) {
            const double d = norm(a.at(f, s) - a.at(f - 1, s));
            step += d;
            if (f == 4) junction += d;
        }
    }
    step /= 20.0 * a.sample_count(), junction /= a.sample_count();
    std::printf("swirl clip continued: mean step %.4f (spacing %.3f), at the junction %.4f\n", step, in.mean, junction);
    EXPECT_GT(step, 0.005 * in.mean) << "it moves on";
    EXPECT_LT(junction, 3.0 * step) << "no jump where the clip ends";
    o.threads = 1;
    EXPECT_TRUE(extend_by_graph(clip, o).positions == a.positions);
    o.frames = 4;
    EXPECT_TRUE(extend_by_graph(clip, o).positions == clip.positions) << "a clip long enough is kept";
}

// --- In the dynamic method ---

TEST(GraphMotion, DynamicSynthesisOfAStillMovesItsElements) {
    const Exemplar still = poisson_still();
    DynamicOptions o;
    o.frames = 8;
    o.threads = 2;
    const AnimatedArrangement out = synthesize_dynamic(animation_from_exemplar(still), still.domain.scaled(1.5), o);
    ASSERT_EQ(out.frame_count(), 8);
    ASSERT_FALSE(out.stats.notes.empty());
    EXPECT_NE(out.stats.notes.front().find("graph synthesis gave the still 24 frames"), std::string::npos)
        << out.stats.notes.front();
    double moved = 0.0;
    for (int s = 0; s < out.sample_count(); ++s) moved += norm(out.at(7, s) - out.at(0, s));
    EXPECT_GT(moved / out.sample_count(), 0.02);
    for (int f = 0; f < 8; ++f) EXPECT_GT(closest_pair(out.frame(f)), 0.5 * closest_pair(still)) << "frame " << f;
    // Off: a still has no window of 3 frames.
    o.graph_frames = 0;
    EXPECT_THROW(synthesize_dynamic(animation_from_exemplar(still), still.domain.scaled(1.5), o), Error);
}

}  // namespace
