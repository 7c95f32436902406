// The interleaved physics solver (section 5) inside synthesis.
#include <gtest/gtest.h>

#include <string>

#include "tessera/tessera.hpp"

using namespace tessera;

TEST(DetPhysics, InterleavedStepsAtLeastHalveInterpenetration) {
    const Exemplar ex = load(std::string(TESSERA_SOURCE_DIR) + "/examples/spheres_3d.json");
    const Domain domain = ex.domain.scaled(1.5);
    DetOptions o;
    o.iterations = 6;
    const Arrangement plain = synthesize_det(ex, domain, o);
    o.physics = true;
    const Arrangement settled = synthesize_det(ex, domain, o);
    const Vec3 down{0, 0, -9.81};
    const PhysicsReport without = measure_physics(plain, domain, down);
    const PhysicsReport with = measure_physics(settled, domain, down);
    // The crowding repair already separates most pairs the assignment leaves overlapping, so
    // the interpenetration to remove is the one before the first physics step.
    ASSERT_GT(settled.stats.penetrations_before, 20) << "the case must have interpenetration to remove";
    EXPECT_LE(with.interpenetrating_pairs, settled.stats.penetrations_before / 2)
        << settled.stats.penetrations_before << " -> " << with.interpenetrating_pairs;
    EXPECT_LE(with.interpenetrating_pairs, without.interpenetrating_pairs);
    EXPECT_EQ(settled.elements.size(), plain.elements.size());  // nothing lost
    for (const auto& s : settled.samples) ASSERT_TRUE(domain.inside(s.p));
    EXPECT_TRUE(settled.stats.physics);
    EXPECT_EQ(settled.stats.penetrations_after, with.interpenetrating_pairs);
    EXPECT_GT(settled.stats.penetrations_before, settled.stats.penetrations_after);
}
