// geometry/animated_scene.hpp — an animation (tessera/animation.hpp) made ready for the
// animated scene writers (USD: write_usda_animated.cpp; glTF: write_gltf_animation.cpp),
// docs/format.md, "Animations (frames)". Every element is drawn one of three ways:
// - instance: posed like in a still scene (a rigid type's mesh fitted to the samples, a
//   default sphere), one pose per frame: the USD PointInstancer, a glTF node per element;
// - curve: a thread without a rigid mesh, a polyline through its samples in sample-id
//   order: a USD BasisCurves curve, a glTF line strip;
// - grid: a sheet without a rigid mesh, the quads of its sample grid: a USD Mesh, glTF
//   triangles.
// Curves and grids move with the samples themselves (every frame's points). Private to
// the library.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "tessera/animation.hpp"
#include "tessera/geometry.hpp"

namespace tessera::geometry {

enum class AnimatedShape { instance, curve, grid };

struct AnimatedScene {
    const Animation* animation = nullptr;
    std::vector<AnimatedShape> shape;  // per element of animation->structure
    // The instanced elements (indices into the elements, in order) and, per frame, the
    // scene of just those: frames[f].instances[k] is element instanced[k] at frame f.
    // Empty when no element is instanced.
    std::vector<int> instanced;
    std::vector<Scene> frames;
    std::vector<double> curve_radius;  // per element: a curve's radius (the static scene's tube), else 0
    int sheet_columns(int element) const;
};

// Sorts the elements into shapes and poses the instanced ones in every frame: a rigid
// type's reference layout is taken from frame 0 (so later frames turn against it), and
// each element's orientations are made continuous (q and -q are the same rotation; the
// one closer to the previous frame's is kept, so interpolation takes the short way).
// Throws Error(input) naming the type for elements that are none of the three shapes
// (deformed meshes, tubes of elements without a thread or sheet topology).
AnimatedScene build_animated_scene(const Animation& animation, const GeometryOptions& options);

// The quads of a sheet of `rows` x `columns` samples (sample id = row x columns + column),
// all wound the same way: (r, c), (r, c + 1), (r + 1, c + 1), (r + 1, c), counterclockwise
// seen from +z when rows go along +y and columns along +x.
std::vector<std::array<int, 4>> grid_quads(int rows, int columns);

// USD time codes of the frames: timeCodesPerSecond = (frames - 1) / (last time - first time),
// the mean frame rate, and code f = (times[f] - times[0]) x that, which is exactly f when the
// frames are evenly spaced (to 1e-9) and fractional otherwise.
struct TimeCodes {
    double per_second = 24.0;
    std::vector<double> codes;
};
TimeCodes usd_time_codes(const std::vector<double>& times);

// The writers. Error(input) for ids USD cannot hold (to_usda_animated), Error(internal)
// when tinygltf cannot serialise (to_gltf_animated).
std::string to_usda_animated(const AnimatedScene& scene);
std::string to_gltf_animated(const AnimatedScene& scene, bool binary);

}  // namespace tessera::geometry
