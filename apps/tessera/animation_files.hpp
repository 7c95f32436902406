// apps/tessera/animation_files.hpp — animations as the commands write them: an animated PNG
// (each particle's path over its last frames drawn behind it) or, by the extension, what
// tessera::save_animation writes (.json, .csv, .usda, .gltf, .glb).
#pragma once

#include <string>

#include "tessera/animation.hpp"

namespace tessera_cli {

// Frames of path drawn behind each particle in an animated PNG.
constexpr int kAnimationTrail = 6;

// The animation as an animated PNG at `path`, atomically.
void write_animation_picture(const tessera::Animation& animation, const std::string& path);

// The animation at `path`: an animated PNG for .png, else save_animation's format.
void write_animation_file(const tessera::Animation& animation, const std::string& path);

}  // namespace tessera_cli
