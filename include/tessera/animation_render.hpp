// tessera/animation_render.hpp — pictures of an animation (tessera/animation.hpp):
//   an animated PNG (APNG: every browser and most image viewers play it; a viewer without
//   APNG support shows the first frame), one frame per animation frame, each drawn as
//   render_png draws a static arrangement, with each sample's recent path drawn behind it;
//   a "trails" picture: one frame with the paths of the frames before it, the motion of a
//   whole clip in one still image.
#pragma once

#include <string>

#include "tessera/animation.hpp"
#include "tessera/render.hpp"

namespace tessera {

struct AnimationRenderOptions {
    RenderOptions picture;   // each frame's picture (width, domain outline, legend)
    // Frames per second of the APNG; 0 = from the time stamps (between 1 and 50).
    double fps = 0.0;
    // Frames of path drawn behind each sample of a single-sample element (0 = none).
    int trail = 0;
    // At most this many frames in the APNG (every k-th frame is kept, evenly); 0 = all.
    int max_frames = 0;
};

// APNG bytes. Throws what render_png throws, Error(option) for a negative option.
std::string render_animation_png(const Animation& animation, const AnimationRenderOptions& options = {});

// One still picture (PNG bytes): frame `frame` (negative = from the end: -1 is the last)
// with the path of every single-sample element over the `options.trail` frames before it
// (all frames when trail is 0).
std::string render_trails_png(const Animation& animation, int frame, const AnimationRenderOptions& options = {});

}  // namespace tessera
