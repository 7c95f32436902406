// save_animation to .usda (src/geometry/write_usda_animated.cpp): each kind of element under
// its own prim (PointInstancer, BasisCurves, Mesh), one time sample per frame at the time
// codes of the frames' time stamps, read back with the strict reader of tests/io/usda_reader.hpp
// (no USD library is installed to run usdcat).
#include <gtest/gtest.h>

#include <filesystem>

#include "geometry/animated_fixtures.hpp"
#include "geometry/animated_scene.hpp"
#include "geometry/geometry_test_util.hpp"
#include "io/usda_reader.hpp"
#include "tessera/animation_io.hpp"
#include "tessera/error.hpp"

namespace geometry_test {
namespace {

using animated_test::mixed_animation;
using usda_test::Layer;
using usda_test::Prim;
using usda_test::Value;

class AnimatedUsda : public TempDir {
protected:
    Layer save_and_read(const Animation& a, const std::string& name) {
        save_animation(a, path(name));
        return usda_test::read_usda(read(name));
    }
};

// The points of a time sample as Vec3s.
std::vector<Vec3> points(const Value& list) {
    std::vector<Vec3> out;
    for (const Value& p : list.items) out.push_back({p.items[0].x, p.items[1].x, p.items[2].x});
    return out;
}

// The samples of the elements of `type`, in element order, at frame f.
std::vector<Vec3> expected_points(const Animation& a, const std::string& type, int f) {
    std::vector<Vec3> out;
    for (const Element& el : a.structure.elements)
        if (a.structure.types[el.type].name == type)
            for (int k = 0; k < el.sample_count; ++k) out.push_back(a.at(f, el.first_sample + k));
    return out;
}

void expect_one_sample_per_frame(const Prim& prim, const std::string& property, int frames) {
    const auto& samples = prim.property(property).samples;
    ASSERT_EQ(samples.size(), static_cast<size_t>(frames)) << prim.path << "." << property;
    for (int f = 0; f < frames; ++f) EXPECT_EQ(samples[f].first, f) << prim.path << "." << property;
}

TEST_F(AnimatedUsda, EachKindUnderItsOwnPrimWithOneTimeSamplePerFrame) {
    const Animation a = mixed_animation(6, write_mesh("shard.obj", tetrahedron()));
    const Layer layer = save_and_read(a, "mixed.usda");
    EXPECT_EQ(layer.metadata.at("startTimeCode").x, 0);
    EXPECT_EQ(layer.metadata.at("endTimeCode").x, 5);
    EXPECT_EQ(layer.metadata.at("timeCodesPerSecond").x, 8);  // frames 0.125 s apart

    const Prim* instancer = layer.find("/World/Elements");
    ASSERT_NE(instancer, nullptr);
    EXPECT_EQ(instancer->type, "PointInstancer");
    EXPECT_EQ(instancer->property("ids").value.items.size(), 4u);  // 3 dots and the shard
    for (const char* p : {"positions", "orientations", "orientationsf"}) expect_one_sample_per_frame(*instancer, p, 6);
    const Value& dot0 = instancer->property("positions").samples[3].second.items[0];
    EXPECT_NEAR(dot0.items[0].x, a.at(3, 0).x, 1e-6);

    const Prim* threads = layer.find("/World/Threads/noodle");
    ASSERT_NE(threads, nullptr);
    EXPECT_EQ(threads->type, "BasisCurves");
    EXPECT_EQ(threads->property("type").value.text, "linear");
    EXPECT_EQ(threads->property("curveVertexCounts").value.items.size(), 3u);
    for (const Value& n : threads->property("curveVertexCounts").value.items) EXPECT_EQ(n.x, 10);
    const Value& widths = threads->property("widths").value;
    ASSERT_EQ(widths.items.size(), 30u);
    EXPECT_FLOAT_EQ(widths.items[0].x, 0.1);        // 2 x radius 0.05
    EXPECT_GT(widths.items[29].x, 0.0);             // no radius: the default tube's
    EXPECT_EQ(threads->property("primvars:tessera:id").metadata.at("interpolation").text, "uniform");
    EXPECT_EQ(threads->property("primvars:tessera:id").value.items[2].x, 17);
    for (const char* p : {"points", "extent"}) expect_one_sample_per_frame(*threads, p, 6);
    for (int f = 0; f < 6; ++f)
        EXPECT_LT(max_distance(points(threads->property("points").samples[f].second), expected_points(a, "noodle", f)),
                  1e-6);

    const Prim* sheet = layer.find("/World/Sheets/cloth");
    ASSERT_NE(sheet, nullptr);
    EXPECT_EQ(sheet->type, "Mesh");
    const auto& counts = sheet->property("faceVertexCounts").value.items;
    ASSERT_EQ(counts.size(), 12u);  // (4 - 1) x (5 - 1) quads
    for (const Value& n : counts) EXPECT_EQ(n.x, 4);
    const auto& indices = sheet->property("faceVertexIndices").value.items;
    ASSERT_EQ(indices.size(), 48u);
    for (const Value& i : indices) EXPECT_TRUE(i.x >= 0 && i.x < 20) << i.x;
    EXPECT_EQ(sheet->property("primvars:tessera:id").value.items.size(), 12u);
    for (const char* p : {"points", "extent"}) expect_one_sample_per_frame(*sheet, p, 6);
    for (int f = 0; f < 6; ++f)
        EXPECT_LT(max_distance(points(sheet->property("points").samples[f].second), expected_points(a, "cloth", f)), 1e-6);
    // One winding: every quad faces +z (the sheet lies along x-y, waving in z).
    const std::vector<Vec3> p0 = points(sheet->property("points").samples[0].second);
    for (size_t q = 0; q < 12; ++q) {
        const auto corner = [&](size_t k) { return p0.at(static_cast<size_t>(indices[4 * q + k].x)); };
        EXPECT_GT(cross(corner(2) - corner(0), corner(3) - corner(1)).z, 0.0) << "quad " << q;
    }
}

TEST_F(AnimatedUsda, UnevenTimesGetFractionalTimeCodes) {
    Animation a = mixed_animation(3);
    a.times = {0.0, 0.1, 0.3};
    const geometry::TimeCodes t = geometry::usd_time_codes(a.times);
    EXPECT_DOUBLE_EQ(t.per_second, 2 / 0.3);
    ASSERT_EQ(t.codes.size(), 3u);
    EXPECT_EQ(t.codes[0], 0);
    EXPECT_NEAR(t.codes[1], 2.0 / 3.0, 1e-12);
    EXPECT_EQ(t.codes[2], 2);
    const Layer layer = save_and_read(a, "uneven.usda");
    EXPECT_EQ(layer.metadata.at("endTimeCode").x, 2);
    const auto& samples = layer.find("/World/Threads/noodle")->property("points").samples;
    ASSERT_EQ(samples.size(), 3u);
    EXPECT_NEAR(samples[1].first, 2.0 / 3.0, 1e-12);
}

TEST_F(AnimatedUsda, OneFrameIsAStillLayerAndBytesAreDeterministic) {
    const Layer layer = save_and_read(mixed_animation(1), "still.usda");
    EXPECT_EQ(layer.metadata.count("timeCodesPerSecond"), 0u);
    EXPECT_TRUE(layer.find("/World/Sheets/cloth")->property("points").samples.empty());
    const Animation a = mixed_animation(4);
    save_animation(a, path("a.usda"));
    save_animation(a, path("b.usda"));
    EXPECT_EQ(read("a.usda"), read("b.usda"));
}

TEST_F(AnimatedUsda, ElementsWithoutAnAnimatedFormAreAnErrorNamingTheFileAndWriteNothing) {
    Animation a = mixed_animation(3, write_mesh("blob.obj", tetrahedron()));
    Exemplar& s = a.structure;
    s.types[static_cast<size_t>(s.find_type("shard"))].rigid = false;  // deformed, topology automatic
    s.types[static_cast<size_t>(s.find_type("shard"))].topology = ElementTopology::none;
    s.types[static_cast<size_t>(s.find_type("shard"))].reference = animated_test::shard_layout();
    for (const char* name : {"x.usda", "x.glb"}) {
        try {
            save_animation(a, path(name));
            FAIL() << "no error for " << name;
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::input);
            const std::string what = e.what();
            EXPECT_NE(what.find("cannot save animation " + path(name) + ": type 'shard'"), std::string::npos) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
        EXPECT_FALSE(std::filesystem::exists(path(name)));
    }
}

}  // namespace
}  // namespace geometry_test
