// geometry/write_gltf_animation.cpp — an animation as glTF 2.0 with one animation, "tessera"
// (docs/format.md, "Animations (frames)"). One node per element, in element order, named
// type_id, under the same z-up root node as still scenes (write_gltf.cpp):
// - instanced elements (particles, rigid meshes) share their type's mesh and carry their
//   frame-0 pose; a `translation` channel moves them, and a `rotation` channel turns the
//   elements whose orientation changes. EXT_mesh_gpu_instancing has no animation, so
//   GltfInstancing does not apply here;
// - threads and sheets are meshes of their own whose frames are morph targets
//   (gltf_morph.hpp), stepped through by a `weights` channel.
// Every sampler's input is the one accessor of keyframe times (the frames' time stamps in
// seconds) and its interpolation LINEAR. For the weights, LINEAR with one-hot keyframes
// (1 on target f at frame f) gives between frames f and f + 1 the blend (1 - a) target f +
// a target f + 1, which is exactly the straight-line motion of every sample, as the
// translation channels move the particles; STEP would make threads and sheets jump while
// particles glide. At most two weights are non-zero at any time, which also suits viewers
// that apply only a few morph targets at once.
#include <cmath>
#include <numeric>
#include <sstream>

#include "geometry/geometry_internal.hpp"
#include "geometry/gltf_model.hpp"
#include "geometry/gltf_morph.hpp"
#include "tessera/error.hpp"
#include "tessera/version.hpp"

namespace tessera::geometry {

namespace {

// The animation under construction and the accessors its samplers share.
struct Channels {
    tinygltf::Animation animation;
    int times = -1;    // keyframe times
    int weights = -1;  // one-hot weights, made on first need

    void add(int node, const std::string& path, int output) {
        tinygltf::AnimationSampler sampler;
        sampler.input = times;
        sampler.output = output;
        sampler.interpolation = "LINEAR";
        animation.samplers.push_back(sampler);
        tinygltf::AnimationChannel channel;
        channel.sampler = static_cast<int>(animation.samplers.size()) - 1;
        channel.target_node = node;
        channel.target_path = path;
        animation.channels.push_back(channel);
    }
};

std::string node_name(const Exemplar& data, int element) {
    const Element& el = data.elements[element];
    return data.types[el.type].name + "_" + std::to_string(el.id);
}

// Instanced element k (AnimatedScene::instanced[k]): its node at the frame-0 pose, and its
// translation (and rotation) keyframes.
tinygltf::Node instance_node(tinygltf::Model& model, const AnimatedScene& scene, size_t k,
                             const std::vector<int>& shared, Channels& channels) {
    const SceneInstance& first = scene.frames[0].instances[k];
    tinygltf::Node node;
    node.name = node_name(scene.animation->structure, scene.instanced[k]);
    node.mesh = shared.at(static_cast<size_t>(first.mesh));
    node.translation = {first.position.x, first.position.y, first.position.z};
    node.rotation = {first.orientation.x, first.orientation.y, first.orientation.z, first.orientation.w};
    node.scale = {first.scale, first.scale, first.scale};
    std::vector<float> translation, rotation;
    bool turns = false;
    for (const Scene& frame : scene.frames) {
        const SceneInstance& inst = frame.instances[k];
        const Vec3& p = inst.position;
        const Quat& q = inst.orientation;
        translation.insert(translation.end(), {float(p.x), float(p.y), float(p.z)});
        rotation.insert(rotation.end(), {float(q.x), float(q.y), float(q.z), float(q.w)});
        turns = turns || q.w != first.orientation.w || q.x != first.orientation.x || q.y != first.orientation.y ||
                q.z != first.orientation.z;
    }
    const int index = static_cast<int>(model.nodes.size());
    channels.add(index, "translation", gltf::add_floats(model, translation, TINYGLTF_TYPE_VEC3, 0));
    if (turns) channels.add(index, "rotation", gltf::add_floats(model, rotation, TINYGLTF_TYPE_VEC4, 0));
    return node;
}

// A thread or sheet: its morphed mesh under an untransformed node, and its weights channel.
tinygltf::Node morph_node(tinygltf::Model& model, const AnimatedScene& scene, int element, Channels& channels) {
    tinygltf::Node node;
    node.name = node_name(scene.animation->structure, element);
    node.mesh = gltf::add_morph_mesh(model, scene, element, node.name);
    if (channels.weights < 0) channels.weights = gltf::add_one_hot_weights(model, scene.animation->frame_count());
    channels.add(static_cast<int>(model.nodes.size()), "weights", channels.weights);
    return node;
}


}  // namespace

std::string to_gltf_animated(const AnimatedScene& scene, bool binary) {
    const Exemplar& data = scene.animation->structure;
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = std::string("tessera ") + version;
    model.buffers.resize(1);
    for (size_t t = 0; t < data.types.size(); ++t)
        model.materials.push_back(gltf::material(data.types[t].name, static_cast<int>(t)));
    const std::vector<int> shared = scene.frames.empty() ? std::vector<int>{}
                                                         : gltf::add_shared_meshes(model, scene.frames[0]);
    Channels channels;
    channels.animation.name = "tessera";
    channels.times = gltf::add_keyframe_times(model, scene.animation->times);
    size_t k = 0;  // the next instanced element
    for (int e = 0; e < static_cast<int>(data.elements.size()); ++e)
        model.nodes.push_back(scene.shape[e] == AnimatedShape::instance
                                  ? instance_node(model, scene, k++, shared, channels)
                                  : morph_node(model, scene, e, channels));
    model.animations.push_back(channels.animation);
    gltf::add_root(model);

    std::ostringstream out;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, /*prettyPrint=*/!binary, /*writeBinary=*/binary))
        throw Error(ErrorKind::internal, "tinygltf could not serialise the animation");
    return out.str();
}

}  // namespace tessera::geometry
