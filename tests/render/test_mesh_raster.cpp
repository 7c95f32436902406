// Tests of the triangle rasterizer behind the mesh pictures: the top-left fill rule
// (shared edges drawn once, no cracks), depth test, attribute interpolation, either
// winding, degenerate input and clipping; and of the corner normals (smooth across
// gentle bends, split at the crease angle, independent of the winding).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "render/mesh_normals.hpp"
#include "render/mesh_raster.hpp"
#include "render/render_test_util.hpp"

using namespace tessera;
using render::MeshRaster;
using render::RasterVertex;

namespace {

RasterVertex at(double x, double y, float depth = 0.0f) {
    return {x, y, depth, 0.0f, 0.0f, 1.0f};
}

int tagged(const MeshRaster& r) {
    int n = 0;
    for (int i = 0; i < r.width() * r.height(); ++i) n += r.tag(i) >= 0;
    return n;
}

}  // namespace

TEST(RenderMeshRaster, SquareOfTwoTrianglesCoversEachPixelOnce) {
    MeshRaster r(20, 20);
    // Corners on pixel boundaries: centres on the shared diagonal are claimed by one triangle.
    r.draw_triangle(at(2, 2), at(12, 2), at(12, 12), 0);
    r.draw_triangle(at(2, 2), at(12, 12), at(2, 12), 1);
    EXPECT_EQ(r.fragments(), 100u);
    EXPECT_EQ(tagged(r), 100);
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 20; ++x)
            EXPECT_EQ(r.tag(y * 20 + x) >= 0, x >= 2 && x < 12 && y >= 2 && y < 12) << x << "," << y;
}

TEST(RenderMeshRaster, FanHasNoCracksAndNoOverlaps) {
    // A 17-gon cut into triangles from a centre that sits exactly on a pixel centre,
    // corners at awkward positions, and a second fan whose edges pass through centres.
    for (const double cx : {20.5, 20.3}) {
        MeshRaster r(41, 41);
        constexpr int n = 17;
        std::vector<RasterVertex> ring;
        for (int k = 0; k < n; ++k) {
            const double a = 2.0 * std::numbers::pi * k / n + 0.1;
            ring.push_back(at(cx + 15.3 * std::cos(a), 20.5 + 15.3 * std::sin(a)));
        }
        for (int k = 0; k < n; ++k) r.draw_triangle(at(cx, 20.5), ring[k], ring[(k + 1) % n], k);
        EXPECT_EQ(r.fragments(), static_cast<size_t>(tagged(r)));  // nothing drawn twice
        // Every centre strictly inside the polygon is drawn.
        for (int y = 0; y < 41; ++y)
            for (int x = 0; x < 41; ++x) {
                bool inside = true;
                for (int k = 0; k < n; ++k) {
                    const RasterVertex &a = ring[k], &b = ring[(k + 1) % n];
                    const double e = (b.x - a.x) * (y + 0.5 - a.y) - (b.y - a.y) * (x + 0.5 - a.x);
                    inside = inside && e > 1e-9;
                }
                if (inside) {
                    EXPECT_GE(r.tag(y * 41 + x), 0) << x << "," << y;
                }
            }
    }
}

TEST(RenderMeshRaster, NearerTriangleWinsInEitherOrderAndWinding) {
    for (const bool near_first : {false, true}) {
        MeshRaster r(10, 10);
        const RasterVertex a = at(0, 0, 1.0f), b = at(10, 0, 1.0f), c = at(0, 10, 1.0f);  // far (depth 1)
        const RasterVertex d = at(0, 0, 2.0f), e = at(0, 10, 2.0f),
                           f = at(10, 10, 2.0f);  // near, other winding
        if (near_first)
            r.draw_triangle(d, e, f, 1), r.draw_triangle(a, b, c, 0);
        else
            r.draw_triangle(a, b, c, 0), r.draw_triangle(d, e, f, 1);
        EXPECT_EQ(r.tag(1 * 10 + 6), 0);  // only the far one
        EXPECT_EQ(r.tag(8 * 10 + 3), 1);  // only the near one
        EXPECT_EQ(r.tag(4 * 10 + 1), 1);  // both: near wins
        EXPECT_FLOAT_EQ(r.depth(4 * 10 + 1), 2.0f);
    }
}

TEST(RenderMeshRaster, InterpolatesDepthAndNormalLinearly) {
    MeshRaster r(8, 8);
    RasterVertex a{0, 0, 0.0f, 1.0f, 0.0f, 0.0f}, b{8, 0, 8.0f, 1.0f, 0.0f, 0.0f},
        c{0, 8, 0.0f, 0.0f, 1.0f, 0.0f};
    r.draw_triangle(a, b, c, 0);
    const size_t i = 2 * 8 + 3;  // centre (3.5, 2.5)
    EXPECT_NEAR(r.depth(i), 3.5f, 1e-5);
    EXPECT_NEAR(r.normal(i)[0], 1.0f - 2.5f / 8.0f, 1e-5);
    EXPECT_NEAR(r.normal(i)[1], 2.5f / 8.0f, 1e-5);
}

TEST(RenderMeshRaster, DegenerateAndNonFiniteTrianglesDrawNothing) {
    MeshRaster r(10, 10);
    r.draw_triangle(at(1, 1), at(5, 5), at(9, 9), 0);  // collinear
    r.draw_triangle(at(3, 3), at(3, 3), at(3, 3), 0);  // a point
    r.draw_triangle(at(1, 1), at(1, 1), at(8, 2), 0);  // repeated corner
    r.draw_triangle(at(0, 0), at(std::nan(""), 5), at(9, 9), 0);
    r.draw_triangle(at(0, 0), at(INFINITY, 0), at(0, INFINITY), 0);
    EXPECT_EQ(r.fragments(), 0u);
    EXPECT_EQ(tagged(r), 0);
}

TEST(RenderMeshRaster, ClipsToThePicture) {
    MeshRaster r(30, 20);
    // Partly outside: only the pixels inside the picture, none wrapped around rows.
    r.draw_triangle(at(-10, -10), at(20, -10), at(-10, 20), 0);
    EXPECT_EQ(r.fragments(), static_cast<size_t>(tagged(r)));
    EXPECT_GE(r.tag(0), 0);
    EXPECT_LT(r.tag(29), 0);
    // Corners far beyond the guard band: the triangle covers the whole picture and its
    // depth plane survives the clipping.
    MeshRaster big(30, 20);
    big.draw_triangle(at(-1e7, -1e7, -1e7f), at(3e7, -1e7, 3e7f), at(-1e7, 3e7, -1e7f), 0);
    EXPECT_EQ(tagged(big), 600);
    EXPECT_EQ(big.fragments(), 600u);
    EXPECT_NEAR(big.depth(5 * 30 + 10), 10.5f, 1.0f);  // depth = x, float precision at 1e7
}

namespace {

// A unit cube (8 shared corners) with every other face wound the wrong way, plus a
// degenerate triangle and one with an index out of range.
TriangleMesh badly_wound_cube() {
    TriangleMesh cube;
    for (int i = 0; i < 8; ++i)
        cube.vertices.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (int f = 0; f < 6; ++f) {
        const auto& q = quads[f];
        if (f % 2) {
            cube.triangles.push_back({q[0], q[2], q[1]}), cube.triangles.push_back({q[0], q[3], q[2]});
        } else {
            cube.triangles.push_back({q[0], q[1], q[2]}), cube.triangles.push_back({q[0], q[2], q[3]});
        }
    }
    cube.triangles.push_back({0, 0, 7});   // degenerate: ignored
    cube.triangles.push_back({0, 1, 99});  // index out of range: ignored
    return cube;
}

Vec3 centroid(const TriangleMesh& m, int t) {
    const auto& [a, b, c] = m.triangles[t];
    return (m.vertices[a] + m.vertices[b] + m.vertices[c]) / 3.0;
}

}  // namespace

TEST(RenderMeshNormals, CubeCornersTakeTheirFacesNormalOnOneSide) {
    const TriangleMesh cube = badly_wound_cube();
    const auto normals = render::corner_normals(cube);
    ASSERT_EQ(normals.size(), 3 * cube.triangles.size());
    const Vec3 centre{0.5, 0.5, 0.5};
    const double sign = dot(normals[0], centroid(cube, 0) - centre) > 0 ? 1.0 : -1.0;
    for (int t = 0; t < 12; ++t) {
        // The face's own axis, the same side (out or in) for every face.
        const Vec3 axis = (centroid(cube, t) - centre) * 2.0;
        const Vec3 face{std::round(axis.x), std::round(axis.y), std::round(axis.z)};
        for (int k = 0; k < 3; ++k) EXPECT_LT(norm(normals[3 * t + k] * sign - face), 1e-12) << t << " " << k;
    }
    for (int c = 36; c < 42; ++c) EXPECT_EQ(norm(normals[c]), 0.0) << c;  // the ignored triangles
}

TEST(RenderMeshNormals, InconsistentWindingStillGivesOneSidedSmoothNormals) {
    // Without a crease (180 degrees) every corner gets the average of all faces at
    // its vertex: near the vertex's diagonal (faces weigh by their triangles' areas at
    // the corner, 1 or 2 halves), every face counted with the same side.
    const TriangleMesh cube = badly_wound_cube();
    const auto normals = render::corner_normals(cube, 180.0);
    const Vec3 centre{0.5, 0.5, 0.5};
    const double sign = dot(normals[0], cube.vertices[cube.triangles[0][0]] - centre) > 0 ? 1.0 : -1.0;
    for (int t = 0; t < 12; ++t)
        for (int k = 0; k < 3; ++k) {
            const Vec3 n = normals[3 * t + k] * sign;
            const Vec3 out = cube.vertices[cube.triangles[t][k]] - centre;
            EXPECT_NEAR(norm(n), 1.0, 1e-12);
            EXPECT_GT(dot(n, out) / norm(out), 0.9) << t << " " << k;
        }
}

TEST(RenderMeshNormals, SharpCornersOfAConsistentMeshKeepTheirFaces) {
    // A tetrahedron: faces meet at more than 90 degrees, which must not flip any.
    TriangleMesh t;
    t.vertices = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    t.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    const auto smooth = render::corner_normals(t, 180.0);
    const double sign = dot(smooth[0], t.vertices[0]) > 0 ? 1.0 : -1.0;
    for (int f = 0; f < 4; ++f)
        for (int k = 0; k < 3; ++k) {
            const Vec3 n = smooth[3 * f + k] * sign;
            const Vec3& v = t.vertices[t.triangles[f][k]];
            EXPECT_GT(dot(n, v) / (norm(n) * norm(v)), 0.99) << f << " " << k;
        }
    // With the default crease every corner keeps its face's normal, outward like the rest.
    const auto flat = render::corner_normals(t);
    for (int f = 0; f < 4; ++f) {
        const Vec3 out = centroid(t, f) / norm(centroid(t, f));
        for (int k = 0; k < 3; ++k) EXPECT_GT(dot(flat[3 * f + k] * sign, out), 1.0 - 1e-12) << f << " " << k;
    }
}

TEST(RenderMeshNormals, IcosphereStaysSmooth) {
    const TriangleMesh sphere = test::icosphere(2, 1.0);
    const auto normals = render::corner_normals(sphere);
    const double sign = dot(normals[0], sphere.vertices[sphere.triangles[0][0]]) > 0 ? 1.0 : -1.0;
    std::vector<Vec3> at_vertex(sphere.vertices.size());
    for (size_t t = 0; t < sphere.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            // Not split: every corner of a vertex has the same normal, close to the radius.
            const int v = sphere.triangles[t][k];
            const Vec3 n = normals[3 * t + k] * sign;
            if (at_vertex[v] == Vec3{}) at_vertex[v] = n;
            EXPECT_LT(norm(n - at_vertex[v]), 1e-12) << t << " " << k;
            EXPECT_GT(dot(n, sphere.vertices[v]), 0.999) << t << " " << k;
        }
}

TEST(RenderMeshNormals, CreaseAngleDecidesBetweenSmoothAndSplit) {
    // Two strips of two triangles folded along the x axis by 30 and by 50 degrees.
    for (const double fold : {30.0, 50.0}) {
        const double a = fold * std::numbers::pi / 180.0;
        TriangleMesh m;
        m.vertices = {{0, 0, 0},
                      {1, 0, 0},
                      {0, 1, 0},
                      {1, 1, 0},
                      {0, -std::cos(a), std::sin(a)},
                      {1, -std::cos(a), std::sin(a)}};
        m.triangles = {{0, 1, 3}, {0, 3, 2}, {1, 0, 4}, {1, 4, 5}};
        const auto normals = render::corner_normals(m);
        const Vec3 up{0, 0, 1};
        // Corner 0 of triangle 0 and corner 1 of triangle 2 sit on vertex 0, on either side.
        const Vec3 here = normals[0], there = normals[3 * 2 + 1];
        if (fold < render::crease_angle_degrees) {
            EXPECT_LT(norm(here - there), 1e-12);
            const double tilt = std::acos(dot(here, up));  // between the faces
            EXPECT_GT(tilt, 0.2 * a);
            EXPECT_LT(tilt, 0.8 * a);
        } else {
            EXPECT_GT(dot(here, up), 1.0 - 1e-12);  // the flat side's own normal
            EXPECT_NEAR(std::acos(dot(there, up)), a, 1e-9);
        }
    }
}
