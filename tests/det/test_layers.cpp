// A layered exemplar (thinner than a neighbourhood along one axis, like a wall one brick
// thick) synthesized into a shell under a closed surface, with the surface's mesh field
// turning the layer into the tangent plane: the shell receives one layer at the
// exemplar's areal density, not a stack of copies.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "test_meshes.hpp"
#include "tessera/tessera.hpp"

using namespace tessera;

namespace {

// A jittered hexagonal lattice (spacing 0.5) in a 6 x 6 window, 0.2 thick, at z = 0.1.
Exemplar hex_layer() {
    Exemplar ex;
    ex.dimension = 3;
    ex.domain = Domain::box({0, 0, 0}, {6, 6, 0.2}, 3);
    ex.type_index("tile");
    const double a = 0.5, h = a * std::sqrt(3.0) / 2;
    for (int j = 0; j * h < 6 - 1e-9; ++j)
        for (int i = 0; i < 12; ++i) {
            const double x = (i + 0.5 * (j % 2) + 0.25) * a, y = (j + 0.5) * h;
            if (x < 6) ex.add_element(0, {{x, y, 0.1}}, 0.2);
        }
    return ex;
}

}  // namespace

TEST(DetLayers, ALayerFillsAShellOnceAtItsArealDensity) {
    const Exemplar ex = hex_layer();
    const TriangleMesh sphere = test::icosphere(3, 3.0);
    const Domain shell = Domain::shell(sphere, 0.2, 64);
    // Directions along the lines of latitude; the frame's z is the surface normal.
    std::vector<Vec3> east;
    for (const Vec3& v : sphere.vertices) {
        const Vec3 t{-v.y, v.x, 0};
        east.push_back(norm(t) > 1e-9 ? t * (1.0 / norm(t)) : Vec3{1, 0, 0});
    }
    DetOptions o;
    o.field = OrientationField::mesh_vertices(sphere, east);
    o.iterations = 4;
    const Arrangement out = synthesize_det(ex, shell, o);

    // Areal density: the exemplar's elements per unit area times the sphere's area.
    const double per_area = ex.elements.size() / 36.0;
    const double expected = per_area * 4 * 3.14159265358979 * 2.9 * 2.9;  // mid-surface of the shell
    EXPECT_NEAR(out.elements.size() / expected, 1.0, 0.15) << out.elements.size() << " vs " << expected;
    int outside = 0;
    for (const auto& s : out.samples) outside += !shell.inside(s.p);
    EXPECT_LT(static_cast<double>(outside) / out.samples.size(), 0.02);
    // One layer: no element has a neighbour much closer than the lattice spacing (a second
    // layer would put copies within the shell's thickness, 0.2).
    int crowded = 0;
    for (size_t i = 0; i < out.elements.size(); ++i) {
        double nearest = INFINITY;
        for (size_t j = 0; j < out.elements.size(); ++j)
            if (i != j) nearest = std::min(nearest, norm(out.elements[i].position - out.elements[j].position));
        crowded += nearest < 0.3;
    }
    EXPECT_LT(static_cast<double>(crowded) / out.elements.size(), 0.05) << crowded;
}
