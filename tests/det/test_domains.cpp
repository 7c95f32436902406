// Synthesis into shaped domains (Eq. 6 and the boundary term): nothing leaves the shape.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tessera/tessera.hpp"

using namespace tessera;

TEST(DetDomains, PolygonWithAHoleHoldsItsElements) {
    const std::string dir = std::string(TESSERA_SOURCE_DIR) + "/examples/";
    const Exemplar ex = load(dir + "poisson_disk_2d.json");
    const Domain ring = load_domain_json(dir + "domain_disk_with_hole.json", 2);
    const Arrangement out = synthesize_det(ex, ring, DetOptions{});
    int outside = 0;
    for (const auto& s : out.samples) outside += !ring.inside(s.p);
    EXPECT_LT(static_cast<double>(outside) / out.samples.size(), 0.01);
    // The density is the exemplar's: count within 5% of density x area.
    const double expected = ex.elements.size() / ex.domain.measure() * ring.measure();
    EXPECT_NEAR(out.elements.size() / expected, 1.0, 0.05);
    // And the hole is empty while its surroundings are not.
    int in_hole = 0;
    for (const auto& e : out.elements) in_hole += norm(e.position - Vec3{15, 15, 0}) < 4.0;
    EXPECT_EQ(in_hole, 0);
}

TEST(DetDomains, ClosedMeshHoldsItsElements) {
    const std::string dir = std::string(TESSERA_SOURCE_DIR) + "/examples/";
    const Exemplar ex = load(dir + "spheres_3d.json");
    const Domain blob = Domain::mesh(dir + "blob.obj", 64);
    DetOptions o;
    o.iterations = 5;
    const Arrangement out = synthesize_det(ex, blob, o);
    int outside = 0;
    for (const auto& s : out.samples) outside += !blob.inside(s.p);
    EXPECT_LT(static_cast<double>(outside) / out.samples.size(), 0.01);
    const double expected = ex.elements.size() / ex.domain.measure() * blob.measure();
    EXPECT_NEAR(out.elements.size() / expected, 1.0, 0.1);
}
