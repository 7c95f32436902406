// Default shapes (geometry.hpp): types without a mesh become spheres (single sample) or
// tubes (several samples), sized by the element radius or, without one, the spacing.
#include <numbers>

#include "geometry/geometry_internal.hpp"
#include "geometry_test_util.hpp"
#include "tessera/det.hpp"

using namespace geometry_test;

TEST(GeometryShapes, IcosphereVerticesLieOnTheSphere) {
    for (int s = 0; s <= 3; ++s) {
        const TriangleMesh m = geometry::icosphere({1, -2, 3}, 0.25, s);
        EXPECT_EQ(m.triangles.size(), 20u << (2 * s));
        EXPECT_EQ(m.vertices.size(), 10u * (1u << (2 * s)) + 2u);
        for (const Vec3& v : m.vertices) EXPECT_NEAR(norm(v - Vec3{1, -2, 3}), 0.25, 1e-12);
        // Closed and facing outward: the enclosed volume approaches the sphere's from below.
        const double sphere = 4.0 / 3.0 * std::numbers::pi * 0.25 * 0.25 * 0.25;
        TriangleMesh centred = m;
        for (Vec3& v : centred.vertices) v -= Vec3{1, -2, 3};
        EXPECT_GT(signed_volume(centred), (1.0 - 0.45 * std::pow(0.5, s)) * sphere);
        EXPECT_LT(signed_volume(centred), sphere);
    }
}

TEST(GeometryShapes, TubeFollowsThePolyline) {
    const std::vector<Vec3> points = {{0, 0, 0}, {1, 0, 0}, {1.5, 0.8, 0}, {1.5, 0.8, 0}, {1.5, 2, 1}};
    const int sides = 7;
    const TriangleMesh m = geometry::tube(points, 0.1, sides);
    EXPECT_EQ(m.triangles.size(), size_t(2 * sides * (points.size() - 1) + 2 * sides));
    EXPECT_EQ(m.vertices.size(), points.size() * sides + 2);
    for (size_t i = 0; i < points.size(); ++i)
        for (int k = 0; k < sides; ++k) EXPECT_NEAR(norm(m.vertices[i * sides + k] - points[i]), 0.1, 1e-12);
    // Straight tube: closed and facing outward, volume about pi r^2 L (a heptagon's area is smaller).
    const TriangleMesh straight = geometry::tube({{0, 0, 0}, {2, 0, 0}}, 0.1, 32);
    EXPECT_NEAR(signed_volume(straight), std::numbers::pi * 0.01 * 2.0, 0.01 * std::numbers::pi * 0.01 * 2.0);
}

TEST(GeometryShapes, DefaultShapesInTheScene) {
    Exemplar ex;
    ex.dimension = 2;
    ex.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    const int dot = ex.type_index("dot"), stick = ex.type_index("stick");
    ex.add_element(dot, {{1, 1, 0}}, 0.3);
    ex.add_element(dot, {{3, 1, 0}});  // no radius: half the spacing
    ex.add_element(stick, {{5, 5, 0}, {6, 5, 0}, {7, 6, 0}}, 0.2);
    ex.add_element(stick, {{1, 8, 0}, {2, 8, 0}, {3, 8, 0}});  // no radius: a fifth of the spacing
    GeometryOptions options;
    options.sphere_subdivisions = 1;
    options.tube_sides = 6;
    const Scene scene = build_scene(ex, options);
    ASSERT_EQ(scene.instances.size(), 4u);
    // The dots share one unit sphere, instanced with their radius as scale (so instancing
    // outputs carry them as points); the sticks' tubes follow their samples, meshes of their own.
    EXPECT_EQ(scene.meshes.size(), 3u);
    EXPECT_TRUE(scene.instances[0].instanced && scene.instances[1].instanced);
    EXPECT_EQ(scene.instances[0].mesh, scene.instances[1].mesh);
    EXPECT_EQ(scene.instances[0].scale, 0.3);
    EXPECT_EQ(scene.instances[0].position, Vec3(1, 1, 0));
    for (const Vec3& v : scene.meshes[scene.instances[0].mesh].vertices) EXPECT_NEAR(norm(v), 1.0, 1e-12);
    EXPECT_FALSE(scene.instances[2].instanced || scene.instances[3].instanced);
    const double spacing = mean_nearest_neighbor_distance(ex);
    const auto radius_of_sphere = [&](int i) { return norm(scene.world_mesh(i).vertices[0] - ex.samples[ex.elements[i].first_sample].p); };
    EXPECT_NEAR(radius_of_sphere(0), 0.3, 1e-12);
    EXPECT_NEAR(radius_of_sphere(1), 0.5 * spacing, 1e-12);
    const TriangleMesh tube = scene.world_mesh(2);
    EXPECT_EQ(tube.triangles.size(), size_t(2 * 6 * 2 + 2 * 6));
    EXPECT_NEAR(norm(tube.vertices[0] - Vec3(5, 5, 0)), 0.2, 1e-12);
    EXPECT_NEAR(norm(scene.world_mesh(3).vertices[0] - Vec3(1, 8, 0)), 0.2 * spacing, 1e-12);
    // 2D data sit in the z = 0 plane: every shape is centred on it.
    const TriangleMesh all = scene.merged();
    double zmin = 0.0, zmax = 0.0;
    for (const Vec3& v : all.vertices) zmin = std::min(zmin, v.z), zmax = std::max(zmax, v.z);
    EXPECT_NEAR(zmin, -zmax, 1e-12);
    EXPECT_GT(zmax, 0.0);
}

TEST(GeometryShapes, MergedCountsAndTriangleOwners) {
    Exemplar ex;
    ex.dimension = 3;
    ex.domain = Domain::box({0, 0, 0}, {4, 4, 4}, 3);
    ex.add_element(ex.type_index("ball"), {{1, 1, 1}}, 0.2);
    ex.add_element(ex.type_index("ball"), {{2, 2, 2}}, 0.2);
    const Scene scene = build_scene(ex);
    std::vector<int> owner;
    const TriangleMesh all = scene.merged(&owner);
    EXPECT_EQ(all.vertices.size(), 2 * scene.meshes[0].vertices.size());
    EXPECT_EQ(all.triangles.size(), 2 * scene.meshes[0].triangles.size());
    ASSERT_EQ(owner.size(), all.triangles.size());
    EXPECT_EQ(owner.front(), 0);
    EXPECT_EQ(owner.back(), 1);
    // Triangles of the second instance index its own vertices.
    EXPECT_GE(all.triangles.back()[0], static_cast<int>(scene.meshes[0].vertices.size()));
}
