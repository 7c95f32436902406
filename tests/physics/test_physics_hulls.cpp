// Element types with meshes: the physics simulates and measures them as the convex hull
// of their mesh (hulls.hpp), so a cube is a cube, not the sphere of its radius.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/rng.hpp"
#include "tessera/error.hpp"
#include "tessera/physics.hpp"

using namespace tessera;
namespace fs = std::filesystem;

namespace {

// A closed cube of side `side` centred at the origin, written as OBJ; returns its path.
std::string write_cube(const std::string& name, double side) {
    const fs::path path = fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()) + ".obj");
    std::ofstream out(path);
    const double h = side / 2;
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x) out << "v " << (x ? h : -h) << ' ' << (y ? h : -h) << ' ' << (z ? h : -h) << '\n';
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads)
        out << "f " << q[0] + 1 << ' ' << q[1] + 1 << ' ' << q[2] + 1 << "\nf " << q[0] + 1 << ' ' << q[2] + 1 << ' '
            << q[3] + 1 << '\n';
    return path.string();
}

Arrangement cubes(const std::string& mesh) {
    Arrangement a;
    a.dimension = 3;
    a.domain = Domain::box({0, 0, 0}, {10, 10, 10}, 3);
    a.types.push_back({"cube", true, false, mesh, {}, std::nullopt});
    return a;
}

}  // namespace

TEST(PhysicsHulls, CubesSideBySideTouchWithoutOverlapThoughTheirSpheresWould) {
    const std::string mesh = write_cube("hull_cube", 1.0);
    Arrangement a = cubes(mesh);
    // Radius 0.8 (the cube's circumsphere is 0.87): as spheres these would overlap by 0.6.
    a.add_element(0, {{5, 5, 0.5}}, 0.8);
    a.add_element(0, {{6.0, 5, 0.5}}, 0.8);   // face to face
    a.add_element(0, {{5.5, 5, 1.5}}, 0.8);   // resting on both
    const PhysicsReport r = measure_physics(a, a.domain, {});
    EXPECT_EQ(r.interpenetrating_pairs, 0);
    EXPECT_LT(r.max_depth, 1e-3);
    EXPECT_EQ(r.floating, 0);  // the floor carries the bottom two, they carry the top one
    // Pushed into each other by 0.3, they overlap by 0.3.
    a.samples[1].p.x = 5.7;
    a.update_positions();
    const PhysicsReport r2 = measure_physics(a, a.domain, {});
    EXPECT_GE(r2.interpenetrating_pairs, 1);
    EXPECT_NEAR(r2.max_depth, 0.3, 1e-3);
    fs::remove(mesh);
}

TEST(PhysicsHulls, ATurnedCubeIsMeasuredTurned) {
    const std::string mesh = write_cube("hull_turned", 1.0);
    Arrangement a = cubes(mesh);
    a.add_element(0, {{5, 5, 0.5}}, 0.5);
    a.add_element(0, {{6.2, 5, 0.5}}, 0.5);
    // Turned 45 degrees about z, the second cube reaches sqrt(2)/2 = 0.707 toward the first:
    // overlap 0.5 + 0.707 - 1.2 = 0.007 (no interpenetration at the 5% tolerance) ...
    a.elements[1].orientation = Quat::from_angle_z(0.7853981633974483);
    EXPECT_NEAR(measure_physics(a, a.domain, {}).max_depth, 0.00711, 1e-3);
    // ... and 0.107 when moved 0.1 closer.
    a.samples[1].p.x = 6.1;
    a.update_positions();
    EXPECT_NEAR(measure_physics(a, a.domain, {}).max_depth, 0.10711, 1e-3);
    fs::remove(mesh);
}

TEST(PhysicsHulls, StepsHalveTheOverlapsOfADensePileOfCubesAndLoseNone) {
    const std::string mesh = write_cube("hull_pile", 0.8);
    Arrangement a = cubes(mesh);
    a.domain = Domain::box({0, 0, 0}, {6, 6, 8}, 3);
    const core::KeyedRng rng(3, core::Purpose::test);
    for (int i = 0; i < 150; ++i) {
        const std::uint64_t c = 4 * static_cast<std::uint64_t>(i);
        a.add_element(0, {{0.5 + 5 * rng.uniform(c), 0.5 + 5 * rng.uniform(c + 1), 0.5 + 3 * rng.uniform(c + 2)}}, 0.45);
        a.elements.back().orientation = Quat::from_angle_z(6.283 * rng.uniform(c + 3));
    }
    const PhysicsReport before = measure_physics(a, a.domain, {});
    ASSERT_GT(before.interpenetrating_pairs, 20);
    PhysicsOptions o;
    o.substeps = 60;
    const PhysicsReport after = step_physics(a, a.domain, o);
    EXPECT_LE(after.interpenetrating_pairs * 2, before.interpenetrating_pairs);
    EXPECT_EQ(after.lost, 0);
    EXPECT_EQ(a.elements.size(), 150u);
    fs::remove(mesh);
}

TEST(PhysicsHulls, AMissingMeshFileIsAnIoErrorNamingIt) {
    Arrangement a = cubes("/nonexistent/cube.obj");
    a.add_element(0, {{5, 5, 0.5}}, 0.5);
    try {
        measure_physics(a, a.domain, {});
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::io);
        EXPECT_NE(std::string(e.what()).find("/nonexistent/cube.obj"), std::string::npos);
    }
}
