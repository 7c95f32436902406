// Tests of render_scene_png, the pictures of element meshes, on scenes built by hand:
// 3D colour by class, flat faces with crisp edges on a box and smooth shading on a
// sphere, depth order along the view, 2D placement and rotation in the 2D preview's
// frame, winding independence, determinism, empty and degenerate scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/render_test_util.hpp"
#include "render/scene_3d.hpp"
#include "render/style.hpp"
#include "tessera/error.hpp"
#include "tessera/render.hpp"

using namespace tessera;

namespace {

// A box centred on the origin with half sides h, outward counter-clockwise faces.
TriangleMesh box_mesh(Vec3 h) {
    TriangleMesh m;
    for (int i = 0; i < 8; ++i)
        m.vertices.push_back({(i & 1) ? h.x : -h.x, (i & 2) ? h.y : -h.y, (i & 4) ? h.z : -h.z});
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads)
        m.triangles.push_back({q[0], q[1], q[2]}), m.triangles.push_back({q[0], q[2], q[3]});
    return m;
}

SceneInstance placed(int element, int type, int mesh, Vec3 position, Quat orientation = {}) {
    SceneInstance s;
    s.element = element, s.type = type, s.mesh = mesh, s.instanced = true;
    s.position = position, s.orientation = orientation;
    return s;
}

Exemplar cube_data_3d() {
    Exemplar ex;
    ex.dimension = 3;
    ex.domain = Domain::box({0, 0, 0}, {4, 4, 4}, 3);
    ex.add_element(ex.type_index("a"), {Vec3{2, 2, 2}});
    ex.add_element(ex.type_index("b"), {Vec3{1, 1, 1}});
    return ex;
}

Scene one_cube_scene_3d() {
    Scene s;
    s.dimension = 3;
    s.type_names = {"a", "b"};
    s.meshes = {box_mesh({0.5, 0.5, 0.5})};
    s.instances = {placed(0, 0, 0, {2, 2, 2})};
    return s;
}

// Hue in degrees; -1 for a grey.
double hue(render::Rgb c) {
    const float hi = std::max({c.r, c.g, c.b}), lo = std::min({c.r, c.g, c.b}), d = hi - lo;
    if (d < 1e-6f) return -1.0;
    double h = hi == c.r ? (c.g - c.b) / d : hi == c.g ? 2.0 + (c.b - c.r) / d : 4.0 + (c.r - c.g) / d;
    h *= 60.0;
    return h < 0.0 ? h + 360.0 : h;
}

double hue_distance(render::Rgb a, render::Rgb b) {
    const double d = std::abs(hue(a) - hue(b));
    return std::min(d, 360.0 - d);
}

bool saturated(render::Rgb c) {
    return std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b}) > 0.15f;
}
// Any tint at all: mesh pixels however dark or light their shading, not the grey outline.
bool tinted(render::Rgb c) {
    return std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b}) > 0.02f;
}

}  // namespace

TEST(RenderScene, CubeAtTheDomainCentreInItsClassColour) {
    const std::string png = render_scene_png(cube_data_3d(), one_cube_scene_3d(), {.width = 240});
    ASSERT_TRUE(test::has_png_signature(png));
    const auto img = test::decode_png(png);
    ASSERT_EQ(img.width, 240);
    const auto centre = img.at(img.width / 2, img.height / 2);
    EXPECT_TRUE(saturated(centre));
    EXPECT_LT(hue_distance(centre, render::class_color(0)), 5.0);
    EXPECT_EQ(test::color_distance(img.at(0, 0), render::white), 0);
    EXPECT_EQ(test::color_distance(img.at(img.width - 1, img.height - 1), render::white), 0);
    // Shaded: the cube is not one flat colour (its faces face the light differently).
    float darkest = 3.0f, brightest = 0.0f;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            if (const auto c = img.at(x, y); saturated(c)) {
                darkest = std::min(darkest, c.r + c.g + c.b),
                brightest = std::max(brightest, c.r + c.g + c.b);
            }
    EXPECT_GT(brightest - darkest, 0.3f);
}

TEST(RenderScene, CubeFacesAreFlatWithDistinctShades) {
    // Pixels well inside each face the camera sees (a 5 x 5 grid over the middle 60%):
    // one colour per face once the depth fog (which lightens the farther parts of a
    // face a little) is taken out, and a different colour on each face.
    const Exemplar ex = cube_data_3d();
    const Scene s = one_cube_scene_3d();
    const RenderOptions options{.width = 300, .show_domain = false};  // no edges across the faces
    const auto img = test::decode_png(render_scene_png(ex, s, options));
    const render::View3D view = render::View3D::standard();
    std::vector<render::Sphere> extent;  // framed as render_scene_png frames it
    for (const auto& [a, b] : render::box_edges({{1.5, 1.5, 1.5}, {2.5, 2.5, 2.5}}))
        for (const Vec3& corner : {a, b}) extent.push_back({corner, 0.0, 0, false});
    const auto frame = render::make_frame_3d(ex, extent, view, options);
    ASSERT_EQ(img.width, frame.width);
    std::vector<render::Rgb> means;
    for (int axis = 0; axis < 3; ++axis)
        for (const double side : {-1.0, 1.0}) {
            Vec3 n;
            n[axis] = side;
            if (dot(n, view.toward) < 0.2) continue;                     // hidden or seen edge-on
            const Vec3 u = Vec3{n.y, n.z, n.x} * side, w = cross(n, u);  // in the face
            render::Rgb sum{0, 0, 0}, lo{1, 1, 1}, hi{0, 0, 0};
            for (int i = -2; i <= 2; ++i)
                for (int j = -2; j <= 2; ++j) {
                    const Vec3 p = Vec3{2, 2, 2} + n * 0.5 + u * (0.15 * i) + w * (0.15 * j);
                    const auto fogged =
                        img.at(static_cast<int>(frame.px(view, p)), static_cast<int>(frame.py(view, p)));
                    EXPECT_LT(hue_distance(fogged, render::class_color(0)), 5.0);
                    // shade_sphere: toward_white(lit, 0.4 * farness), undone.
                    const float f = static_cast<float>(
                        0.4 * std::clamp((frame.near - view.depth(p)) / (frame.near - frame.far), 0.0, 1.0));
                    const render::Rgb c{(fogged.r - f) / (1 - f), (fogged.g - f) / (1 - f),
                                        (fogged.b - f) / (1 - f)};
                    sum.r += c.r / 25, sum.g += c.g / 25, sum.b += c.b / 25;
                    lo = {std::min(lo.r, c.r), std::min(lo.g, c.g), std::min(lo.b, c.b)};
                    hi = {std::max(hi.r, c.r), std::max(hi.g, c.g), std::max(hi.b, c.b)};
                }
            EXPECT_LE(test::color_distance(lo, hi), 3) << "face " << n.x << " " << n.y << " " << n.z;
            means.push_back(sum);
        }
    ASSERT_EQ(means.size(), 3u);  // -y, +x and the top
    for (size_t a = 0; a < 3; ++a)
        for (size_t b = a + 1; b < 3; ++b)
            EXPECT_GE(test::color_distance(means[a], means[b]), 20) << a << " " << b;
}

TEST(RenderScene, IcosphereShadesSmoothly) {
    // A sphere of 320 triangles: across the edges between its faces, as anywhere inside
    // its outline, neighbouring pixels differ little (flat faces would step by ~10
    // degrees of normal, tens of 8-bit levels).
    const Exemplar ex = cube_data_3d();
    Scene s = one_cube_scene_3d();
    s.meshes = {test::icosphere(2, 1.5)};
    const RenderOptions options{.width = 400, .show_domain = false};
    const auto img = test::decode_png(render_scene_png(ex, s, options));
    const render::View3D view = render::View3D::standard();
    std::vector<render::Sphere> extent;
    for (const auto& [a, b] : render::box_edges({{0.5, 0.5, 0.5}, {3.5, 3.5, 3.5}}))
        for (const Vec3& corner : {a, b}) extent.push_back({corner, 0.0, 0, false});
    const auto frame = render::make_frame_3d(ex, extent, view, options);
    ASSERT_EQ(img.width, frame.width);
    const double cx = frame.px(view, {2, 2, 2}), cy = frame.py(view, {2, 2, 2}), r = 1.5 * frame.scale;
    int steepest = 0, inside = 0;
    for (int y = 0; y + 1 < img.height; ++y)
        for (int x = 0; x + 1 < img.width; ++x) {
            if (std::hypot(x + 0.5 - cx, y + 0.5 - cy) > 0.85 * r) continue;
            ++inside;
            const auto c = img.at(x, y);
            EXPECT_LT(hue_distance(c, render::class_color(0)), 8.0);
            steepest = std::max({steepest, test::color_distance(c, img.at(x + 1, y)),
                                 test::color_distance(c, img.at(x, y + 1))});
        }
    EXPECT_GT(inside, 10000);
    EXPECT_LE(steepest, 6);
}

TEST(RenderScene, NearerInstanceWinsAlongTheViewDirection) {
    const Vec3 toward = render::View3D::standard().toward;
    const Vec3 c{2, 2, 2};
    for (const bool near_first : {false, true}) {
        Scene s = one_cube_scene_3d();
        const SceneInstance far = placed(0, 0, 0, c - toward * 1.2), near = placed(1, 1, 0, c + toward * 1.2);
        s.instances = near_first ? std::vector{near, far} : std::vector{far, near};
        const auto img = test::decode_png(render_scene_png(cube_data_3d(), s, {.width = 240}));
        const auto centre = img.at(img.width / 2, img.height / 2);  // both cubes project here
        EXPECT_LT(hue_distance(centre, render::class_color(1)), 5.0)
            << "near instance listed first: " << near_first;
    }
}

TEST(RenderScene, WindingDoesNotMatter) {
    const Exemplar ex = cube_data_3d();
    Scene s = one_cube_scene_3d();
    const std::string reference = render_scene_png(ex, s, {.width = 160});
    // Reversed everywhere, then every other triangle reversed.
    for (auto& t : s.meshes[0].triangles) std::swap(t[1], t[2]);
    EXPECT_EQ(render_scene_png(ex, s, {.width = 160}), reference);
    for (size_t k = 0; k < s.meshes[0].triangles.size(); k += 2)
        std::swap(s.meshes[0].triangles[k][1], s.meshes[0].triangles[k][2]);
    EXPECT_EQ(render_scene_png(ex, s, {.width = 160}), reference);
}

TEST(RenderScene, OwnMeshesInWorldCoordinatesMatchInstancedOnes) {
    const Exemplar ex = cube_data_3d();
    const Scene instanced = one_cube_scene_3d();
    Scene own = instanced;
    for (auto& v : own.meshes[0].vertices) v += Vec3{2, 2, 2};
    own.instances[0].instanced = false;
    own.instances[0].position = {};
    const auto a = test::decode_png(render_scene_png(ex, instanced, {.width = 160}));
    const auto b = test::decode_png(render_scene_png(ex, own, {.width = 160}));
    ASSERT_EQ(a.rgb.size(), b.rgb.size());
    int differing = 0;
    for (size_t i = 0; i < a.rgb.size(); ++i) differing += std::abs(int(a.rgb[i]) - int(b.rgb[i])) > 2;
    EXPECT_EQ(differing, 0);
}

TEST(RenderScene, TwoDimensionalCubeSeenFromAboveWhereThePreviewPutsTheElement) {
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    ex.add_element(ex.type_index("a"), {Vec3{3, 6, 0}}, 1.0);
    Scene s;
    s.dimension = 2;
    s.type_names = {"a"};
    s.meshes = {box_mesh({1, 1, 1})};
    s.instances = {placed(0, 0, 0, {3, 6, 0})};
    const auto img = test::decode_png(render_scene_png(ex, s, {.width = 400, .show_legend = false}));
    const auto frame = render::make_frame_2d(ex, render::make_style(ex, {}), RenderOptions{.width = 400});
    ASSERT_EQ(img.width, frame.width);
    ASSERT_EQ(img.height, frame.height);  // the pixel scale of render_png
    double sx = 0, sy = 0;
    int n = 0, x0 = img.width, x1 = -1, y0 = img.height, y1 = -1;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            if (const auto c = img.at(x, y); tinted(c)) {
                EXPECT_LT(hue_distance(c, render::class_color(0)), 8.0);
                sx += x + 0.5, sy += y + 0.5, ++n;
                x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
            }
    ASSERT_GT(n, 0);
    EXPECT_NEAR(sx / n, frame.px(3), 2.0);
    EXPECT_NEAR(sy / n, frame.py(6), 2.0);
    // A 2 x 2 square seen from above.
    EXPECT_NEAR(x1 + 1 - x0, 2.0 * frame.scale, 2.0);
    EXPECT_NEAR(y1 + 1 - y0, 2.0 * frame.scale, 2.0);
    EXPECT_EQ(test::color_distance(img.at(static_cast<int>(frame.px(7)), static_cast<int>(frame.py(3))),
                                   render::white),
              0);
}

TEST(RenderScene, TwoDimensionalRotationAboutZTurnsAnElongatedBox) {
    Exemplar ex;
    ex.domain = Domain::box({0, 0, 0}, {10, 10, 0}, 2);
    ex.add_element(ex.type_index("stick"), {Vec3{5, 5, 0}}, 1.0);
    Scene s;
    s.dimension = 2;
    s.type_names = {"stick"};
    s.meshes = {box_mesh({2.5, 0.4, 0.4})};
    s.instances = {placed(0, 0, 0, {5, 5, 0})};
    const auto frame = render::make_frame_2d(ex, render::make_style(ex, {}), RenderOptions{.width = 300});
    auto covered = [&](const test::Image& img, double x, double y) {
        return tinted(img.at(static_cast<int>(frame.px(x)), static_cast<int>(frame.py(y))));
    };
    const auto along_x = test::decode_png(render_scene_png(ex, s, {.width = 300}));
    EXPECT_TRUE(covered(along_x, 5, 5));
    EXPECT_TRUE(covered(along_x, 7, 5));
    EXPECT_TRUE(covered(along_x, 3, 5));
    EXPECT_FALSE(covered(along_x, 5, 7));
    EXPECT_FALSE(covered(along_x, 5, 3));

    s.instances[0].orientation = Quat::from_angle_z(0.5 * std::numbers::pi);
    const auto along_y = test::decode_png(render_scene_png(ex, s, {.width = 300}));
    EXPECT_TRUE(covered(along_y, 5, 5));
    EXPECT_TRUE(covered(along_y, 5, 7));
    EXPECT_TRUE(covered(along_y, 5, 3));
    EXPECT_FALSE(covered(along_y, 7, 5));
    EXPECT_FALSE(covered(along_y, 3, 5));
}

TEST(RenderScene, OutputIsDeterministic) {
    Exemplar ex = cube_data_3d();
    Scene s = one_cube_scene_3d();
    s.meshes.push_back(box_mesh({1.2, 0.2, 0.3}));
    for (int i = 0; i < 20; ++i)
        s.instances.push_back(placed(0, i % 3, i % 2, {0.2 * i, 4.0 - 0.2 * i, 0.1 * i},
                                     Quat{std::cos(0.1 * i), std::sin(0.1 * i), 0.0, 0.0}));
    const std::string a = render_scene_png(ex, s, {.width = 300});
    const std::string b = render_scene_png(ex, s, {.width = 300});
    EXPECT_EQ(a, b);
}

TEST(RenderScene, EmptySceneIsJustTheDomain) {
    for (const int dimension : {2, 3}) {
        Exemplar ex;
        ex.dimension = dimension;
        ex.domain =
            dimension == 2 ? Domain::box({0, 0, 0}, {3, 2, 0}, 2) : Domain::box({0, 0, 0}, {1, 2, 3}, 3);
        Scene s;
        s.dimension = dimension;
        EXPECT_EQ(render_scene_png(ex, s, {.width = 120}), render_png(ex, {.width = 120}))
            << dimension << "D";
    }
}

TEST(RenderScene, DegenerateTrianglesDoNotCrash) {
    const Exemplar ex = cube_data_3d();
    Scene s = one_cube_scene_3d();
    TriangleMesh flat;
    flat.vertices = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {0, 0, 0}};
    flat.triangles = {{0, 1, 2}, {0, 3, 1}, {1, 1, 1}, {3, 0, 3}};  // collinear, coincident, repeated
    s.meshes.push_back(flat);
    TriangleMesh point;
    point.vertices = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    point.triangles = {{0, 1, 2}};
    s.meshes.push_back(point);
    s.meshes.push_back(TriangleMesh{});  // no triangles at all
    s.instances.push_back(placed(1, 1, 1, {1, 1, 1}));
    s.instances.push_back(placed(1, 1, 2, {3, 3, 3}));
    s.instances.push_back(placed(1, 1, 3, {3, 1, 3}));
    SceneInstance squashed = placed(1, 1, 0, {1, 3, 1});
    squashed.scale = 0.0;
    s.instances.push_back(squashed);
    const auto img = test::decode_png(render_scene_png(ex, s, {.width = 160}));
    ASSERT_EQ(img.width, 160);
    EXPECT_LT(hue_distance(img.at(img.width / 2, img.height / 2), render::class_color(0)),
              5.0);  // the cube still shows
}

TEST(RenderScene, RejectsSceneThatDoesNotFitTheData) {
    const Exemplar ex = cube_data_3d();
    Scene s = one_cube_scene_3d();
    s.instances[0].mesh = 1;
    EXPECT_THROW(render_scene_png(ex, s), Error);
    s.instances[0].mesh = 0;
    s.dimension = 2;
    EXPECT_THROW(render_scene_png(ex, s), Error);
    s.dimension = 3;
    EXPECT_THROW(render_scene_png(ex, s, {.width = 4}), Error);
}
