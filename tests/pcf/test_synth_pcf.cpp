// PCF synthesis end to end (synthesize_pcf on models from analyze_distribution):
// determinism, counts, radii, the hard core of a Poisson-disk exemplar, a clustered
// class, polygon domains, fallbacks, bounds and errors.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "pcf/pcf_math.hpp"
#include "pcf/analysis_test_data.hpp"
#include "pcf/synth_test_data.hpp"
#include "tessera/error.hpp"
#include "tessera/io.hpp"
#include "tessera/pcf_synthesis.hpp"

using namespace tessera;

namespace {

// Class "parent": a sparse hard-core set; class "child": 4 elements at 0.3 to 0.6 from
// each parent (clustered around it), depending on the parent class only.
Exemplar clustered(std::uint64_t seed, double parent_radius = 0.0, double child_radius = 0.0) {
    Exemplar ex = test::poisson_disk(20, 10.0, 1.6, seed, parent_radius);
    ex.types[0].name = "parent";
    const int child = ex.type_index("child");
    ex.types[child].depends_on = std::vector<std::string>{"parent"};
    const core::KeyedRng rng(seed + 1, core::Purpose::test);
    const int parents = static_cast<int>(ex.elements.size());
    std::uint64_t draw = 0;
    for (int i = 0; i < parents; ++i)
        for (int k = 0; k < 4; ++k) {
            for (int attempt = 0; attempt < 20; ++attempt) {
                const double d = 0.3 + 0.3 * rng.uniform(draw++);
                const double a = 2.0 * pcf::kPi * rng.uniform(draw++);
                const Vec3 p = ex.elements[i].position + Vec3{d * std::cos(a), d * std::sin(a), 0.0};
                if (!ex.domain.inside(p)) continue;
                ex.add_element(child, {p}, child_radius);
                break;
            }
        }
    return ex;
}

// Nearest-neighbour distance of every element of class a to the elements of class b.
std::vector<double> nearest(const Exemplar& data, int a, int b) {
    std::vector<double> out;
    for (size_t i = 0; i < data.elements.size(); ++i) {
        if (data.elements[i].type != a) continue;
        double best = 1e300;
        for (size_t j = 0; j < data.elements.size(); ++j)
            if (j != i && data.elements[j].type == b)
                best = std::min(best, norm(data.elements[i].position - data.elements[j].position));
        out.push_back(best);
    }
    return out;
}

double mean(const std::vector<double>& v) {
    double s = 0.0;
    for (double x : v) s += x;
    return v.empty() ? 0.0 : s / v.size();
}

PcfSynthOptions quick(std::uint64_t seed, int iterations = 20) {
    PcfSynthOptions o;
    o.seed = seed;
    o.threads = 2;
    o.max_iterations = iterations;
    return o;
}

}  // namespace

TEST(PcfSynth, SameBytesForAnyThreadCount) {
    const Exemplar ex = clustered(3, 0.25, 0.1);
    const PcfModel model = analyze_distribution(ex);
    const Domain domain = ex.domain.scaled(1.2);
    std::string first;
    std::vector<std::string> first_notes;
    int first_fallbacks = -1;
    for (int threads : {1, 2, 3}) {
        PcfSynthOptions o = quick(11, 10);
        o.threads = threads;
        o.max_fails = 50;  // the grid search runs too
        o.grid_cells = 24;
        const Arrangement out = synthesize_pcf(model, domain, o);
        const std::string text = to_json(out, &out.stats);
        if (first.empty()) {
            first = text;
            first_notes = out.stats.notes;
            first_fallbacks = out.stats.fallbacks;
        } else {
            EXPECT_EQ(text, first) << threads << " threads";
            EXPECT_EQ(out.stats.notes, first_notes) << threads << " threads";
            EXPECT_EQ(out.stats.fallbacks, first_fallbacks) << threads << " threads";
        }
        EXPECT_EQ(out.stats.threads, threads);
    }
}

TEST(PcfSynth, CountsFollowTheDensityOnFourTimesTheArea) {
    const Exemplar ex = clustered(5);
    const PcfModel model = analyze_distribution(ex);
    const Arrangement out = synthesize_pcf(model, ex.domain.scaled(2.0), quick(2, 5));
    ASSERT_EQ(out.types.size(), 2u);
    for (int c = 0; c < 2; ++c) {
        const double expected = 4.0 * model.counts[c];
        const auto n = std::count_if(out.elements.begin(), out.elements.end(), [&](const Element& e) { return e.type == c; });
        EXPECT_NEAR(n / expected, 1.0, 0.02) << out.types[c].name;
    }
    EXPECT_EQ(out.stats.method, "pcf");
    EXPECT_EQ(out.stats.seed, 2u);
    for (size_t i = 0; i < out.elements.size(); ++i) {
        EXPECT_EQ(out.elements[i].id, i);
        EXPECT_EQ(out.elements[i].sample_count, 1);
    }
    ASSERT_TRUE(out.types[1].depends_on.has_value());
    EXPECT_EQ(*out.types[1].depends_on, std::vector<std::string>{"parent"});
}

TEST(PcfSynth, PoissonDiskExemplarKeepsItsHardCore) {
    const Exemplar ex = test::poisson_disk(150, 10.0, 0.6, 7);
    const std::vector<double> nn_in = nearest(ex, 0, 0);
    const double min_in = *std::min_element(nn_in.begin(), nn_in.end());
    const PcfModel model = analyze_distribution(ex);
    const Arrangement out = synthesize_pcf(model, ex.domain.scaled(1.5), quick(4, 40));
    const std::vector<double> nn = nearest(out, 0, 0);
    const auto close = std::count_if(nn.begin(), nn.end(), [&](double d) { return d < 0.8 * min_in; });
    EXPECT_LT(static_cast<double>(close) / nn.size(), 0.02) << close << " of " << nn.size();
}

TEST(PcfSynth, ClusteredClassStaysAroundItsParents) {
    const Exemplar ex = clustered(9);
    const PcfModel model = analyze_distribution(ex);
    const Arrangement out = synthesize_pcf(model, ex.domain.scaled(1.5), quick(6, 30));
    const double in = mean(nearest(ex, 1, 0)), got = mean(nearest(out, 1, 0));
    EXPECT_NEAR(got / in, 1.0, 0.15) << "input " << in << ", output " << got;
}

TEST(PcfSynth, ClassesWithoutAPcfKeepTheirSeparation) {
    // Two independent disk classes that never overlap in the exemplar (a Poisson-disk set
    // split in two): no PCF links them, the separation keeps them apart in the output.
    Exemplar ex = test::poisson_disk(120, 12.0, 0.9, 5, 0.3);
    ex.types[0].name = "odd";
    ex.types[0].depends_on = std::vector<std::string>{};
    const int even = ex.type_index("even");
    ex.types[even].depends_on = std::vector<std::string>{};
    for (size_t i = 0; i < ex.elements.size(); i += 2) ex.elements[i].type = even;
    const PcfModel model = analyze_distribution(ex);
    ASSERT_EQ(model.separations.size(), 1u);
    EXPECT_GT(model.separations[0].x, 3.0);  // the exemplar's disks never touch
    const Arrangement out = synthesize_pcf(model, ex.domain.scaled(1.5), quick(3, 10));
    double closest = 1e300;
    for (size_t i = 0; i < out.elements.size(); ++i)
        for (size_t j = i + 1; j < out.elements.size(); ++j)
            if (out.elements[i].type != out.elements[j].type)
                closest = std::min(closest, disk_metric_normalised(norm(out.elements[i].position - out.elements[j].position),
                                                                   out.elements[i].radius, out.elements[j].radius,
                                                                   model.r_max));
    // The separation is a penalty in the candidate error (a tenth of a kernel width inside
    // weighs like a neighbour where the exemplar has none): no overlaps, at most a trace inside.
    EXPECT_GT(closest, 3.0);
    EXPECT_GE(closest, model.separations[0].x - 0.01);
}

TEST(PcfSynth, RadiiAreDrawnFromTheExemplars) {
    Exemplar ex = test::poisson_disk(40, 10.0, 1.0, 12);
    for (size_t i = 0; i < ex.elements.size(); ++i) ex.elements[i].radius = 0.1 + 0.01 * i;  // all different
    const PcfModel model = analyze_distribution(ex);
    const Arrangement out = synthesize_pcf(model, ex.domain.scaled(1.6), quick(1, 3));
    std::map<double, int> uses;
    for (const Element& e : out.elements) ++uses[e.radius];
    const int n = static_cast<int>(out.elements.size()), m = static_cast<int>(ex.elements.size());
    ASSERT_GT(n, 2 * m);
    for (const auto& [radius, count] : uses) {
        const bool known = std::any_of(ex.elements.begin(), ex.elements.end(), [&](const Element& e) { return e.radius == radius; });
        EXPECT_TRUE(known) << radius;
        // every radius the number of whole copies of the list, plus at most one
        EXPECT_GE(count, n / m);
        EXPECT_LE(count, n / m + 1);
    }
    EXPECT_EQ(static_cast<int>(uses.size()), m);
}

TEST(PcfSynth, PolygonDomainHoldsEveryElement) {
    const Exemplar ex = test::poisson_disk(100, 10.0, 0.7, 4);
    const PcfModel model = analyze_distribution(ex);
    const Domain l_shape = Domain::polygon({{0, 0, 0}, {14, 0, 0}, {14, 6, 0}, {6, 6, 0}, {6, 14, 0}, {0, 14, 0}});
    const Arrangement out = synthesize_pcf(model, l_shape, quick(8, 10));
    ASSERT_FALSE(out.elements.empty());
    for (const Element& e : out.elements) EXPECT_TRUE(l_shape.inside(e.position)) << e.position.x << ", " << e.position.y;
    EXPECT_EQ(out.domain.kind(), Domain::Kind::polygon);
}

TEST(PcfSynth, GridSearchFallbackIsCountedAndNoted) {
    const Exemplar ex = test::poisson_disk(60, 10.0, 0.9, 2);
    const PcfModel model = analyze_distribution(ex);
    PcfSynthOptions o = quick(3, 2);
    o.max_fails = 1;
    o.grid_cells = 16;
    const Arrangement out = synthesize_pcf(model, ex.domain, o);
    EXPECT_GT(out.stats.fallbacks, 0);
    const bool noted = std::any_of(out.stats.notes.begin(), out.stats.notes.end(),
                                   [](const std::string& n) { return n.find("grid search") != std::string::npos; });
    EXPECT_TRUE(noted);
    // Both are in the output's "stats" (max_fails 0: grid search from the first element).
    o.max_fails = 0;
    const Arrangement grid = synthesize_pcf(model, ex.domain, o);
    EXPECT_EQ(grid.stats.fallbacks, static_cast<int>(grid.elements.size()));
    const nlohmann::json stats = nlohmann::json::parse(to_json(grid, &grid.stats))["stats"];
    EXPECT_EQ(stats["fallbacks"].get<int>(), grid.stats.fallbacks);
    ASSERT_EQ(stats["notes"].size(), grid.stats.notes.size());
    for (size_t k = 0; k < grid.stats.notes.size(); ++k) EXPECT_EQ(stats["notes"][k].get<std::string>(), grid.stats.notes[k]);
    EXPECT_NE(stats["notes"][0].get<std::string>().find("grid search placed"), std::string::npos);
}

TEST(PcfSynth, RefinementBoundIsReported) {
    const Exemplar ex = test::poisson_disk(60, 10.0, 0.9, 2);
    const PcfModel model = analyze_distribution(ex);
    PcfSynthOptions o = quick(3, 1);
    o.convergence = 0.0;
    o.outlier_rounds = 0;
    const Arrangement out = synthesize_pcf(model, ex.domain, o);
    EXPECT_EQ(out.stats.solver_bound_hits, 1);
    EXPECT_EQ(out.stats.energy.size(), 1u);
    o.max_iterations = 0;
    const Arrangement none = synthesize_pcf(model, ex.domain, o);
    EXPECT_EQ(none.stats.solver_bound_hits, 0);
    EXPECT_TRUE(none.stats.energy.empty());
}

TEST(PcfSynth, LargeClassConvergesAndKeepsItsLowestError) {
    // 240 elements of one class: they keep moving, but the error stalls, so the refinement
    // ends before max_iterations, at its lowest error.
    const Exemplar ex = test::poisson_points(60, 8.0, 4);
    const PcfModel model = analyze_distribution(ex);
    PcfSynthOptions o = quick(5, 100);
    o.outlier_rounds = 0;
    const Arrangement out = synthesize_pcf(model, ex.domain.scaled(2.0), o);
    EXPECT_EQ(out.elements.size(), 4 * ex.elements.size());
    EXPECT_EQ(out.stats.solver_bound_hits, 0);
    EXPECT_LT(out.stats.energy.size(), 100u);
    ASSERT_FALSE(out.stats.energy.empty());
    EXPECT_DOUBLE_EQ(out.stats.final_energy, *std::min_element(out.stats.energy.begin(), out.stats.energy.end()));
    // convergence 0: every sweep runs.
    o.convergence = 0.0;
    o.max_iterations = 21;
    EXPECT_EQ(synthesize_pcf(model, ex.domain.scaled(2.0), o).stats.energy.size(), 21u);
}

TEST(PcfSynth, ProgressReportsAndCancels) {
    const Exemplar ex = test::poisson_disk(40, 10.0, 1.0, 2);
    const PcfModel model = analyze_distribution(ex);
    int sweeps = 0;
    const Arrangement out = synthesize_pcf(model, ex.domain, quick(1, 4), [&](const ProgressEvent& e) {
        sweeps += e.stage == "iteration";
        return true;
    });
    EXPECT_EQ(sweeps, static_cast<int>(out.stats.energy.size()));
    EXPECT_THROW(synthesize_pcf(model, ex.domain, quick(1, 4), [](const ProgressEvent& e) { return e.stage != "iteration"; }),
                 Cancelled);
}

TEST(PcfSynth, BadOptionsNameTheField) {
    const Exemplar ex = test::poisson_disk(30, 10.0, 1.0, 2);
    const PcfModel model = analyze_distribution(ex);
    const auto expect_option = [&](const PcfSynthOptions& o, const std::string& field) {
        try {
            synthesize_pcf(model, ex.domain, o);
            ADD_FAILURE() << field << " accepted";
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::option) << e.what();
            EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
        }
    };
    PcfSynthOptions o;
    o.threads = -1;
    expect_option(o, "threads");
    o = {};
    o.epsilon0 = -1.0;
    expect_option(o, "epsilon0");
    o = {};
    o.epsilon_step = std::nan("");
    expect_option(o, "epsilon_step");
    o = {};
    o.max_fails = -2;
    expect_option(o, "max_fails");
    o = {};
    o.grid_cells = 0;
    expect_option(o, "grid_cells");
    o = {};
    o.max_iterations = -1;
    expect_option(o, "iterations");  // the option's name in every front end
    o = {};
    o.convergence = -0.1;
    expect_option(o, "convergence");
    o = {};
    o.outlier_rounds = -1;
    expect_option(o, "outlier_rounds");
}

TEST(PcfSynth, DomainErrors) {
    const Exemplar ex = clustered(2);
    const PcfModel model = analyze_distribution(ex);
    try {
        synthesize_pcf(model, Domain::box({0, 0, 0}, {0.5, 0.5, 0}, 2));
        ADD_FAILURE() << "a tiny domain was accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::domain);
        EXPECT_NE(std::string(e.what()).find("parent"), std::string::npos) << e.what();
    }
    try {
        synthesize_pcf(model, Domain::box({0, 0, 0}, {10, 10, 10}, 3));
        ADD_FAILURE() << "a 3D domain was accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::domain);
    }
    PcfModel broken = model;
    broken.pcfs[0].mean.pop_back();
    try {
        synthesize_pcf(broken, ex.domain);
        ADD_FAILURE() << "an inconsistent model was accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::input);
    }
}
