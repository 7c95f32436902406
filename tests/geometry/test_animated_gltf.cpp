// save_animation to .gltf and .glb (src/geometry/write_gltf_animation.cpp, gltf_morph.cpp),
// loaded back with tinygltf: a node per element under the z-up root, one animation whose
// samplers read the frames' times, translation/rotation channels of the instanced elements
// and weights channels of the morphed threads and sheets, whose base + target f is frame f.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "cli/cli_fixture.hpp"
#include "dynamic/dynamic_fixtures.hpp"
#include "geometry/animated_fixtures.hpp"
#include "geometry/geometry_test_util.hpp"
#include "geometry/tinygltf.hpp"
#include "tessera/animation_io.hpp"

namespace geometry_test {
namespace {

using animated_test::mixed_animation;

tinygltf::Model load_gltf(const std::string& bytes) {
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    const bool ok =
        bytes.compare(0, 4, "glTF") == 0
            ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                          static_cast<unsigned>(bytes.size()), "")
            : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), static_cast<unsigned>(bytes.size()), "");
    EXPECT_TRUE(ok) << err;
    EXPECT_TRUE(warn.empty()) << warn;
    return model;
}

// The float components of an accessor (tightly packed, as the writer makes them).
std::vector<float> floats(const tinygltf::Model& m, int accessor) {
    const tinygltf::Accessor& a = m.accessors.at(static_cast<size_t>(accessor));
    EXPECT_EQ(a.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
    const tinygltf::BufferView& v = m.bufferViews.at(static_cast<size_t>(a.bufferView));
    std::vector<float> out(a.count * static_cast<size_t>(tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type))));
    std::memcpy(out.data(), m.buffers.at(0).data.data() + v.byteOffset + a.byteOffset, out.size() * sizeof(float));
    return out;
}

// min and max of an accessor are those of its values (per component).
void expect_bounds(const tinygltf::Model& m, int accessor) {
    const std::vector<float> v = floats(m, accessor);
    const tinygltf::Accessor& a = m.accessors[accessor];
    const size_t n = a.minValues.size();
    ASSERT_GT(n, 0u);
    ASSERT_EQ(a.maxValues.size(), n);
    for (size_t c = 0; c < n; ++c) {
        float lo = v[c], hi = v[c];
        for (size_t k = c; k < v.size(); k += n) lo = std::min(lo, v[k]), hi = std::max(hi, v[k]);
        EXPECT_EQ(a.minValues[c], lo);
        EXPECT_EQ(a.maxValues[c], hi);
    }
}

// The channel of `node` animating `path`, or nullptr.
const tinygltf::AnimationChannel* channel(const tinygltf::Animation& anim, int node, const std::string& path) {
    for (const auto& c : anim.channels)
        if (c.target_node == node && c.target_path == path) return &c;
    return nullptr;
}

class AnimatedGltf : public TempDir {
protected:
    // Checks everything the file says against the animation; `shift` is what the writer
    // adds to the times (a negative first time stamp becomes 0).
    void check(const Animation& a, const std::string& name, double shift = 0.0) {
        save_animation(a, path(name));
        const tinygltf::Model m = load_gltf(read(name));
        const size_t elements = a.structure.elements.size();
        ASSERT_EQ(m.nodes.size(), elements + 1);  // + the z-up root
        EXPECT_EQ(m.nodes.back().children.size(), elements);
        ASSERT_EQ(m.animations.size(), 1u);
        const tinygltf::Animation& anim = m.animations[0];
        for (const auto& s : anim.samplers) {
            EXPECT_EQ(s.interpolation, "LINEAR");
            const std::vector<float> t = floats(m, s.input);
            ASSERT_EQ(t.size(), a.times.size());
            for (size_t f = 0; f < t.size(); ++f) EXPECT_EQ(t[f], float(a.times[f] + shift)) << f;
            expect_bounds(m, s.input);
        }
        for (size_t e = 0; e < elements; ++e) check_element(a, m, anim, static_cast<int>(e));
    }

    void check_element(const Animation& a, const tinygltf::Model& m, const tinygltf::Animation& anim, int e) {
        const Element& el = a.structure.elements[e];
        const std::string type = a.structure.types[el.type].name;
        EXPECT_EQ(m.nodes[e].name, type + "_" + std::to_string(el.id));
        if (type == "dot" || type == "shard") return check_instance(a, m, anim, e);
        const auto* weights = channel(anim, e, "weights");
        ASSERT_NE(weights, nullptr) << e;
        const std::vector<float> w = floats(m, anim.samplers[weights->sampler].output);
        const size_t n = a.times.size();
        ASSERT_EQ(w.size(), n * n);
        for (size_t f = 0; f < n; ++f)
            for (size_t t = 0; t < n; ++t) EXPECT_EQ(w[f * n + t], f == t ? 1.0f : 0.0f);
        const tinygltf::Primitive& p = m.meshes.at(static_cast<size_t>(m.nodes[e].mesh)).primitives.at(0);
        EXPECT_EQ(p.mode, type == "noodle" ? TINYGLTF_MODE_LINE_STRIP : TINYGLTF_MODE_TRIANGLES);
        if (type == "cloth") {
            EXPECT_EQ(m.accessors.at(static_cast<size_t>(p.indices)).count, 72u);  // 12 quads
        }
        const std::vector<float> base = floats(m, p.attributes.at("POSITION"));
        expect_bounds(m, p.attributes.at("POSITION"));
        ASSERT_EQ(p.targets.size(), n);
        for (size_t f = 0; f < n; ++f) {
            const int target = p.targets[f].at("POSITION");
            expect_bounds(m, target);
            const std::vector<float> d = floats(m, target);
            ASSERT_EQ(d.size(), 3u * static_cast<size_t>(el.sample_count));
            for (int s = 0; s < el.sample_count; ++s) {
                const Vec3 q{base[3 * s] + d[3 * s], base[3 * s + 1] + d[3 * s + 1], base[3 * s + 2] + d[3 * s + 2]};
                EXPECT_LT(norm(q - a.at(static_cast<int>(f), el.first_sample + s)), 1e-5) << e << " " << f << " " << s;
            }
        }
    }

    void check_instance(const Animation& a, const tinygltf::Model& m, const tinygltf::Animation& anim, int e) {
        const Element& el = a.structure.elements[e];
        const bool shard = a.structure.types[el.type].name == "shard";
        const auto* translation = channel(anim, e, "translation");
        ASSERT_NE(translation, nullptr) << e;
        const std::vector<float> t = floats(m, anim.samplers[translation->sampler].output);
        ASSERT_EQ(t.size(), 3 * a.times.size());
        const auto* rotation = channel(anim, e, "rotation");
        EXPECT_EQ(rotation != nullptr, shard) << e;  // only the shard turns
        for (int f = 0; f < a.frame_count(); ++f) {
            Vec3 centroid;
            for (int s = 0; s < el.sample_count; ++s) centroid += a.at(f, el.first_sample + s) / el.sample_count;
            EXPECT_LT(norm(Vec3{t[3 * f], t[3 * f + 1], t[3 * f + 2]} - centroid), 1e-5) << e << " " << f;
        }
        if (!rotation) return;
        const std::vector<float> r = floats(m, anim.samplers[rotation->sampler].output);  // x, y, z, w
        for (int f = 0; f < a.frame_count(); ++f) {
            const double half = 0.5 * animated_test::shard_turn * f;
            EXPECT_NEAR(std::abs(r[4 * f + 2] * std::sin(half) + r[4 * f + 3] * std::cos(half)), 1.0, 1e-5) << f;
        }
    }
};

TEST_F(AnimatedGltf, GltfAndGlbCarryEveryElementsMotion) {
    const Animation a = mixed_animation(6, write_mesh("shard.obj", tetrahedron()));
    check(a, "mixed.gltf");
    check(a, "mixed.glb");
}

TEST_F(AnimatedGltf, NegativeTimesStartAtZeroAndBytesAreDeterministic) {
    const Animation a = mixed_animation(4, "", -0.25);
    check(a, "early.glb", 0.25);
    save_animation(a, path("again.glb"));
    EXPECT_EQ(read("early.glb"), read("again.glb"));
}

TEST_F(AnimatedGltf, TargetNamesNameTheFrames) {
    save_animation(mixed_animation(3), path("names.gltf"));
    const tinygltf::Model m = load_gltf(read("names.gltf"));
    const tinygltf::Value& names = m.meshes.at(static_cast<size_t>(m.nodes.at(1).mesh)).extras.Get("targetNames");
    ASSERT_EQ(names.ArrayLen(), 3u);
    EXPECT_EQ(names.Get(2).Get<std::string>(), "frame 2");
}

}  // namespace
}  // namespace geometry_test

namespace tessera_cli_test {
namespace {

class AnimatedGltfCli : public CliFixture {};

TEST_F(AnimatedGltfCli, SynthWritesAnAnimatedGlb) {
    tessera::save_animation(dynamic_test::drifting_lattice(5, 5, 3, {0.1, 0, 0}, 0.05), path("lattice.json"));
    const Result r = run("synth '" + path("lattice.json") + "' -o '" + path("out.glb") + "' --frames 3 --scale 1.2 -q");
    ASSERT_EQ(r.code, 0) << r.err;
    const tinygltf::Model m = geometry_test::load_gltf(read_text(path("out.glb")));
    ASSERT_EQ(m.animations.size(), 1u);
    EXPECT_EQ(m.animations[0].channels.size(), m.nodes.size() - 1);  // a translation per particle
}

}  // namespace
}  // namespace tessera_cli_test
