// Orientation fields read from files: grids (JSON) sampled from a known vortex,
// clamping, every malformed-file error; mesh-vertex fields on an icosphere written
// as PLY / OBJ (with and without faces); the frame with a normal; determinism across
// threads; a synthesis run steered by a grid field.
#include <gtest/gtest.h>

#include "test_meshes.hpp"
#include <unistd.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "tessera/tessera.hpp"

using namespace tessera;

namespace {

double degrees_between(const Vec3& a, const Vec3& b) {
    const double c = dot(a, b) / (norm(a) * norm(b));
    return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI;
}

// A file in the temp directory, unique to this process (tests run in parallel).
std::string write(const std::string& name, const std::string& text) {
    const std::string path =
        (std::filesystem::temp_directory_path() / ("tessera_field_" + std::to_string(getpid()) + "_" + name)).string();
    std::ofstream(path) << text;
    return path;
}

// The grid file of a vortex about `center` (counter-clockwise about +z), x fastest.
std::string vortex_grid_json(int dimension, const Vec3& origin, const Vec3& spacing, const std::array<int, 3>& size,
                             const Vec3& center) {
    std::ostringstream s;
    s.precision(17);
    auto list = [&](const Vec3& v) {
        s << "[" << v.x << "," << v.y;
        if (dimension == 3) s << "," << v.z;
        s << "]";
    };
    s << "{\"format\": \"tessera-field\", \"dimension\": " << dimension << ", \"origin\": ";
    list(origin);
    s << ", \"spacing\": ";
    list(spacing);
    s << ", \"size\": [" << size[0] << "," << size[1];
    if (dimension == 3) s << "," << size[2];
    s << "],\n\"vectors\": [";
    const OrientationField vortex = OrientationField::vortex(center);
    bool first = true;
    for (int k = 0; k < (dimension == 3 ? size[2] : 1); ++k)
        for (int j = 0; j < size[1]; ++j)
            for (int i = 0; i < size[0]; ++i) {
                s << (first ? "" : ",\n");
                first = false;
                list(vortex.direction(origin + Vec3{i * spacing.x, j * spacing.y, k * spacing.z}));
            }
    s << "]}\n";
    return s.str();
}

// Expects `fn` to throw tessera::Error whose message contains every one of `parts`.
template <class Fn>
void expect_error(Fn&& fn, const std::vector<std::string>& parts, ErrorKind kind = ErrorKind::input) {
    try {
        fn();
        ADD_FAILURE() << "no error; expected one mentioning " << parts.front();
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_EQ(e.kind(), kind) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
        for (const auto& part : parts) EXPECT_NE(message.find(part), std::string::npos) << part << " in: " << message;
    }
}

using test::icosphere;

// Along the line of latitude through p (relative to the sphere's centre), eastward.
Vec3 latitude_tangent(const Vec3& r) {
    const Vec3 t{-r.y, r.x, 0};
    return norm(t) > 1e-9 ? t / norm(t) : Vec3{1, 0, 0};  // the poles get +x
}

const Vec3 sphere_center{1, -2, 0.5};
constexpr double sphere_radius = 4.0;

// The icosphere scaled and moved, with latitude directions, as an ASCII PLY. With
// `flip_some`, every 7th face is written clockwise (the field orients them consistently).
std::string sphere_ply(bool faces, bool flip_some) {
    const TriangleMesh m = icosphere(3);
    std::ostringstream s;
    s.precision(17);
    s << "ply\nformat ascii 1.0\ncomment latitude field\nelement vertex " << m.vertices.size()
      << "\nproperty float x\nproperty float y\nproperty float z\nproperty float vx\nproperty float vy\n"
         "property float vz\n";
    if (faces) s << "element face " << m.triangles.size() << "\nproperty list uchar int vertex_indices\n";
    s << "end_header\n";
    for (const Vec3& v : m.vertices) {
        const Vec3 p = sphere_center + v * sphere_radius, d = latitude_tangent(v);
        s << p.x << " " << p.y << " " << p.z << " " << d.x << " " << d.y << " " << d.z << "\n";
    }
    if (faces)
        for (size_t f = 0; f < m.triangles.size(); ++f) {
            const auto& t = m.triangles[f];
            if (flip_some && f % 7 == 3)
                s << "3 " << t[0] << " " << t[2] << " " << t[1] << "\n";
            else
                s << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
        }
    return s.str();
}

// Random points near the sphere (radius +-10%), away from the poles (|z| < 0.7 r).
std::vector<Vec3> points_near_sphere(int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> gauss;
    std::uniform_real_distribution<double> radius(0.9 * sphere_radius, 1.1 * sphere_radius);
    std::vector<Vec3> out;
    while (static_cast<int>(out.size()) < count) {
        Vec3 u{gauss(rng), gauss(rng), gauss(rng)};
        u = u / norm(u);
        if (std::abs(u.z) > 0.7) continue;
        out.push_back(sphere_center + u * radius(rng));
    }
    return out;
}

}  // namespace

TEST(FieldGridFile, ReproducesTheSampledVortex) {
    const Vec3 center{15.5, 14.5, 0};
    const std::string path =
        write("vortex2.json", vortex_grid_json(2, {0, 0, 0}, {1, 1, 1}, {31, 31, 1}, center));
    const OrientationField f = OrientationField::parse("grid:" + path, 2, "--field");
    EXPECT_EQ(f.kind(), OrientationField::Kind::grid);
    EXPECT_EQ(f.data_dimension(), 2);
    EXPECT_NE(f.describe().find(path), std::string::npos);
    EXPECT_NE(f.describe().find("31 x 31 nodes"), std::string::npos) << f.describe();
    const OrientationField vortex = OrientationField::vortex(center);
    // Exactly at nodes.
    for (int j = 0; j < 31; j += 5)
        for (int i = 0; i < 31; i += 3) {
            const Vec3 p{double(i), double(j), 0};
            EXPECT_NEAR(norm(f.direction(p) - vortex.direction(p)), 0.0, 1e-12) << i << "," << j;
        }
    // Within 2 degrees at random points inside (away from the centre, where it turns fast).
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 30.0);
    double worst = 0.0;
    for (int k = 0; k < 2000; ++k) {
        const Vec3 p{u(rng), u(rng), 0};
        if (norm(p - center) < 3.0) continue;
        worst = std::max(worst, degrees_between(f.direction(p), vortex.direction(p)));
    }
    EXPECT_LT(worst, 2.0);
    // Frames follow the direction.
    const Vec3 p{3.3, 20.1, 0};
    EXPECT_NEAR(norm(f.frame(p, 2).rotate({1, 0, 0}) - f.direction(p)), 0.0, 1e-12);
}

TEST(FieldGridFile, TrilinearIn3DAndClampedOutside) {
    const Vec3 center{2.25, 1.75, 0};
    const std::string path =
        write("vortex3.json", vortex_grid_json(3, {-5, -6, -1}, {0.5, 0.5, 1.0}, {31, 29, 4}, center));
    const OrientationField f = OrientationField::grid_file(path);
    EXPECT_EQ(f.data_dimension(), 3);
    EXPECT_NE(f.describe().find("31 x 29 x 4 nodes"), std::string::npos) << f.describe();
    const OrientationField vortex = OrientationField::vortex(center);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> ux(-5, 10), uy(-6, 8), uz(-1, 2);
    double worst = 0.0;
    for (int k = 0; k < 2000; ++k) {
        const Vec3 p{ux(rng), uy(rng), uz(rng)};
        if (norm(Vec3{p.x, p.y, 0} - center) < 1.5) continue;
        worst = std::max(worst, degrees_between(f.direction(p), vortex.direction(p)));
    }
    EXPECT_LT(worst, 2.0);
    EXPECT_NEAR(norm(f.direction({-5, -6, 2}) - vortex.direction({-5, -6, 0})), 0.0, 1e-12);
    // Outside, clamped to the border: the same as the nearest border point.
    EXPECT_EQ(f.direction({-50, 1.3, 0.4}), f.direction({-5, 1.3, 0.4}));
    EXPECT_EQ(f.direction({3.1, 100, 9}), f.direction({3.1, 8, 2}));
    EXPECT_EQ(f.direction({1e9, -1e9, -1e9}), f.direction({10, -6, -1}));
    // Z of the 3D frame stays up (least twist) for a horizontal field.
    EXPECT_NEAR(norm(f.frame({7, 7, 0}, 3).rotate({0, 0, 1}) - Vec3{0, 0, 1}), 0.0, 1e-12);
    // The grid read through parse must match the exemplar's dimension.
    expect_error([&] { OrientationField::parse("grid:" + path, 2, "--field"); }, {"--field", path, "3D", "2D"});
}

TEST(FieldGridFile, OppositeNeighboursCancelToADegeneratePoint) {
    FieldGrid g;
    g.dimension = 2;
    g.size = {2, 2, 1};
    g.vectors = {{1, 0}, {-1, 0}, {1, 0}, {-1, 0}};  // a line field stored with both signs
    const OrientationField f = OrientationField::grid(g);
    EXPECT_EQ(f.direction({0.5, 0.5, 0}), Vec3{});
    EXPECT_EQ(f.frame({0.5, 0.5, 0}, 2), Quat{});
    EXPECT_EQ(f.frame({0.5, 0.3, 0}, 3), Quat{});
    EXPECT_NEAR(norm(f.direction({0.25, 0.5, 0}) - Vec3{1, 0, 0}), 0.0, 1e-12);
    // Node vectors are normalised first: magnitudes do not weigh the blend.
    g.vectors = {{10, 0}, {0, 1}, {10, 0}, {0, 1}};
    const Vec3 d = OrientationField::grid(g).direction({0.5, 0.5, 0});
    EXPECT_NEAR(degrees_between(d, {1, 1, 0}), 0.0, 1e-9);
    // A copy shares the data and answers alike.
    const OrientationField copy = f;
    EXPECT_EQ(copy.direction({0.2, 0.7, 0}), f.direction({0.2, 0.7, 0}));
}

TEST(FieldGridFile, MalformedFilesNameTheFileAndTheKey) {
    const std::string head2 = "{\"format\": \"tessera-field\", \"dimension\": 2, ";
    const std::string missing = (std::filesystem::temp_directory_path() / "tessera_field_no_such_file.json").string();
    expect_error([&] { OrientationField::grid_file(missing); }, {missing, "cannot open"}, ErrorKind::io);
    expect_error([&] { OrientationField::parse("grid:" + missing, 2, "--field"); }, {"--field", missing},
                 ErrorKind::io);
    const std::string ok_head = head2 + "\"origin\": [0, 0], \"spacing\": [1, 1], \"size\": [2, 3], ";
    const std::string count = write("count.json", ok_head + "\"vectors\": [[1,0],[1,0],[1,0],[1,0],[1,0]]}");
    expect_error([&] { OrientationField::grid_file(count); }, {count, "vectors", "expected 6", "got 5"});
    const std::string zero = write("zero.json", ok_head + "\"vectors\": [[1,0],[1,0],[1,0],[0,0],[1,0],[1,0]]}");
    expect_error([&] { OrientationField::grid_file(zero); }, {zero, "vectors[3]", "zero", "(1,1)"});
    const std::string inf = write("inf.json", ok_head + "\"vectors\": [[1,0],[1,0],[1,1e999],[1,0],[1,0],[1,0]]}");
    expect_error([&] { OrientationField::grid_file(inf); }, {inf, "vectors[2][1]", "1e999", "finite"});
    const std::string spacing = write(
        "spacing.json",
        head2 + "\"origin\": [0, 0], \"spacing\": [1, 0], \"size\": [2, 2], \"vectors\": [[1,0],[1,0],[1,0],[1,0]]}");
    expect_error([&] { OrientationField::grid_file(spacing); }, {spacing, "spacing[1]", "> 0"});
    const std::string negative = write(
        "negative.json",
        head2 + "\"origin\": [0, 0], \"spacing\": [-1, 1], \"size\": [2, 2], \"vectors\": [[1,0],[1,0],[1,0],[1,0]]}");
    expect_error([&] { OrientationField::grid_file(negative); }, {negative, "spacing[0]"});
    const std::string small = write(
        "small.json", head2 + "\"origin\": [0, 0], \"spacing\": [1, 1], \"size\": [1, 4], \"vectors\": [[1,0],[1,0],[1,0],[1,0]]}");
    expect_error([&] { OrientationField::grid_file(small); }, {small, "size[0]", ">= 2"});
    // Dimension mismatches: a 3-vector in a 2D grid, a 2D origin in a 3D grid.
    const std::string vec3 = write("vec3.json", ok_head + "\"vectors\": [[1,0],[1,0],[1,0],[1,0],[1,0,0],[1,0]]}");
    expect_error([&] { OrientationField::grid_file(vec3); }, {vec3, "vectors[4]", "expected 2 numbers", "got 3"});
    const std::string origin = write("origin.json", "{\"format\": \"tessera-field\", \"dimension\": 3, \"origin\": [0, 0], "
                                                    "\"spacing\": [1, 1, 1], \"size\": [2, 2, 2], \"vectors\": []}");
    expect_error([&] { OrientationField::grid_file(origin); }, {origin, "origin", "expected 3 numbers"});
    const std::string dim = write("dim.json", "{\"format\": \"tessera-field\", \"dimension\": 4}");
    expect_error([&] { OrientationField::grid_file(dim); }, {dim, "dimension", "2 or 3"});
    const std::string format = write("format.json", "{\"format\": \"tessera\", \"dimension\": 2}");
    expect_error([&] { OrientationField::grid_file(format); }, {format, "format", "tessera-field"});
    const std::string typo = write("typo.json", ok_head + "\"vector\": []}");
    expect_error([&] { OrientationField::grid_file(typo); }, {typo, "unknown key 'vector'"});
    const std::string text = write("text.json", ok_head + "\"vectors\": [[1,0],[1,\"a\"]]}");
    expect_error([&] { OrientationField::grid_file(text); }, {text, "vectors[1][1]", "number"});
    const std::string broken = write("broken.json", ok_head + "\"vectors\": [[1,0],[1,0]");
    expect_error([&] { OrientationField::grid_file(broken); }, {broken, "invalid JSON", "line"});
    expect_error([&] { OrientationField::parse("grid:", 2, "--field"); }, {"--field", "grid:FILE"}, ErrorKind::option);
    // The same checks apply to grids built in code.
    FieldGrid g;
    g.vectors = {{1, 0}, {1, 0}, {1, 0}, {NAN, 0}};
    expect_error([&] { OrientationField::grid(g, "my grid"); }, {"my grid", "vectors[3]", "finite", "(1,1)"});
}

TEST(FieldMeshFile, SphereFramesLieInTheTangentPlane) {
    const std::string path = write("sphere.ply", sphere_ply(true, true));
    const OrientationField f = OrientationField::parse("mesh:" + path, 3, "--field");
    EXPECT_EQ(f.kind(), OrientationField::Kind::mesh);
    EXPECT_EQ(f.data_dimension(), 3);
    EXPECT_NE(f.describe().find(path), std::string::npos);
    EXPECT_NE(f.describe().find("642 vertices, 1280 triangles"), std::string::npos) << f.describe();
    double worst_z = 0.0, worst_x = 0.0;
    for (const Vec3& p : points_near_sphere(3000, 3)) {
        const Quat q = f.frame(p, 3);
        const Vec3 outward = (p - sphere_center) / norm(p - sphere_center);
        worst_z = std::max(worst_z, degrees_between(q.rotate({0, 0, 1}), outward));
        worst_x = std::max(worst_x, degrees_between(q.rotate({1, 0, 0}), latitude_tangent(p - sphere_center)));
        EXPECT_LT(degrees_between(f.direction(p), latitude_tangent(p - sphere_center)), 10.0);
    }
    EXPECT_LT(worst_z, 5.0);
    EXPECT_LT(worst_x, 10.0);
    // Far away (outside the acceleration grid) and at the centre the closest point is still found.
    const Vec3 far = sphere_center + Vec3{100, 3, -2};
    EXPECT_LT(degrees_between(f.frame(far, 3).rotate({0, 0, 1}), far - sphere_center), 5.0);
    EXPECT_LT(degrees_between(f.direction(far), latitude_tangent(far - sphere_center)), 10.0);
    const Quat at_center = f.frame(sphere_center, 3);
    EXPECT_NEAR(norm(at_center.rotate({1, 0, 0})), 1.0, 1e-12);
    // A mesh field is 3D.
    expect_error([&] { OrientationField::parse("mesh:" + path, 2, "--field"); }, {"--field", path, "3D"},
                 ErrorKind::option);
}

TEST(FieldMeshFile, ObjWithOneNormalLinePerVertex) {
    const TriangleMesh m = icosphere(2);
    std::ostringstream s;
    s.precision(17);
    for (const Vec3& v : m.vertices) s << "v " << v.x << " " << v.y << " " << v.z << "\n";
    for (const Vec3& v : m.vertices) {
        const Vec3 d = latitude_tangent(v);
        s << "vn " << d.x << " " << d.y << " " << d.z << "\n";
    }
    for (const auto& t : m.triangles) s << "f " << t[0] + 1 << "//" << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
    const std::string path = write("sphere.obj", s.str());
    const OrientationField f = OrientationField::mesh_file(path);
    EXPECT_NE(f.describe().find("162 vertices, 320 triangles"), std::string::npos) << f.describe();
    const Vec3 p{0.8, -0.5, 0.1};
    EXPECT_LT(degrees_between(f.frame(p, 3).rotate({0, 0, 1}), p), 5.0);
    EXPECT_LT(degrees_between(f.direction(p), latitude_tangent(p)), 10.0);
    // One vn too few.
    std::string text = s.str();
    text.erase(text.find("vn "), text.find('\n', text.find("vn ")) - text.find("vn ") + 1);
    const std::string short_path = write("short.obj", text);
    expect_error([&] { OrientationField::mesh_file(short_path); }, {short_path, "162 vertices", "161 directions"});
}

TEST(FieldMeshFile, PointCloudBlendsTheNearestVertices) {
    const std::string path = write("cloud.ply", sphere_ply(false, false));
    const OrientationField f = OrientationField::parse("mesh:" + path, 3, "--field");
    EXPECT_NE(f.describe().find("point cloud"), std::string::npos) << f.describe();
    EXPECT_NE(f.describe().find("642 vertices"), std::string::npos) << f.describe();
    double worst = 0.0;
    for (const Vec3& p : points_near_sphere(2000, 5)) {
        const Vec3 want = latitude_tangent(p - sphere_center);
        worst = std::max(worst, degrees_between(f.direction(p), want));
        EXPECT_NEAR(norm(f.frame(p, 3).rotate({1, 0, 0}) - f.direction(p)), 0.0, 1e-9);
    }
    EXPECT_LT(worst, 10.0);
    // On a vertex: exactly its direction.
    const Vec3 v = icosphere(3).vertices[100];
    EXPECT_NEAR(norm(f.direction(sphere_center + v * sphere_radius) - latitude_tangent(v)), 0.0, 1e-6);
}

TEST(FieldMeshFile, MalformedMeshFilesNameTheFile) {
    const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\n";
    const std::string no_direction = write("nodir.ply", head + "end_header\n0 0 0\n1 0 0\n0 1 0\n");
    expect_error([&] { OrientationField::mesh_file(no_direction); }, {no_direction, "vx"});
    const std::string zero = write("zero.ply", head + "property float vx\nproperty float vy\nproperty float vz\n"
                                                      "end_header\n0 0 0 1 0 0\n1 0 0 0 0 0\n0 1 0 1 0 0\n");
    expect_error([&] { OrientationField::mesh_file(zero); }, {zero, "vertex 1", "zero direction"});
    const std::string bad = write("bad.ply", head + "property float vx\nproperty float vy\nproperty float vz\n"
                                                    "end_header\n0 0 0 1 0 0\n1 0 0 nan 0 0\n0 1 0 1 0 0\n");
    expect_error([&] { OrientationField::mesh_file(bad); }, {bad + ":", "nan"});
    const std::string missing = (std::filesystem::temp_directory_path() / "tessera_field_no_such_mesh.ply").string();
    expect_error([&] { OrientationField::parse("mesh:" + missing, 3, "--field"); }, {"--field", missing},
                 ErrorKind::io);
    TriangleMesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}};
    expect_error([&] { OrientationField::mesh_vertices(m, {{1, 0, 0}}, "my mesh"); },
                 {"my mesh", "2 vertices", "1 directions"});
    // The plain mesh reader still ignores the direction properties.
    const TriangleMesh plain = read_triangle_mesh(zero);
    EXPECT_EQ(plain.vertices.size(), 3u);
}

TEST(FieldFrame, FrameFromDirectionAndNormal) {
    const Vec3 n = Vec3{1, 2, 2} / 3.0;
    const Quat q = frame_from_direction({1, 0, 0}, n);
    EXPECT_NEAR(norm(q.rotate({0, 0, 1}) - n), 0.0, 1e-12);
    const Vec3 x = q.rotate({1, 0, 0});
    EXPECT_NEAR(dot(x, n), 0.0, 1e-12);
    const Vec3 projected = Vec3{1, 0, 0} - n * n.x;
    EXPECT_NEAR(norm(x - projected / norm(projected)), 0.0, 1e-12);
    EXPECT_NEAR(norm(q.rotate({0, 1, 0}) - cross(n, x)), 0.0, 1e-12) << "right-handed";
    // d along the normal, or zero: the least rotation taking +z onto n, applied to +x.
    for (const Vec3& d : {n * 2.0, Vec3{}}) {
        const Quat r = frame_from_direction(d, n);
        EXPECT_NEAR(norm(r.rotate({0, 0, 1}) - n), 0.0, 1e-12);
        EXPECT_NEAR(dot(r.rotate({1, 0, 0}), n), 0.0, 1e-12);
        EXPECT_GT(r.rotate({1, 0, 0}).x, 0.5);
    }
    EXPECT_EQ(frame_from_direction(Vec3{}, Vec3{0, 0, 1}), Quat{});
    const Quat down = frame_from_direction(Vec3{}, Vec3{0, 0, -1});
    EXPECT_NEAR(norm(down.rotate({1, 0, 0}) - Vec3{1, 0, 0}), 0.0, 1e-12);
    EXPECT_NEAR(norm(down.rotate({0, 0, 1}) - Vec3{0, 0, -1}), 0.0, 1e-12);
    // Normal = +z reproduces the least-twist frame; a zero normal falls back to it.
    const Vec3 d{1, 1, 0};
    EXPECT_NEAR(norm(frame_from_direction(d, Vec3{0, 0, 1}).rotate({1, 0, 0}) -
                     frame_from_direction(d, 3).rotate({1, 0, 0})),
                0.0, 1e-12);
    EXPECT_EQ(frame_from_direction(Vec3{0, 1, 1}, Vec3{}), frame_from_direction(Vec3{0, 1, 1}, 3));
}

// The accelerated searches against brute force, near and far from a bumpy two-part mesh
// with unrelated directions at its vertices (so a wrong closest triangle shows).
TEST(FieldMeshFile, AcceleratedSearchMatchesBruteForce) {
    TriangleMesh m = icosphere(2);
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (Vec3& v : m.vertices) v = v * (1.0 + 0.2 * unit(rng));
    const size_t n = m.vertices.size();
    for (size_t k = 0; k < n; ++k) m.vertices.push_back(m.vertices[k] * 0.3 + Vec3{6, 1, -2});  // a second part
    for (size_t t = 0, count = m.triangles.size(); t < count; ++t) {
        const auto f = m.triangles[t];  // a copy: push_back may reallocate
        m.triangles.push_back({f[0] + int(n), f[1] + int(n), f[2] + int(n)});
    }
    std::vector<Vec3> directions;
    for (size_t k = 0; k < m.vertices.size(); ++k) directions.push_back({unit(rng), unit(rng), unit(rng)});
    for (Vec3& d : directions) d = d / norm(d);
    const OrientationField field = OrientationField::mesh_vertices(m, directions, "bumpy");
    TriangleMesh cloud_mesh = m;
    cloud_mesh.triangles.clear();
    const OrientationField cloud = OrientationField::mesh_vertices(cloud_mesh, directions, "bumpy cloud");

    // Closest point of a triangle, the plain way: the plane projection if inside, else the best edge point.
    auto closest = [](const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
        const Vec3 nrm = cross(b - a, c - a);
        const Vec3 q = p - nrm * (dot(p - a, nrm) / dot(nrm, nrm));
        const double area = dot(nrm, nrm);
        const std::array<double, 3> w{dot(cross(c - b, q - b), nrm) / area, dot(cross(a - c, q - c), nrm) / area,
                                      dot(cross(b - a, q - a), nrm) / area};
        if (w[0] >= 0 && w[1] >= 0 && w[2] >= 0) return w;
        std::array<double, 3> best{1, 0, 0};
        double best_d = INFINITY;
        const Vec3 corner[3] = {a, b, c};
        for (int e = 0; e < 3; ++e) {
            const Vec3 u = corner[e], v = corner[(e + 1) % 3];
            const double t = std::clamp(dot(p - u, v - u) / dot(v - u, v - u), 0.0, 1.0);
            const double d = norm(u + (v - u) * t - p);
            if (d < best_d) {
                best_d = d;
                best = {0, 0, 0};
                best[e] = 1 - t, best[(e + 1) % 3] = t;
            }
        }
        return best;
    };
    std::uniform_real_distribution<double> box(-12.0, 14.0);
    int checked = 0;
    for (int k = 0; k < 600; ++k) {
        const Vec3 p = k < 300 ? Vec3{box(rng), box(rng), box(rng)} : Vec3{unit(rng), unit(rng), unit(rng)} * 1.5;
        // Every triangle at the least distance (several share a closest vertex or edge) is right.
        std::vector<std::pair<double, Vec3>> candidates;
        for (const auto& f : m.triangles) {
            const Vec3 &a = m.vertices[f[0]], &b = m.vertices[f[1]], &c = m.vertices[f[2]];
            const auto w = closest(p, a, b, c);
            const Vec3 nrm = cross(b - a, c - a) / norm(cross(b - a, c - a));
            const Vec3 blend = directions[f[0]] * w[0] + directions[f[1]] * w[1] + directions[f[2]] * w[2];
            const Vec3 d = blend - nrm * dot(blend, nrm);
            candidates.push_back({norm(a * w[0] + b * w[1] + c * w[2] - p), d / norm(d)});
        }
        double best = INFINITY;
        for (const auto& c : candidates) best = std::min(best, c.first);
        const Vec3 got = field.direction(p);
        bool matched = false;
        for (const auto& c : candidates) matched = matched || (c.first < best + 1e-9 && norm(got - c.second) < 1e-9);
        EXPECT_TRUE(matched) << p.x << "," << p.y << "," << p.z;
        ++checked;
        // The 8 nearest vertices, weighted by 1 / d^2.
        std::vector<std::pair<double, size_t>> near;
        for (size_t v = 0; v < m.vertices.size(); ++v) near.push_back({squared_norm(m.vertices[v] - p), v});
        std::partial_sort(near.begin(), near.begin() + 8, near.end());
        Vec3 idw;
        for (int j = 0; j < 8; ++j) idw += directions[near[j].second] / near[j].first;
        EXPECT_NEAR(norm(cloud.direction(p) - idw / norm(idw)), 0.0, 1e-9);
    }
    EXPECT_EQ(checked, 600);
}

// Pure functions of p: the same answers from any number of threads.
TEST(FieldMeshFile, IdenticalResultsFromManyThreads) {
    const OrientationField mesh = OrientationField::mesh_file(write("threads.ply", sphere_ply(true, false)));
    const OrientationField cloud = OrientationField::mesh_file(write("threads_cloud.ply", sphere_ply(false, false)));
    const std::vector<Vec3> points = points_near_sphere(4000, 9);
    auto evaluate = [&](int threads) {
        std::vector<Quat> out(2 * points.size());
        std::vector<std::thread> pool;
        for (int t = 0; t < threads; ++t)
            pool.emplace_back([&, t] {
                for (size_t k = t; k < points.size(); k += threads) {
                    out[2 * k] = mesh.frame(points[k], 3);
                    out[2 * k + 1] = cloud.frame(points[k], 3);
                }
            });
        for (auto& th : pool) th.join();
        return out;
    };
    const auto serial = evaluate(1);
    EXPECT_EQ(evaluate(4), serial);
    EXPECT_EQ(evaluate(7), serial);
}

// The criterion with a grid file: element orientations within 10 degrees of the field.
TEST(FieldGridFile, SynthesisFollowsAGridField) {
    Exemplar ex = load(std::string(TESSERA_SOURCE_DIR) + "/examples/poisson_disk_2d.json");
    for (auto& e : ex.elements) e.orientation = Quat::from_angle_z(0.0);
    const Domain domain = ex.domain.scaled(3.0);
    const Vec3 lo = domain.bounds().lo, hi = domain.bounds().hi;
    const Vec3 center = (lo + hi) * 0.5 + Vec3{0.25, -0.25, 0};
    const std::array<int, 3> size{25, 25, 1};
    const Vec3 spacing{(hi.x - lo.x) / 24, (hi.y - lo.y) / 24, 1};
    DetOptions o;
    o.field = OrientationField::grid_file(write("synth.json", vortex_grid_json(2, lo, spacing, size, center)));
    o.iterations = 3;
    const Arrangement out = synthesize_det(ex, domain, o);
    ASSERT_GT(out.elements.size(), 50u);
    const OrientationField vortex = OrientationField::vortex(center);
    double sum = 0.0, sum_vortex = 0.0;
    for (const auto& e : out.elements) {
        const Vec3 axis = e.orientation.rotate({1, 0, 0});
        sum += std::min(degrees_between(axis, o.field.direction(e.position)),
                        180.0 - degrees_between(axis, o.field.direction(e.position)));
        sum_vortex += std::min(degrees_between(axis, vortex.direction(e.position)),
                               180.0 - degrees_between(axis, vortex.direction(e.position)));
    }
    EXPECT_LT(sum / out.elements.size(), 10.0);
    EXPECT_LT(sum_vortex / out.elements.size(), 10.0);
}

// Rigid sticks in a grid-sampled vortex: the stick directions (first to last sample, as
// undirected lines) follow the field within 10 degrees on average and by no more than the
// exemplar's sticks deviate from +x, plus 4 degrees (as DetField.SticksFollowAVortex).
TEST(FieldGridFile, SticksFollowAGridField) {
    const Exemplar ex = load(std::string(TESSERA_SOURCE_DIR) + "/examples/sticks_2d.json");
    const Vec3 center{10.25, 9.75, 0};
    DetOptions o;
    o.field = OrientationField::grid_file(
        write("sticks.json", vortex_grid_json(2, {0, 0, 0}, {1, 1, 1}, {21, 21, 1}, center)));
    const Arrangement out = synthesize_det(ex, Domain::box({0, 0, 0}, {20, 20, 0}, 2), o);
    auto line_angle = [](const Exemplar& d, const Element& e, const Vec3& reference) {
        const double a = degrees_between(d.samples[e.first_sample + e.sample_count - 1].p - d.samples[e.first_sample].p,
                                         reference);
        return std::min(a, 180.0 - a);
    };
    double spread = 0.0;
    for (const auto& e : ex.elements) spread += line_angle(ex, e, {1, 0, 0});
    spread /= ex.elements.size();
    double along = 0.0;
    int counted = 0;
    for (const auto& e : out.elements) {
        if (norm(e.position - center) < 2.0) continue;  // the field turns fast at its centre
        along += line_angle(out, e, o.field.direction(e.position));
        ++counted;
    }
    ASSERT_GT(counted, 100);
    EXPECT_LT(along / counted, 10.0);
    EXPECT_LT(along / counted, spread + 4.0) << "exemplar spread " << spread;
}
