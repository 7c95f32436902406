// The exemplar's correlation range (det/structure_range.hpp) and the default patch size
// it sets: none for a random pattern, the cluster size for a clustered one, everything
// for a lattice; clustered field data keep their clusters at 4x the area, and every
// dataset its density (det/thin_crowds.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "core/rng.hpp"
#include "det/structure_range.hpp"
#include "tessera/tessera.hpp"

using namespace tessera;

namespace {

Exemplar unit_square_points() {
    Exemplar ex;
    ex.dimension = 2;
    ex.domain = Domain::box({0, 0, 0}, {1, 1, 0}, 2);
    ex.type_index("dot");
    return ex;
}

Exemplar uniform_points(int n, std::uint64_t seed) {
    Exemplar ex = unit_square_points();
    const core::KeyedRng rng(seed, core::Purpose::test);
    for (int i = 0; i < n; ++i) ex.add_element(0, {Vec3{rng.uniform(2 * i), rng.uniform(2 * i + 1), 0}});
    return ex;
}

// Thomas process: `parents` uniform centres, `children` Gaussian offsets (sd sigma) each,
// kept inside the unit square.
Exemplar thomas_points(int parents, int children, double sigma, std::uint64_t seed) {
    Exemplar ex = unit_square_points();
    const core::KeyedRng rng(seed, core::Purpose::test);
    std::uint64_t counter = 0;
    for (int p = 0; p < parents; ++p) {
        const double cx = rng.uniform(counter++);
        const double cy = rng.uniform(counter++);
        const Vec3 centre{cx, cy, 0};
        for (int c = 0; c < children; ++c) {
            // Box-Muller
            const double radius = sigma * std::sqrt(-2.0 * std::log(1.0 - rng.uniform(counter++)));
            const double angle = 2.0 * std::numbers::pi * rng.uniform(counter++);
            const Vec3 q = centre + Vec3{radius * std::cos(angle), radius * std::sin(angle), 0};
            if (q.x >= 0 && q.x <= 1 && q.y >= 0 && q.y <= 1) ex.add_element(0, {q});
        }
    }
    return ex;
}

double spacing_of(const Exemplar& ex) { return nearest_neighbor_distances(ex).mean; }

}  // namespace

TEST(StructureRange, RandomPointsHaveNoneBeyondANeighbourhood) {
    for (std::uint64_t seed : {1, 2, 3}) {
        const Exemplar ex = uniform_points(1500, seed);
        const double d = spacing_of(ex);
        // At most the default neighbourhood radius (2 spacings): the paper's patch stays.
        EXPECT_LE(det::structure_range(ex, d, 12.0 * d, 2), 2.0 * d) << "seed " << seed;
    }
}

TEST(StructureRange, ClustersAreFoundAtTheirSize) {
    // Many clusters: with few, chance gaps between them show as a deficit of pairs
    // (g < 1) out to large r, which is structure of that sample, not of the clusters.
    const double sigma = 0.01;
    const Exemplar ex = thomas_points(100, 8, sigma, 4);
    const double d = spacing_of(ex);
    const double range = det::structure_range(ex, d, 0.25, 2);
    // Cluster members lie within ~2 sigma of the centre, pairs within ~4-6 sigma.
    EXPECT_GE(range, 3.0 * sigma);
    EXPECT_LE(range, 9.0 * sigma);
    EXPECT_GT(range, 2.0 * d);  // beyond the neighbourhood: the patch grows
}

TEST(StructureRange, ALatticeIsStructuredAllTheWay) {
    Exemplar ex = unit_square_points();
    const double a = 0.05;
    for (int j = 0; j * a * std::sqrt(3.0) / 2.0 < 1.0; ++j)
        for (int i = 0; i * a < 1.0; ++i)
            ex.add_element(0, {Vec3{i * a + (j % 2) * a / 2.0 + 0.01, j * a * std::sqrt(3.0) / 2.0 + 0.01, 0}});
    const double limit = 0.25;
    EXPECT_GE(det::structure_range(ex, spacing_of(ex), limit, 2), 0.9 * limit);
}

TEST(StructureRange, ClassesSegregatedAtLongRangeCount) {
    // Two classes that each look random but occupy opposite halves: only the
    // class-pair curves show it; the range must see it although the pooled pattern is uniform.
    Exemplar ex = uniform_points(1200, 7);
    ex.type_index("other");
    for (Element& e : ex.elements) e.type = e.position.x < 0.5 ? 0 : 1;
    const double d = spacing_of(ex);
    EXPECT_GT(det::structure_range(ex, d, 12.0 * d, 2), 2.0 * d);
}

TEST(DetSynthesis, ClusteredFieldDataKeepTheirClustersAtFourTimesTheArea) {
    // redwood (62 seedlings in clusters): with one-neighbourhood patches the clusters were
    // cut apart (PCF error 0.20-0.26 on seeds 1-3); patches of twice the structure range
    // keep them (0.14-0.17). A uniform random pattern scores 0.65.
    LoadOptions lo;
    lo.input_domain = parse_box_domain("0,-1,1,0", "window");
    const Exemplar ex = load(std::string(TESSERA_SHARED_DATA_DIR) + "/points/redwood.csv", lo);
    double total = 0.0;
    for (std::uint64_t seed : {1, 2}) {
        DetOptions o;
        o.seed = seed;
        const Arrangement out = synthesize_det(ex, ex.domain.scaled(2.0), o);
        ASSERT_FALSE(out.stats.notes.empty());
        EXPECT_NE(out.stats.notes[0].find("initialization patches of"), std::string::npos);
        total += pcf_relative_error(ex, out);
    }
    EXPECT_LT(total / 2.0, 0.19);
}

TEST(DetSynthesis, FieldDataKeepTheirDensityPerClassAtFourTimesTheArea) {
    // The patch copy used to overfill: amacrine +4.5%, cells +10%, swedishpines +9% from
    // seam pairs (now thinned out, det/thin_crowds.cpp), and clustered redwood up to +31%
    // (seed 4) from windows of very different counts (now balanced over the raster order,
    // det/init.cpp, class by class). The attribute vote (Eq. 5) used to drift the classes
    // apart over the iterations (amacrine +3.1% / -3.3%); it now exchanges types instead.
    // Each class within 2.5%: over seeds 1 to 6 the worst class is within 2.3% on every
    // dataset (redwood, 250 elements at 4x, and ganglia's 'on' cells vary most).
    for (const auto& [name, window] : std::vector<std::pair<std::string, std::string>>{
             {"amacrine", "0,0,1.60121,1"}, {"cells", "0,0,1,1"}, {"redwood", "0,-1,1,0"},
             {"ganglia", "0,0,1,0.7533"}, {"swedishpines", "0,0,96,100"}, {"anemones", "0,0,280,180"}}) {
        LoadOptions lo;
        lo.input_domain = parse_box_domain(window, "window");
        const Exemplar ex = load(std::string(TESSERA_SHARED_DATA_DIR) + "/points/" + name + ".csv", lo);
        for (std::uint64_t seed : {1, 4}) {
            DetOptions o;
            o.seed = seed;
            const Arrangement out = synthesize_det(ex, ex.domain.scaled(2.0), o);
            EXPECT_NEAR(static_cast<double>(out.elements.size()) / (4.0 * ex.elements.size()), 1.0, 0.025)
                << name << " seed " << seed;
            for (int t = 0; t < static_cast<int>(ex.types.size()); ++t) {
                const auto of_type = [t](const Exemplar& data) {
                    return static_cast<double>(std::count_if(data.elements.begin(), data.elements.end(),
                                                             [t](const Element& e) { return e.type == t; }));
                };
                EXPECT_NEAR(of_type(out) / (4.0 * of_type(ex)), 1.0, 0.025)
                    << name << " seed " << seed << " class " << ex.types[t].name;
            }
        }
    }
}
