// Tests of the 3D mesh and shell domains: an icosphere and a cube written as OBJ/PLY
// here, voxel measure against the true volume, inside away from the surface, a
// crack (one triangle removed), an open sheet (error), shell volume, parse errors.
#include <gtest/gtest.h>

#include "test_meshes.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>

#include "tessera/domain.hpp"
#include "tessera/error.hpp"
#include "tessera/mesh.hpp"
#include "core/triangle_tree.hpp"
#include "core/winding_number.hpp"

using namespace tessera;

namespace {

using test::icosphere;

// Volume of a closed mesh (divergence theorem): the exact volume the voxels approximate.
double mesh_volume(const TriangleMesh& m) {
    double v = 0;
    for (const auto& f : m.triangles) v += dot(m.vertices[f[0]], cross(m.vertices[f[1]], m.vertices[f[2]])) / 6.0;
    return v;
}

std::string write(const std::string& name, const std::string& text) {
    const std::string path = (std::filesystem::temp_directory_path() / name).string();
    std::ofstream(path) << text;
    return path;
}

}  // namespace

TEST(DomainMesh, CubeFromObjHasTheRightVolume) {
    const std::string path = write("tessera_cube.obj",
                                   "# unit cube, quads\n"
                                   "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nv 0 0 2\nv 2 0 2\nv 2 2 2\nv 0 2 2\n"
                                   "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
    const Domain d = Domain::mesh(path, 64);
    EXPECT_EQ(d.kind(), Domain::Kind::mesh);
    EXPECT_NEAR(d.measure(), 8.0, 0.03 * 8.0);
    EXPECT_TRUE(d.inside({1, 1, 1}));
    EXPECT_TRUE(d.inside({0.1, 1.9, 0.1}));
    EXPECT_FALSE(d.inside({2.2, 1, 1}));
    EXPECT_EQ(d.notes(), "");
    std::filesystem::remove(path);
}

TEST(DomainMesh, SphereVolumeInsideAndBoundaryQueries) {
    const TriangleMesh m = icosphere(3);  // 1280 triangles
    const Domain d = Domain::mesh(m, 64, "sphere");
    const double volume = mesh_volume(m);
    EXPECT_NEAR(d.measure(), volume, 0.03 * volume);
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> u(-1.3, 1.3);
    const double h = 2.0 / 60;  // cell size
    for (int i = 0; i < 4000; ++i) {
        const Vec3 p{u(rng), u(rng), u(rng)};
        const double r = norm(p);
        if (r < 0.97) { EXPECT_TRUE(d.inside(p)) << r; }
        if (r > 1.02) { EXPECT_FALSE(d.inside(p)) << r; }
        if (d.inside(p)) {
            // Never more than the true distance to the (voxel) boundary, up to a cell.
            EXPECT_LE(d.distance_to_boundary(p), std::max(0.0, 1.0 - r) + h) << r;
        } else {
            const Vec3 q = d.closest_inside(p);
            EXPECT_TRUE(d.inside(q));
            EXPECT_NEAR(norm(q), 1.0, 2 * h);
        }
    }
}

TEST(DomainMesh, ACrackStillGivesTheRightInside) {
    TriangleMesh m = icosphere(3);
    m.triangles.erase(m.triangles.begin() + 100);
    const Domain d = Domain::mesh(m, 64, "cracked.obj");
    EXPECT_NEAR(d.measure(), mesh_volume(icosphere(3)), 0.03 * 4.0);
    EXPECT_NE(d.notes().find("3 boundary edges"), std::string::npos) << d.notes();
    EXPECT_NE(d.notes().find("winding number"), std::string::npos);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(-1.3, 1.3);
    for (int i = 0; i < 3000; ++i) {
        const Vec3 p{u(rng), u(rng), u(rng)};
        if (norm(p) < 0.95) { EXPECT_TRUE(d.inside(p)); }
        if (norm(p) > 1.05) { EXPECT_FALSE(d.inside(p)); }
    }
}

TEST(DomainMesh, ASelfOverlappingMeshIsTheUnionAndSaysSo) {
    // Two unit-radius spheres whose volumes overlap (centres 1 apart), as one mesh: a
    // self-intersecting surface. The domain is their union, and the notes report it.
    TriangleMesh m = icosphere(3);
    const TriangleMesh other = icosphere(3);
    const int base = static_cast<int>(m.vertices.size());
    for (const Vec3& v : other.vertices) m.vertices.push_back(v + Vec3{1, 0, 0});
    for (const auto& t : other.triangles) m.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    const Domain d = Domain::mesh(m, 64, "twins.obj");
    const double sphere = mesh_volume(icosphere(3));
    const double lens = 5.0 / 12.0 * 3.14159265358979 * 1.0;  // overlap of two unit balls 1 apart
    EXPECT_NEAR(d.measure(), 2 * sphere - lens, 0.04 * 2 * sphere);
    EXPECT_TRUE(d.inside({0.5, 0, 0}));  // in both
    EXPECT_TRUE(d.inside({1.8, 0, 0}));  // in the second only
    EXPECT_NE(d.notes().find("overlaps itself"), std::string::npos) << d.notes();
    EXPECT_NE(d.notes().find("union"), std::string::npos);
}

TEST(DomainMesh, AnOpenSheetEnclosesNoVolume) {
    TriangleMesh sheet;
    sheet.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.2}, {0, 1, 0.2}};  // planar, tilted
    sheet.triangles = {{0, 1, 2}, {0, 2, 3}};
    try {
        Domain::mesh(sheet, 32, "sheet.obj");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::domain);
        EXPECT_NE(std::string(e.what()).find("encloses no volume"), std::string::npos) << e.what();
    }
}

TEST(DomainMesh, ShellVolumeIsCloseToTheAnalyticShell) {
    const TriangleMesh m = icosphere(3);
    const double thickness = 0.25;
    const Domain d = Domain::shell(m, thickness, 64, "sphere");
    EXPECT_EQ(d.kind(), Domain::Kind::shell);
    // The polyhedron's inscribed radius is a little below 1: use its volume-equivalent radius.
    const double r = std::cbrt(mesh_volume(m) * 3 / (4 * M_PI));
    const double expected = 4.0 / 3.0 * M_PI * (r * r * r - std::pow(r - thickness, 3));
    EXPECT_NEAR(d.measure(), expected, 0.05 * expected);
    EXPECT_FALSE(d.inside({0, 0, 0}));
    EXPECT_TRUE(d.inside({0, 0, 0.88}));
    EXPECT_FALSE(d.inside({0, 0, 1.1}));
    EXPECT_THROW(Domain::shell(m, 0.0, 64, "sphere"), Error);
}

TEST(DomainMesh, ScaledMeshScalesMeasure) {
    const Domain d = Domain::mesh(icosphere(2), 32, "sphere");
    EXPECT_NEAR(d.scaled(2.0).measure(), 8 * d.measure(), 1e-9);
    EXPECT_TRUE(d.scaled(2.0).inside(d.bounds().lo + (d.bounds().center() - d.bounds().lo) * 2.0));
}

TEST(DomainMesh, TranslatedOverlapOfASphereAtZeroIsItsVolume) {
    const Domain d = Domain::mesh(icosphere(2), 32, "sphere");
    EXPECT_NEAR(d.translated_overlap({0, 0, 0}), d.measure(), 0.05 * d.measure());
    EXPECT_DOUBLE_EQ(d.translated_overlap({3, 0, 0}), 0.0);
}

TEST(MeshIo, PlyReadsAndErrorsNameFileAndLine) {
    const std::string ply = write("tessera_tet.ply",
                                  "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                                  "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n"
                                  "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
    const TriangleMesh m = read_triangle_mesh(ply);
    EXPECT_EQ(m.vertices.size(), 4u);
    EXPECT_EQ(m.triangles.size(), 4u);
    EXPECT_NEAR(mesh_volume(m), 1.0 / 6.0, 1e-12);
    const std::string bad = write("tessera_bad.ply",
                                  "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                                  "property float z\nend_header\n0 zero 0\n");
    try {
        read_triangle_mesh(bad);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::input);
        EXPECT_NE(std::string(e.what()).find("tessera_bad.ply:8:"), std::string::npos) << e.what();
    }
    std::filesystem::remove(ply);
    std::filesystem::remove(bad);
}

TEST(MeshIo, ObjErrorsNameFileAndLine) {
    const std::string obj = write("tessera_bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n");
    try {
        read_triangle_mesh(obj);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::input);
        EXPECT_NE(std::string(e.what()).find("tessera_bad.obj:5:"), std::string::npos) << e.what();
    }
    EXPECT_THROW(parse_obj("v 0 0 x\n", "a.obj"), Error);
    try {
        read_triangle_mesh("/nonexistent/bowl.obj");
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::io);
    }
    std::filesystem::remove(obj);
}

namespace {

// The exact references: generalized winding number, and the nearest triangle by brute force.
bool inside_mesh(const TriangleMesh& m, const Vec3& p) { return std::abs(core::generalized_winding_number(m, p)) >= 0.5; }

double surface_distance(const TriangleMesh& m, const Vec3& p) {
    double d2 = INFINITY;
    for (const auto& t : m.triangles)
        d2 = std::min(d2, core::triangle_distance_squared(p, m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]));
    return std::sqrt(d2);
}

// Points within a cell or so of the torus' surface, where voxels are unreliable.
std::vector<Vec3> points_near_torus(double ring, double tube, double spread, int count) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> angle(0, 2 * M_PI), offset(-spread, spread);
    std::vector<Vec3> points;
    for (int i = 0; i < count; ++i) {
        const double u = angle(rng), v = angle(rng), r = tube + offset(rng);
        const double rho = ring + r * std::cos(v);
        points.push_back({rho * std::cos(u), rho * std::sin(u), r * std::sin(v)});
    }
    return points;
}

}  // namespace

TEST(DomainMesh, InsideOfATorusIsExactNotTheVoxels) {
    const TriangleMesh m = test::torus(1.0, 0.35);
    const Domain d = Domain::mesh(m, 32, "torus");
    int wrong = 0, voxel_wrong = 0;
    for (const Vec3& p : points_near_torus(1.0, 0.35, 0.08, 4000)) {
        const bool truth = inside_mesh(m, p);
        wrong += d.inside(p) != truth;
        voxel_wrong += (d.occupancy(p) >= 0.5) != truth;
    }
    EXPECT_EQ(wrong, 0);
    EXPECT_GT(voxel_wrong, 100) << "the test points must be where the voxels alone are wrong";
    EXPECT_FALSE(d.inside({0, 0, 0})) << "the hole through the torus";
    EXPECT_TRUE(d.inside({1, 0, 0}));
}

TEST(DomainMesh, InsideOfAThinShellIsExact) {
    const TriangleMesh m = test::torus(1.0, 0.35);
    const double thickness = 0.06;  // about one cell of the grid
    const Domain d = Domain::shell(m, thickness, 48, "torus");
    int wrong = 0, in = 0;
    for (const Vec3& p : points_near_torus(1.0, 0.35, 0.1, 3000)) {
        const bool truth = inside_mesh(m, p) && surface_distance(m, p) <= thickness;
        wrong += d.inside(p) != truth;
        in += truth;
    }
    EXPECT_EQ(wrong, 0);
    EXPECT_GT(in, 500);
    // closest_inside lands in the exact shell.
    for (const Vec3& p : points_near_torus(1.0, 0.35, 0.3, 300)) EXPECT_TRUE(d.inside(d.closest_inside(p)));
}
