// End-to-end properties of discrete element texture synthesis on the built-in exemplars.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/rng.hpp"
#include "tessera/tessera.hpp"

using namespace tessera;

namespace {

Exemplar example(const std::string& name) { return load(std::string(TESSERA_SOURCE_DIR) + "/examples/" + name); }

// Uniformly random points of the same count, in the same domain: the baseline a
// synthesis must beat by far.
Exemplar uniform_random_like(const Exemplar& like, std::uint64_t seed) {
    Exemplar r;
    r.dimension = like.dimension;
    r.domain = like.domain;
    r.type_index("dot");
    const core::KeyedRng rng(seed, core::Purpose::test);
    const Box b = like.domain.bounds();
    for (size_t i = 0; i < like.elements.size(); ++i) {
        Vec3 p;
        for (int k = 0; k < like.dimension; ++k) p[k] = b.lo[k] + (b.hi[k] - b.lo[k]) * rng.uniform(3 * i + k);
        r.add_element(0, {p});
    }
    return r;
}


}  // namespace

TEST(DetSynthesis, JitteredHexagonalExemplarKeepsItsOrderAtTripleScale) {
    const Exemplar ex = example("hex_jittered_2d.json");
    DetOptions o;
    o.seed = 5;
    const Arrangement out = synthesize_det(ex, ex.domain.scaled(3.0), o);
    EXPECT_GE(mean_psi6(out), 0.8);
    const double nn_in = nearest_neighbor_distances(ex).mean;
    const double nn_out = nearest_neighbor_distances(out).mean;
    EXPECT_NEAR(nn_out / nn_in, 1.0, 0.05);
    // The density is kept: about 9 times the elements.
    EXPECT_NEAR(static_cast<double>(out.elements.size()) / ex.elements.size(), 9.0, 0.9);
}

TEST(DetSynthesis, PoissonDiskPcfErrorIsFarBelowUniformRandom) {
    const Exemplar ex = example("poisson_disk_2d.json");
    DetOptions o;
    o.seed = 9;
    const Arrangement out = synthesize_det(ex, ex.domain.scaled(3.0), o);
    const PcfResult g_in = pair_correlation(ex);
    const double err_out = pcf_relative_error(g_in, pair_correlation_on_grid_of(out, g_in));
    const Exemplar random = uniform_random_like(out, 17);
    const double err_random = pcf_relative_error(g_in, pair_correlation_on_grid_of(random, g_in));
    EXPECT_LT(err_out, 0.35 * err_random) << "synthesis " << err_out << ", uniform random " << err_random;
    // Poisson-disk inhibition survives: few elements (< 3%) have a neighbour much
    // closer than the exemplar's closest pair.
    const double min_in = nearest_neighbor_distances(ex).min;
    const auto nn_out = nearest_neighbor_distances(out).distances;
    const auto violations = std::count_if(nn_out.begin(), nn_out.end(), [&](double d) { return d < 0.75 * min_in; });
    EXPECT_LT(static_cast<double>(violations) / nn_out.size(), 0.03);
}

TEST(DetSynthesis, ByteIdenticalWhateverTheThreadCount) {
    const Exemplar ex = example("two_class_2d.json");
    DetOptions o;
    o.seed = 21;
    o.iterations = 4;
    o.threads = 1;
    const std::string one = to_json(synthesize_det(ex, ex.domain.scaled(2.0), o));
    o.threads = 2;
    const std::string two = to_json(synthesize_det(ex, ex.domain.scaled(2.0), o));
    o.threads = 7;
    const std::string seven = to_json(synthesize_det(ex, ex.domain.scaled(2.0), o));
    EXPECT_EQ(one, two);
    EXPECT_EQ(one, seven);
    o.seed = 22;
    EXPECT_NE(one, to_json(synthesize_det(ex, ex.domain.scaled(2.0), o)));
}

TEST(DetSynthesis, TranslatingTheExemplarLeavesTheOutputAlone) {
    // The output depends on the exemplar's elements relative to its window, not on where the
    // window lies; the random draws are keyed by the output's world cells.
    Exemplar ex = example("poisson_disk_2d.json");
    DetOptions o;
    o.iterations = 4;
    const Domain out = ex.domain.scaled(2.0);
    const Arrangement a = synthesize_det(ex, out, o);
    const Vec3 shift{100.25, -40.5, 0};
    for (auto& s : ex.samples) s.p += shift;
    ex.domain = Domain::box(ex.domain.bounds().lo + shift, ex.domain.bounds().hi + shift, 2);
    ex.update_positions();
    const Arrangement b = synthesize_det(ex, out, o);
    ASSERT_EQ(a.samples.size(), b.samples.size());
    double worst = 0.0;
    for (size_t i = 0; i < a.samples.size(); ++i) worst = std::max(worst, norm(b.samples[i].p - a.samples[i].p));
    EXPECT_LT(worst, 1e-6);
}

TEST(DetSynthesis, TheSameSeedDrawsTheSameWindowsAtTheSamePlaceInAnyDomain) {
    // The initialization of a domain and of one four times larger around the same origin:
    // the first cell (no earlier neighbours in either) takes the same exemplar window, so
    // the elements well inside it are the same.
    const Exemplar ex = example("poisson_disk_2d.json");
    DetOptions o;
    o.iterations = 0;
    o.relax_sweeps = 0;
    o.patch_size = 4.0;
    o.patch_candidates = 1;
    const Arrangement small = synthesize_det(ex, Domain::box({0, 0, 0}, {8, 8, 0}, 2), o);
    const Arrangement large = synthesize_det(ex, Domain::box({0, 0, 0}, {32, 32, 0}, 2), o);
    int inner = 0, same = 0;
    for (const Element& e : small.elements) {
        if (e.position.x < 0.5 || e.position.x > 3.5 || e.position.y < 0.5 || e.position.y > 3.5) continue;
        ++inner;
        for (const Element& f : large.elements)
            if (norm(f.position - e.position) < 1e-9) {
                ++same;
                break;
            }
    }
    EXPECT_GT(inner, 5);
    EXPECT_GE(same, inner * 9 / 10) << same << " of " << inner;
}

TEST(DetSynthesis, MultiSampleSticksKeepTheirShape) {
    const Exemplar ex = example("sticks_2d.json");
    DetOptions o;
    o.seed = 3;
    const Arrangement out = synthesize_det(ex, ex.domain.scaled(2.0), o);
    ASSERT_GT(out.elements.size(), 3 * ex.elements.size());
    // Every output stick is a rigid copy of some input stick: all sample-to-sample
    // distances agree with that stick's to 1e-6.
    auto distances = [](const Exemplar& d, const Element& e) {
        std::vector<double> v;
        for (int a = 0; a < e.sample_count; ++a)
            for (int b = a + 1; b < e.sample_count; ++b)
                v.push_back(norm(d.samples[e.first_sample + a].p - d.samples[e.first_sample + b].p));
        return v;
    };
    std::vector<std::vector<double>> input_shapes;
    for (const auto& e : ex.elements) input_shapes.push_back(distances(ex, e));
    for (const auto& e : out.elements) {
        ASSERT_EQ(e.sample_count, 5);
        const auto d = distances(out, e);
        bool found = false;
        for (const auto& s : input_shapes) {
            double worst = 0.0;
            for (size_t k = 0; k < s.size(); ++k) worst = std::max(worst, std::abs(s[k] - d[k]));
            found = found || worst < 1e-6;
        }
        EXPECT_TRUE(found) << "element " << e.id << " lost its shape";
    }
    // Orientation statistics survive: sticks stay mostly horizontal, as in the exemplar.
    auto mean_abs_sin = [](const Exemplar& d) {
        double s = 0.0;
        for (const auto& e : d.elements) {
            const Vec3 a = d.samples[e.first_sample].p, b = d.samples[e.first_sample + 4].p;
            s += std::abs((b.y - a.y) / norm(b - a));
        }
        return s / d.elements.size();
    };
    EXPECT_NEAR(mean_abs_sin(out), mean_abs_sin(ex), 0.1);
}

TEST(DetSynthesis, ThreeDimensionalSpherePacking) {
    const Exemplar ex = example("spheres_3d.json");
    DetOptions o;
    o.seed = 4;
    const Arrangement out = synthesize_det(ex, ex.domain.scaled(2.0), o);
    EXPECT_EQ(out.dimension, 3);
    EXPECT_NEAR(static_cast<double>(out.elements.size()) / ex.elements.size(), 8.0, 0.8);
    for (const auto& s : out.samples) ASSERT_TRUE(out.domain.inside(s.p));
    const PcfResult g_in = pair_correlation(ex);
    const double err_out = pcf_relative_error(g_in, pair_correlation_on_grid_of(out, g_in));
    const double err_random = pcf_relative_error(g_in, pair_correlation_on_grid_of(uniform_random_like(out, 5), g_in));
    EXPECT_LT(err_out, 0.5 * err_random) << "synthesis " << err_out << ", uniform random " << err_random;
    EXPECT_NEAR(nearest_neighbor_distances(out).mean / nearest_neighbor_distances(ex).mean, 1.0, 0.15);
}

TEST(DetSynthesis, EnergyDecreasesOverTheIterations) {
    const Exemplar ex = example("hex_jittered_2d.json");
    const Arrangement out = synthesize_det(ex, ex.domain.scaled(2.0), DetOptions{});
    ASSERT_EQ(out.stats.energy.size(), 10u);
    EXPECT_LT(out.stats.final_energy, 0.7 * out.stats.energy.front());
    EXPECT_EQ(out.stats.method, "det");
}

TEST(DetSynthesis, ExhaustiveSearchAndHungarianPairingWork) {
    const Exemplar ex = example("hex_jittered_2d.json");
    DetOptions o;
    o.iterations = 6;
    const Arrangement kc = synthesize_det(ex, ex.domain.scaled(2.0), o);
    o.search = SearchMode::exhaustive;
    const Arrangement full = synthesize_det(ex, ex.domain.scaled(2.0), o);
    // The exhaustive scan finds matches at least as good for the same output.
    EXPECT_LE(full.stats.energy.front(), kc.stats.energy.front() + 1e-9);
    EXPECT_GE(mean_psi6(full), 0.75);
    o.search = SearchMode::kcoherence;
    o.matching = Matching::hungarian;
    const Arrangement exact = synthesize_det(ex, ex.domain.scaled(2.0), o);
    EXPECT_GE(mean_psi6(exact), 0.75);
}

TEST(DetSynthesis, ProgressIsReportedAndCanCancel) {
    const Exemplar ex = example("poisson_disk_2d.json");
    int calls = 0;
    DetOptions o;
    o.iterations = 3;
    synthesize_det(ex, ex.domain, o, [&](const ProgressEvent&) { return ++calls > 0; });
    EXPECT_GE(calls, 4);  // init, three iterations, done
    EXPECT_THROW(synthesize_det(ex, ex.domain, o, [](const ProgressEvent& e) { return e.iteration < 1; }), Cancelled);
}

TEST(DetSynthesis, RejectsBadOptionsAndDomains) {
    const Exemplar ex = example("poisson_disk_2d.json");
    DetOptions o;
    o.radius = -1.0;
    try {
        synthesize_det(ex, ex.domain, o);
        FAIL() << "a negative radius must be rejected";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::option);
        EXPECT_NE(std::string(e.what()).find("radius"), std::string::npos);
    }
    o = DetOptions{};
    o.iterations = -2;
    EXPECT_THROW(synthesize_det(ex, ex.domain, o), Error);
    const Domain three_d = Domain::box({0, 0, 0}, {5, 5, 5}, 3);
    try {
        synthesize_det(ex, three_d, DetOptions{});
        FAIL() << "a 3D domain for a 2D exemplar must be rejected";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::domain);
    }
    Exemplar empty;
    empty.type_index("a");
    EXPECT_THROW(synthesize_det(empty, ex.domain, DetOptions{}), Error);
}
