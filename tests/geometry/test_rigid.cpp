// Rigid elements with a mesh (geometry.hpp): the type's mesh is posed on every element by
// the Kabsch fit of its reference layout, so the rebuilt element keeps the input shape and,
// for data built consistently, the element's own pose.
#include <numbers>

#include "geometry_test_util.hpp"
#include "tessera/io.hpp"

using namespace geometry_test;

namespace {

class GeometryRigid : public TempDir {
protected:
    // One rigid type with the tetrahedron mesh and the layout `reference`, and one
    // element per pose: samples = position + scale * R * reference.
    Exemplar posed_copies(int dimension, const std::vector<Vec3>& reference, const std::vector<Quat>& rotations,
                          double scale, bool explicit_reference) {
        Exemplar ex;
        ex.dimension = dimension;
        ex.domain = dimension == 2 ? Domain::box({-10, -10, 0}, {10, 10, 0}, 2)
                                   : Domain::box({-10, -10, -10}, {10, 10, 10}, 3);
        ElementType type;
        type.name = "shard";
        type.mesh = write_mesh("shard.obj", tetrahedron());
        if (explicit_reference) type.reference = reference;
        ex.types.push_back(type);
        for (size_t i = 0; i < rotations.size(); ++i) {
            const Vec3 at{1.5 * i - 3.0, 0.5 * i, dimension == 3 ? -0.25 * i : 0.0};
            std::vector<Vec3> samples;
            for (const Vec3& r : reference) samples.push_back(at + rotations[i].rotate(r * scale));
            const int e = ex.add_element(0, samples);
            ex.elements[e].orientation = rotations[i];
            ex.elements[e].scale = scale;
        }
        ex.validate("test");
        return ex;
    }

    // Posed reference samples equal the samples; the rebuilt mesh is the mesh moved rigidly.
    void expect_shape_kept(const Exemplar& ex, const std::vector<Vec3>& reference) {
        const Scene scene = build_scene(ex);
        ASSERT_EQ(scene.instances.size(), ex.elements.size());
        ASSERT_EQ(scene.meshes.size(), 1u);  // one shared mesh
        for (size_t i = 0; i < ex.elements.size(); ++i) {
            const SceneInstance& inst = scene.instances[i];
            const Element& el = ex.elements[i];
            EXPECT_TRUE(inst.instanced);
            EXPECT_EQ(inst.element, static_cast<int>(i));
            EXPECT_EQ(inst.id, el.id);
            std::vector<Vec3> samples, fitted;
            for (int s = 0; s < el.sample_count; ++s) {
                samples.push_back(ex.samples[el.first_sample + s].p);
                fitted.push_back(posed(inst, reference[s]));
            }
            EXPECT_LT(max_distance(fitted, samples), 1e-9) << "element " << i;
            EXPECT_LT(pairwise_distance_change(fitted, samples), 1e-6);
            EXPECT_LT(inst.fit_error, 1e-9);
            // The world mesh is the mesh scaled and moved rigidly.
            const TriangleMesh world = scene.world_mesh(static_cast<int>(i));
            std::vector<Vec3> scaled;
            for (const Vec3& v : tetrahedron().vertices) scaled.push_back(v * el.scale);
            EXPECT_LT(pairwise_distance_change(world.vertices, scaled), 1e-6);
            EXPECT_GT(signed_volume(world), 0.0);  // not mirrored
        }
    }
};

const std::vector<Vec3> layout2d = {{-0.6, -0.2, 0}, {0.4, -0.2, 0}, {0.2, 0.4, 0}};
const std::vector<Vec3> layout3d = {{-0.6, -0.2, 0.1}, {0.4, -0.2, -0.3}, {0.2, 0.4, 0.0}, {0.0, 0.0, 0.2}};

}  // namespace

TEST_F(GeometryRigid, Rotated2DElementsKeepTheirShape) {
    const std::vector<Quat> turns = {Quat{}, Quat::from_angle_z(0.7), Quat::from_angle_z(-2.9), Quat::from_angle_z(3.1)};
    expect_shape_kept(posed_copies(2, layout2d, turns, 1.0, true), layout2d);
    // The layout derived from the first element is the same, so the same holds.
    expect_shape_kept(posed_copies(2, layout2d, turns, 1.0, false), layout2d);
}

TEST_F(GeometryRigid, Rotated3DElementsKeepTheirShape) {
    const std::vector<Quat> turns = {unit(1, 0, 0, 0), unit(0.3, 0.5, -0.7, 0.1), unit(-0.2, 0.9, 0.1, 0.4),
                                     unit(0.01, 0.0, 1.0, 0.0)};
    expect_shape_kept(posed_copies(3, layout3d, turns, 1.5, true), layout3d);
    expect_shape_kept(posed_copies(3, layout3d, turns, 1.5, false), layout3d);
}

TEST_F(GeometryRigid, ConsistentDataKeepTheirJsonPose) {
    // A hand-written file whose elements are the reference (centred, as the mesh's frame
    // has its origin at the samples' centroid) posed by their own orientation.
    write_mesh("rod.obj", tetrahedron());
    write("rods.json", R"({"format": "tessera", "version": 1, "dimension": 3,
        "domain": {"type": "box", "min": [0, 0, 0], "max": [10, 10, 10]},
        "types": [{"name": "rod", "mesh": "rod.obj", "reference": [[-1, -0.25, 0], [0, 0.5, 0], [1, -0.25, 0]]}],
        "elements": [
          {"samples": [[2, 1.75, 2], [3, 2.5, 2], [4, 1.75, 2]]},
          {"samples": [[5, 4.75, 4], [5, 5.5, 5], [5, 4.75, 6]], "orientation": [0.7071067811865476, 0, -0.7071067811865476, 0]},
          {"samples": [[0.75, 7, 1], [1.5, 7, 2], [0.75, 7, 3]], "orientation": [0.5, -0.5, -0.5, -0.5], "scale": 1}]})");
    const Exemplar ex = load(path("rods.json"));
    const Scene scene = build_scene(ex);
    for (size_t i = 0; i < ex.elements.size(); ++i) {
        const SceneInstance& inst = scene.instances[i];
        EXPECT_LT(norm(inst.position - ex.elements[i].position), 1e-12) << i;
        EXPECT_EQ(inst.orientation, ex.elements[i].orientation) << i;
        EXPECT_EQ(inst.scale, ex.elements[i].scale);
        EXPECT_LT(inst.fit_error, 1e-12);
    }
}

TEST_F(GeometryRigid, TwistOfALineOfSamplesComesFromTheElement) {
    // Two samples fix a 3D stick's axis but not its twist about it: the element's orientation does.
    const std::vector<Vec3> stick = {{-1, 0, 0}, {1, 0, 0}};
    const Quat twist = unit(std::cos(0.6), std::sin(0.6), 0, 0);  // about the stick's own axis
    const Quat turn = unit(0.8, 0.1, 0.3, -0.5);
    Exemplar ex = posed_copies(3, stick, {twist, turn * twist}, 1.0, true);
    const Scene scene = build_scene(ex);
    EXPECT_EQ(scene.instances[0].orientation, twist);
    EXPECT_EQ(scene.instances[1].orientation, ex.elements[1].orientation);
}

TEST_F(GeometryRigid, WrongOrientationIsOverriddenByTheFit) {
    // Samples rotated by 1 rad while the element claims no rotation: the fit wins.
    Exemplar ex = posed_copies(2, layout2d, {Quat{}, Quat::from_angle_z(1.0)}, 1.0, true);
    ex.elements[1].orientation = Quat{};
    const Scene scene = build_scene(ex);
    EXPECT_NEAR(scene.instances[1].orientation.angle_z(), 1.0, 1e-12);
    EXPECT_LT(scene.instances[1].fit_error, 1e-9);
}

TEST_F(GeometryRigid, FitErrorReportsSamplesThatAreNotACopy) {
    Exemplar ex = posed_copies(2, layout2d, {Quat{}, Quat{}}, 1.0, true);
    ex.samples[ex.elements[1].first_sample].p += Vec3{0.3, 0, 0};  // stretched: no rigid copy fits
    const Scene scene = build_scene(ex);
    EXPECT_LT(scene.instances[0].fit_error, 1e-12);
    EXPECT_GT(scene.instances[1].fit_error, 0.05);
}

TEST_F(GeometryRigid, SingleSampleElementsUseTheirPose) {
    Exemplar ex;
    ex.dimension = 3;
    ex.domain = Domain::box({0, 0, 0}, {5, 5, 5}, 3);
    ex.types.push_back({"rock", true, false, write_mesh("rock.obj", tetrahedron()), {}, std::nullopt});
    const int e = ex.add_element(0, {{1, 2, 3}});
    ex.elements[e].orientation = unit(0.2, 0.4, -0.1, 0.8);
    ex.elements[e].scale = 0.5;
    const Scene scene = build_scene(ex);
    EXPECT_EQ(scene.instances[0].position, Vec3(1, 2, 3));
    EXPECT_EQ(scene.instances[0].orientation, ex.elements[e].orientation);
    EXPECT_EQ(scene.instances[0].scale, 0.5);
    const TriangleMesh world = scene.world_mesh(0);
    EXPECT_LT(norm(world.vertices[1] - posed(scene.instances[0], tetrahedron().vertices[1])), 1e-12);
}
