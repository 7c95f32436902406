// geometry/gltf_morph.cpp — morph-target meshes, one-hot weights and keyframe times of
// animated glTF scenes (gltf_morph.hpp). Displacements are taken in double from frame 0
// and then rounded, so base + target f is frame f to float precision.
#include "geometry/gltf_morph.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

#include "geometry/gltf_model.hpp"
#include "io/io_util.hpp"
#include "tessera/error.hpp"

namespace tessera::geometry::gltf {

namespace {

// The samples of `element` at frame f, minus `origin` (3 floats a sample).
std::vector<float> sample_floats(const Animation& a, const Element& element, int f, const std::vector<Vec3>& origin) {
    std::vector<float> out;
    for (int k = 0; k < element.sample_count; ++k) {
        const Vec3 p = a.at(f, element.first_sample + k) - origin[static_cast<size_t>(k)];
        out.insert(out.end(), {float(p.x), float(p.y), float(p.z)});
    }
    return out;
}

int add_grid_indices(tinygltf::Model& model, int rows, int columns) {
    std::vector<std::uint32_t> indices;
    for (const auto& q : grid_quads(rows, columns))
        for (const int v : {q[0], q[1], q[2], q[0], q[2], q[3]}) indices.push_back(static_cast<std::uint32_t>(v));
    const int view = add_view(model, indices.data(), indices.size() * sizeof(std::uint32_t),
                              TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    return add_accessor(model, view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, indices.size());
}

}  // namespace

int add_points(tinygltf::Model& model, const std::vector<float>& xyz, int target) {
    const int accessor = add_floats(model, xyz, TINYGLTF_TYPE_VEC3, target);
    std::vector<double> lo(3, std::numeric_limits<double>::infinity()), hi(3, -lo[0]);
    for (size_t k = 0; k < xyz.size(); ++k) {
        lo[k % 3] = std::min(lo[k % 3], double(xyz[k]));
        hi[k % 3] = std::max(hi[k % 3], double(xyz[k]));
    }
    model.accessors[accessor].minValues = lo;
    model.accessors[accessor].maxValues = hi;
    return accessor;
}

int add_morph_mesh(tinygltf::Model& model, const AnimatedScene& scene, int element, const std::string& name) {
    const Animation& a = *scene.animation;
    const Element& el = a.structure.elements.at(static_cast<size_t>(element));
    const std::vector<Vec3> zero(static_cast<size_t>(el.sample_count));
    std::vector<Vec3> base;
    for (int k = 0; k < el.sample_count; ++k) base.push_back(a.at(0, el.first_sample + k));

    tinygltf::Primitive primitive;
    primitive.material = el.type;
    primitive.attributes["POSITION"] = add_points(model, sample_floats(a, el, 0, zero), TINYGLTF_TARGET_ARRAY_BUFFER);
    if (scene.shape.at(static_cast<size_t>(element)) == AnimatedShape::grid) {
        const int columns = scene.sheet_columns(element);
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        primitive.indices = add_grid_indices(model, el.sample_count / columns, columns);
    } else {
        primitive.mode = TINYGLTF_MODE_LINE_STRIP;
    }
    tinygltf::Value::Array target_names;
    for (int f = 0; f < a.frame_count(); ++f) {
        primitive.targets.push_back(
            {{"POSITION", add_points(model, sample_floats(a, el, f, base), TINYGLTF_TARGET_ARRAY_BUFFER)}});
        target_names.emplace_back("frame " + std::to_string(f));
    }
    tinygltf::Mesh mesh;
    mesh.name = name;
    mesh.primitives.push_back(primitive);
    mesh.extras = tinygltf::Value(tinygltf::Value::Object{{"targetNames", tinygltf::Value(target_names)}});
    model.meshes.push_back(mesh);
    return static_cast<int>(model.meshes.size()) - 1;
}

int add_one_hot_weights(tinygltf::Model& model, int frames) {
    std::vector<float> weights(static_cast<size_t>(frames) * static_cast<size_t>(frames), 0.0f);
    for (int f = 0; f < frames; ++f) weights[static_cast<size_t>(f) * static_cast<size_t>(frames) + f] = 1.0f;
    return add_floats(model, weights, TINYGLTF_TYPE_SCALAR, 0);
}

int add_keyframe_times(tinygltf::Model& model, const std::vector<double>& times) {
    const double shift = std::min(0.0, times.front());
    std::vector<float> seconds;
    for (const double t : times) {
        seconds.push_back(float(t - shift));
        if (seconds.size() > 1 && !(seconds.back() > seconds[seconds.size() - 2]))
            throw Error(ErrorKind::input, "time stamps " + io_detail::format_number(times[seconds.size() - 2]) +
                                              " and " + io_detail::format_number(t) +
                                              " are the same in glTF's float seconds");
    }
    const int accessor = add_floats(model, seconds, TINYGLTF_TYPE_SCALAR, 0);
    model.accessors[accessor].minValues = {double(seconds.front())};
    model.accessors[accessor].maxValues = {double(seconds.back())};
    return accessor;
}

}  // namespace tessera::geometry::gltf
