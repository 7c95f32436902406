// apps/tessera/animation_files.cpp — animations as the commands write them (animation_files.hpp).
#include "animation_files.hpp"

#include "common.hpp"
#include "tessera/animation_io.hpp"
#include "tessera/animation_render.hpp"
#include "tessera/io.hpp"

namespace tessera_cli {

void write_animation_picture(const tessera::Animation& animation, const std::string& path) {
    tessera::AnimationRenderOptions options;
    options.trail = kAnimationTrail;
    tessera::write_file_atomic(path, tessera::render_animation_png(animation, options));
}

void write_animation_file(const tessera::Animation& animation, const std::string& path) {
    if (extension_of(path) == ".png")
        write_animation_picture(animation, path);
    else
        tessera::save_animation(animation, path);
}

}  // namespace tessera_cli
