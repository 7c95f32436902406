// geometry/gltf_morph.hpp — the glTF pieces of animated scenes (write_gltf_animation.cpp):
// threads and sheets as meshes whose frames are morph targets, the one-hot weights that
// step through them, and the keyframe times. Private to the library.
#pragma once

#include <string>
#include <vector>

#include "geometry/animated_scene.hpp"
#include "geometry/tinygltf.hpp"

namespace tessera::geometry::gltf {

// A float VEC3 accessor over `xyz` (3 floats a point) with min and max, which glTF asks of
// every POSITION accessor, morph targets' included.
int add_points(tinygltf::Model& model, const std::vector<float>& xyz, int target);

// The mesh of element `element`, drawn as its shape says (a curve: one LINE_STRIP through
// the samples in sample-id order; a grid: TRIANGLES, two per quad of grid_quads): POSITION
// = frame 0, and one morph target per frame holding that frame's displacement from frame 0,
// so that base + target f is frame f. The targets are named "frame 0", "frame 1", ... in
// the mesh's extras.targetNames, the names Blender's importer gives the shape keys.
int add_morph_mesh(tinygltf::Model& model, const AnimatedScene& scene, int element, const std::string& name);

// The output of every weights sampler: for keyframe f, weight 1 on target f and 0 on the
// others (frames x frames floats), shared by all the morphed meshes.
int add_one_hot_weights(tinygltf::Model& model, int frames);

// The keyframe times in seconds, a float SCALAR accessor with min and max: the animation's
// time stamps, moved to start at 0 when the first is negative (glTF times are >= 0).
int add_keyframe_times(tinygltf::Model& model, const std::vector<double>& times);

}  // namespace tessera::geometry::gltf
