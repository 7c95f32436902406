// Deformable elements (geometry.hpp): a straight tube authored around a straight
// reference polyline and bent onto a circular arc must stay a tube of the same radius
// around the arc, without tears, in 2D (arc in the z = 0 plane) and 3D (a tilted plane).
#include <numbers>

#include "geometry/geometry_internal.hpp"
#include "geometry_test_util.hpp"
#include "tessera/error.hpp"

using namespace geometry_test;

namespace {

constexpr int samples = 21;
constexpr double spacing = 0.1;       // between consecutive reference samples
constexpr double tube_radius = 0.05;  // half the spacing: the bend is sharp relative to the samples
constexpr int sides = 12;

// A closed straight tube along x from the first to the last reference sample, with
// rings at the samples and halfway between them.
TriangleMesh straight_tube() {
    TriangleMesh m;
    const int rings = 2 * (samples - 1) + 1;
    for (int i = 0; i < rings; ++i)
        for (int k = 0; k < sides; ++k) {
            const double a = 2.0 * std::numbers::pi * k / sides;
            m.vertices.push_back({(i * 0.5 - 10.0) * spacing, tube_radius * std::cos(a), tube_radius * std::sin(a)});
        }
    for (int i = 0; i + 1 < rings; ++i)
        for (int k = 0; k < sides; ++k) {
            const int a = i * sides + k, b = i * sides + (k + 1) % sides;
            m.triangles.push_back({a, b, b + sides});
            m.triangles.push_back({a, b + sides, a + sides});
        }
    const int start = static_cast<int>(m.vertices.size());
    m.vertices.push_back({-10.0 * spacing, 0, 0});
    m.vertices.push_back({10.0 * spacing, 0, 0});
    for (int k = 0; k < sides; ++k) {
        m.triangles.push_back({start, (k + 1) % sides, k});
        const int last = (rings - 1) * sides;
        m.triangles.push_back({start + 1, last + k, last + (k + 1) % sides});
    }
    return m;
}

struct Arc {
    Vec3 centre, e1, e2;  // the arc's plane is spanned by e1, e2 (orthonormal)
    double radius = 1.0;
    Vec3 at(double angle) const { return centre + (e1 * std::cos(angle) + e2 * std::sin(angle)) * radius; }
    // Distance from p to the whole circle.
    double distance(const Vec3& p) const {
        const Vec3 d = p - centre;
        const Vec3 normal = cross(e1, e2);
        const double h = dot(d, normal);
        const double in_plane = norm(d - normal * h);
        return std::hypot(in_plane - radius, h);
    }
};

class GeometryDeform : public TempDir, public ::testing::WithParamInterface<int> {};

}  // namespace

TEST_P(GeometryDeform, TubeBentOntoAnArcKeepsItsRadiusAndIsNotTorn) {
    const int dimension = GetParam();
    const TriangleMesh rest = straight_tube();
    Exemplar ex;
    ex.dimension = dimension;
    ex.domain = dimension == 2 ? Domain::box({-3, -3, 0}, {3, 3, 0}, 2) : Domain::box({-3, -3, -3}, {3, 3, 3}, 3);
    ElementType noodle;
    noodle.name = "noodle";
    noodle.rigid = false;
    noodle.mesh = write_mesh("tube.obj", rest);
    for (int i = 0; i < samples; ++i) noodle.reference.push_back({(i - 10) * spacing, 0, 0});
    ex.types.push_back(noodle);

    // A half circle of the same length: consecutive samples keep their distance along the arc.
    Arc arc;
    arc.radius = (samples - 1) * spacing / std::numbers::pi;
    if (dimension == 2) {
        arc.centre = {0.3, -0.2, 0};
        arc.e1 = {1, 0, 0};
        arc.e2 = {0, 1, 0};
    } else {
        arc.centre = {0.3, -0.2, 0.5};
        arc.e1 = Vec3{1, 1, 1} / std::sqrt(3.0);
        arc.e2 = Vec3{1, -1, 0} / std::sqrt(2.0);
    }
    std::vector<Vec3> bent;
    for (int i = 0; i < samples; ++i) bent.push_back(arc.at(std::numbers::pi * i / (samples - 1)));
    ex.add_element(0, bent);

    const Scene scene = build_scene(ex);
    ASSERT_EQ(scene.instances.size(), 1u);
    EXPECT_FALSE(scene.instances[0].instanced);
    const TriangleMesh out = scene.world_mesh(0);
    ASSERT_EQ(out.vertices.size(), rest.vertices.size());
    ASSERT_EQ(out.triangles, rest.triangles);

    // Every tube-wall vertex lies on the tube of the same radius around the arc.
    double worst = 0.0;
    for (size_t v = 0; v < rest.vertices.size(); ++v) {
        if (std::hypot(rest.vertices[v].y, rest.vertices[v].z) < 0.5 * tube_radius) continue;  // cap centres
        worst = std::max(worst, std::abs(arc.distance(out.vertices[v]) - tube_radius));
    }
    EXPECT_LT(worst, 0.05 * tube_radius);
    // The cap centres stay on the arc's ends.
    EXPECT_LT(norm(out.vertices[rest.vertices.size() - 2] - bent.front()), 0.05 * tube_radius);
    EXPECT_LT(norm(out.vertices[rest.vertices.size() - 1] - bent.back()), 0.05 * tube_radius);

    // Not torn: every edge keeps its length within a factor 1.5 (the inner side shortens by
    // about radius / arc radius = 16%, the outer side lengthens as much).
    for (const auto& t : rest.triangles)
        for (int k = 0; k < 3; ++k) {
            const double before = norm(rest.vertices[t[k]] - rest.vertices[t[(k + 1) % 3]]);
            const double after = norm(out.vertices[t[k]] - out.vertices[t[(k + 1) % 3]]);
            EXPECT_LT(after, 1.5 * before);
            EXPECT_GT(after, before / 1.5);
        }
}

TEST_P(GeometryDeform, UnbentElementMovesRigidly) {
    const int dimension = GetParam();
    const TriangleMesh rest = straight_tube();
    std::vector<Vec3> reference;
    for (int i = 0; i < samples; ++i) reference.push_back({(i - 10) * spacing, 0, 0});
    const Quat r = dimension == 2 ? Quat::from_angle_z(2.5) : unit(0.3, -0.5, 0.7, 0.2);
    const Vec3 t{1.5, -0.25, dimension == 2 ? 0.0 : 0.75};
    std::vector<Vec3> moved;
    for (const Vec3& p : reference) moved.push_back(r.rotate(p) + t);
    const TriangleMesh out = geometry::deform_mesh(rest, reference, moved.data(), 1.0, 1.0, dimension);
    // A straight reference leaves the twist about its line free: only the distance from the
    // line and the position along it are fixed. Both must be kept.
    for (size_t v = 0; v < rest.vertices.size(); ++v) {
        const Vec3 local = r.conjugate().rotate(out.vertices[v] - t);
        EXPECT_NEAR(local.x, rest.vertices[v].x, 1e-9);
        EXPECT_NEAR(std::hypot(local.y, local.z), std::hypot(rest.vertices[v].y, rest.vertices[v].z), 1e-9);
    }
    EXPECT_LT(pairwise_distance_change(rest.vertices, out.vertices), 1e-9);
}

TEST(GeometryDeformScale, StretchesTheMesh) {
    // Element scale 2: the deformed mesh is the rest mesh at twice the size.
    const TriangleMesh rest = tetrahedron();
    const std::vector<Vec3> reference = {{-0.5, 0, 0}, {0, 0.2, 0}, {0.5, 0, 0.1}};
    std::vector<Vec3> scaled;
    for (const Vec3& p : reference) scaled.push_back(p * 2.0 + Vec3{1, 2, 3});
    const TriangleMesh out = geometry::deform_mesh(rest, reference, scaled.data(), 2.0, 1.0, 3);
    for (size_t v = 0; v < rest.vertices.size(); ++v)
        EXPECT_LT(norm(out.vertices[v] - (rest.vertices[v] * 2.0 + Vec3{1, 2, 3})), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Geometry, GeometryDeform, ::testing::Values(2, 3),
                         [](const ::testing::TestParamInfo<int>& info) { return std::to_string(info.param) + "D"; });

TEST(GeometryDeformSingle, SingleSampleFollowsTheElementPose) {
    // One sample fixes no rotation: the element's orientation turns the mesh.
    const TriangleMesh rest = tetrahedron();
    const Quat turn = unit(0.4, -0.3, 0.8, 0.2);
    const Vec3 at{2, -1, 0.5};
    const TriangleMesh out = geometry::deform_mesh(rest, {{0, 0, 0}}, &at, 1.5, 1.0, 3, turn);
    for (size_t v = 0; v < rest.vertices.size(); ++v)
        EXPECT_LT(norm(out.vertices[v] - (at + turn.rotate(rest.vertices[v] * 1.5))), 1e-12);
}
