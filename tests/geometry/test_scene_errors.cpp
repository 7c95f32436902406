// build_scene's errors (geometry.hpp): each names what is at fault (the file, the type
// or the option) and has the documented kind.
#include <functional>

#include "geometry_test_util.hpp"
#include "tessera/error.hpp"

using namespace geometry_test;

namespace {

class SceneErrors : public TempDir {
protected:
    void expect_error(const std::function<void()>& f, ErrorKind kind, const std::vector<std::string>& fragments) {
        try {
            f();
            FAIL() << "no error";
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), kind) << e.what();
            for (const std::string& fragment : fragments)
                EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos)
                    << "'" << fragment << "' not in: " << e.what();
        }
    }
    Exemplar with_mesh(const std::string& mesh, bool rigid, std::vector<Vec3> reference) {
        Exemplar ex;
        ex.dimension = 2;
        ex.domain = Domain::box({0, 0, 0}, {4, 4, 0}, 2);
        ex.types.push_back({"spaghetti", rigid, false, mesh, reference, std::nullopt});
        ex.add_element(0, {{1, 1, 0}, {2, 1, 0}});
        return ex;
    }
};

}  // namespace

TEST_F(SceneErrors, MissingMeshFileIsAnIoErrorNamingIt) {
    expect_error([&] { build_scene(with_mesh(path("nowhere.obj"), true, {})); }, ErrorKind::io,
                 {"nowhere.obj", "spaghetti"});
}

TEST_F(SceneErrors, RelativeMeshPathsUseTheBaseDirectory) {
    write_mesh("tetra.obj", tetrahedron());
    const Exemplar ex = with_mesh("tetra.obj", true, {});
    GeometryOptions options;
    options.base_directory = dir_.string();
    EXPECT_EQ(build_scene(ex, options).meshes.size(), 1u);
    expect_error([&] { build_scene(ex); }, ErrorKind::io, {"tetra.obj"});  // not in the working directory
}

TEST_F(SceneErrors, MeshWithoutTrianglesNamesTheType) {
    write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    expect_error([&] { build_scene(with_mesh(path("points.obj"), true, {})); }, ErrorKind::input,
                 {"spaghetti", "no triangles"});
}

TEST_F(SceneErrors, ReferenceCountMismatchNamesTheType) {
    const std::string mesh = write_mesh("tetra.obj", tetrahedron());
    expect_error([&] { build_scene(with_mesh(mesh, true, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}})); }, ErrorKind::input,
                 {"spaghetti", "3 samples", "have 2"});
}

TEST_F(SceneErrors, DeformableMeshNeedsAReference) {
    const std::string mesh = write_mesh("tetra.obj", tetrahedron());
    expect_error([&] { build_scene(with_mesh(mesh, false, {})); }, ErrorKind::input, {"spaghetti", "reference"});
    EXPECT_NO_THROW(build_scene(with_mesh(mesh, false, {{-0.5, 0, 0}, {0.5, 0, 0}})));
    EXPECT_NO_THROW(build_scene(with_mesh("", false, {})));  // no mesh: a tube, no reference needed
}

TEST_F(SceneErrors, BadOptionsNameTheField) {
    const Exemplar ex = with_mesh("", true, {});
    GeometryOptions o;
    o.tube_sides = 2;
    expect_error([&] { build_scene(ex, o); }, ErrorKind::option, {"tube_sides"});
    o = {};
    o.sphere_subdivisions = 6;
    expect_error([&] { build_scene(ex, o); }, ErrorKind::option, {"sphere_subdivisions"});
    o = {};
    o.deform_falloff = 0.0;
    expect_error([&] { build_scene(ex, o); }, ErrorKind::option, {"deform_falloff"});
}
