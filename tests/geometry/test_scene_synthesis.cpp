// Element geometry after synthesis: types keep their mesh and reference layout through
// synthesize_det, and rigid output elements are exact copies of input elements, so their
// meshes fit their samples to rounding.
#include "geometry_test_util.hpp"
#include "tessera/det.hpp"

using namespace geometry_test;

class SceneSynthesis : public TempDir {};

TEST_F(SceneSynthesis, RigidOutputsFitTheirMeshExactly) {
    Exemplar ex;
    ex.dimension = 2;
    ex.domain = Domain::box({0, 0, 0}, {6, 6, 0}, 2);
    ElementType shard;
    shard.name = "shard";
    shard.mesh = write_mesh("shard.obj", tetrahedron());
    shard.reference = {{-0.3, -0.1, 0}, {0.2, -0.1, 0}, {0.1, 0.2, 0}};
    ex.types.push_back(shard);
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) {
            const Quat turn = Quat::from_angle_z(0.4 * i + 1.3 * j);
            const Vec3 at{0.7 + 1.15 * i, 0.7 + 1.15 * j, 0};
            std::vector<Vec3> samples;
            for (const Vec3& r : shard.reference) samples.push_back(at + turn.rotate(r));
            ex.elements[ex.add_element(0, samples)].orientation = turn;
        }
    DetOptions options;
    options.iterations = 2;
    options.threads = 1;
    const Arrangement out = synthesize_det(ex, ex.domain.scaled(1.5), options);
    ASSERT_EQ(out.types.size(), 1u);
    EXPECT_EQ(out.types[0].mesh, shard.mesh);
    EXPECT_EQ(out.types[0].reference, shard.reference);

    const Scene scene = build_scene(out);
    ASSERT_EQ(scene.instances.size(), out.elements.size());
    ASSERT_GT(out.elements.size(), ex.elements.size());
    for (const SceneInstance& inst : scene.instances) {
        EXPECT_TRUE(inst.instanced);
        EXPECT_LT(inst.fit_error, 1e-9);
        const Element& el = out.elements[inst.element];
        for (int s = 0; s < el.sample_count; ++s)
            EXPECT_LT(norm(posed(inst, shard.reference[s]) - out.samples[el.first_sample + s].p), 1e-9);
    }
}
