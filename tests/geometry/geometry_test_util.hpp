// Helpers of the element geometry tests: a temporary directory per test, meshes
// written as OBJ files, rotations, and point-set measures.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "temp_dir.hpp"
#include "tessera/exemplar.hpp"
#include "tessera/geometry.hpp"
#include "tessera/mesh.hpp"

namespace geometry_test {

using namespace tessera;
namespace fs = std::filesystem;

// A fresh directory per test (tests/temp_dir.hpp), plus mesh files.
class TempDir : public tessera::test::TempDirTest {
protected:
    // Writes `mesh` as an OBJ file and returns its path.
    std::string write_mesh(const std::string& name, const TriangleMesh& mesh) const {
        std::ostringstream out;
        out.precision(17);
        for (const Vec3& v : mesh.vertices) out << "v " << v.x << " " << v.y << " " << v.z << "\n";
        for (const auto& t : mesh.triangles) out << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
        write(name, out.str());
        return path(name);
    }
};

// A unit quaternion from any non-zero (w, x, y, z).
inline Quat unit(double w, double x, double y, double z) {
    const double n = std::sqrt(w * w + x * x + y * y + z * z);
    return {w / n, x / n, y / n, z / n};
}

// An asymmetric closed mesh (a tetrahedron with one long edge) around the origin.
inline TriangleMesh tetrahedron() {
    TriangleMesh m;
    m.vertices = {{-0.5, -0.2, -0.1}, {0.9, -0.1, 0.0}, {0.0, 0.6, 0.05}, {0.1, 0.1, 0.7}};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
    return m;
}

// Where the local point v of instance `inst` lands.
inline Vec3 posed(const SceneInstance& inst, const Vec3& v) {
    return inst.position + inst.orientation.rotate(v * inst.scale);
}

inline double max_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    double worst = 0.0;
    for (size_t k = 0; k < a.size(); ++k) worst = std::max(worst, norm(a[k] - b[k]));
    return worst;
}

// Largest change of any pairwise distance between the two point lists (same order).
inline double pairwise_distance_change(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    double worst = 0.0;
    for (size_t i = 0; i < a.size(); ++i)
        for (size_t j = i + 1; j < a.size(); ++j)
            worst = std::max(worst, std::abs(norm(a[i] - a[j]) - norm(b[i] - b[j])));
    return worst;
}

// Signed volume enclosed by a closed mesh (> 0 when its triangles face outward).
inline double signed_volume(const TriangleMesh& m) {
    double v = 0.0;
    for (const auto& t : m.triangles) v += dot(m.vertices[t[0]], cross(m.vertices[t[1]], m.vertices[t[2]])) / 6.0;
    return v;
}

// A 3D scene of every kind of element: a rigid type with a mesh (3 elements, 3 samples
// each), a deformable type with a mesh (2 elements), balls and ropes without a mesh.
// `mesh` is the tetrahedron's OBJ file.
inline Exemplar mixed_exemplar(const std::string& mesh) {
    Exemplar ex;
    ex.dimension = 3;
    ex.domain = Domain::box({0, 0, 0}, {10, 10, 10}, 3);
    const std::vector<Vec3> layout = {{-0.6, -0.2, 0.1}, {0.4, -0.2, -0.3}, {0.2, 0.4, 0.2}};
    ex.types.push_back({"shard", true, false, mesh, {}, std::nullopt});
    ex.types.push_back({"worm", false, false, mesh, {{-0.5, 0, 0}, {0, 0, 0}, {0.5, 0, 0}}, std::nullopt});
    ex.types.push_back({"ball", true, false, "", {}, std::nullopt});
    ex.types.push_back({"rope", false, false, "", {}, std::nullopt});
    const Quat turns[3] = {Quat{}, unit(0.3, 0.5, -0.7, 0.1), unit(-0.2, 0.9, 0.1, 0.4)};
    for (int i = 0; i < 3; ++i) {
        std::vector<Vec3> samples;
        for (const Vec3& r : layout) samples.push_back(Vec3{2.0 + 2 * i, 2, 2} + turns[i].rotate(r));
        const int e = ex.add_element(0, samples);
        ex.elements[e].orientation = turns[i];
        ex.elements[e].id = 100 + static_cast<std::uint64_t>(i);
    }
    ex.add_element(1, {{2, 6, 2}, {2.5, 6.2, 2}, {3, 6, 2.1}});
    ex.add_element(1, {{6, 6, 2}, {6.5, 6, 2.5}, {6.5, 6, 3}});
    ex.add_element(2, {{8, 8, 8}}, 0.3);
    ex.add_element(2, {{8, 2, 8}}, 0.25);
    ex.add_element(3, {{1, 8, 8}, {2, 8, 8}, {3, 8.5, 8}, {4, 8, 8}}, 0.1);
    ex.validate("mixed");
    return ex;
}

}  // namespace geometry_test
