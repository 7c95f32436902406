// render/animation_render.cpp — animated previews: each frame drawn by render_png with the
// recent path of every particle behind it, the frames assembled into an APNG (apng.hpp).
#include "tessera/animation_render.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "render/apng.hpp"
#include "tessera/error.hpp"
#include "tessera/metrics.hpp"

namespace tessera {

namespace {

std::string hex(Color c) {
    char text[8];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", c.r, c.g, c.b);
    return text;
}

// Halfway to white: a path reads as the faint wake of its element.
Color lighter(Color c) {
    const auto mix = [](std::uint8_t v) { return static_cast<std::uint8_t>(v + (255 - v) / 2); };
    return {mix(c.r), mix(c.g), mix(c.b)};
}

// Elements drawn as a glyph (a fish) head where they move: their orientation is turned to
// the motion from the frame before to the frame after (one-sided at the ends, and where the
// element wrapped across the domain); an element at rest keeps its own.
void turn_glyphs_to_motion(const Animation& a, int frame, Exemplar& out) {
    const int last = a.frame_count() - 1;
    const Vec3 extent = out.domain.bounds().size();
    const double jump2 = 0.25 * std::min(extent.x * extent.x, extent.y * extent.y);
    for (size_t e = 0; e < a.structure.elements.size(); ++e) {
        Element& el = out.elements[e];
        if (el.sample_count != 1 || out.types[el.type].glyph == ElementGlyph::disk) continue;
        const Vec3 here = a.at(frame, el.first_sample);
        Vec3 before = a.at(std::max(0, frame - 1), el.first_sample), after = a.at(std::min(last, frame + 1), el.first_sample);
        if (squared_norm(after - here) > jump2) after = here;
        if (squared_norm(here - before) > jump2) before = here;
        const Vec3 v = after - before;
        if (std::hypot(v.x, v.y) < 1e-12) continue;
        el.orientation = Quat::from_angle_z(std::atan2(v.y, v.x));
    }
}

// Frame `frame` with a path element of `length` samples (frames frame - length + 1 .. frame)
// for every single-sample element; frames before the first repeat it, so that every frame of
// an animation has the same types (and legend). A jump longer than half the domain (an
// element wrapped across it) cuts the path: the samples before it repeat the first after it.
Exemplar frame_with_paths(const Animation& a, int frame, int length) {
    Exemplar out = a.frame(frame);
    if (out.dimension != 2) return out;
    turn_glyphs_to_motion(a, frame, out);
    if (length < 2) return out;
    const std::vector<Color> colors = type_colors(out);
    const size_t types = out.types.size();
    std::vector<int> path_type(types, -1);
    const Vec3 extent = out.domain.bounds().size();
    const double jump2 = 0.25 * std::min(extent.x * extent.x, extent.y * extent.y);
    for (size_t e = 0; e < a.structure.elements.size(); ++e) {
        const Element& el = a.structure.elements[e];
        if (el.sample_count != 1) continue;
        if (path_type[el.type] < 0) {
            ElementType t;
            t.name = out.types[el.type].name + " path";
            t.color = hex(lighter(colors[el.type]));
            path_type[el.type] = static_cast<int>(out.types.size());
            out.types.push_back(t);
        }
        std::vector<Vec3> path(length);
        int cut = 0;
        for (int k = 0; k < length; ++k) {
            path[k] = a.at(std::max(0, frame - length + 1 + k), el.first_sample);
            if (k > 0 && squared_norm(path[k] - path[k - 1]) > jump2) cut = k;
        }
        for (int k = 0; k < cut; ++k) path[k] = path[cut];
        out.add_element(path_type[el.type], path);
    }
    // Paths first, so that the elements are drawn over them.
    std::stable_partition(out.elements.begin(), out.elements.end(),
                          [&](const Element& e) { return e.type >= static_cast<int>(types); });
    for (size_t e = 0; e < out.elements.size(); ++e)
        for (int k = 0; k < out.elements[e].sample_count; ++k)
            out.samples[out.elements[e].first_sample + k].element = static_cast<int>(e);
    return out;
}

// The pictures of an animation show one view: the domain grown to every sample of every frame.
RenderOptions path_picture(const Animation& a, const AnimationRenderOptions& options) {
    RenderOptions r = options.picture;
    r.show_samples = false;
    if (!(r.spacing > 0.0) && a.structure.elements.size() >= 2) r.spacing = nearest_neighbor_distances(a.frame(0)).mean;
    if (!r.view) {
        Box view = a.structure.domain.bounds();
        for (const Vec3& p : a.positions)
            for (int k = 0; k < a.structure.dimension; ++k)
                view.lo[k] = std::min(view.lo[k], p[k]), view.hi[k] = std::max(view.hi[k], p[k]);
        r.view = view;
    }
    return r;
}

void check(const AnimationRenderOptions& options) {
    if (options.fps < 0.0 || !std::isfinite(options.fps))
        throw Error(ErrorKind::option, "fps must be a number >= 0, got " + std::to_string(options.fps));
    if (options.trail < 0) throw Error(ErrorKind::option, "trail must be >= 0, got " + std::to_string(options.trail));
    if (options.max_frames < 0)
        throw Error(ErrorKind::option, "max_frames must be >= 0, got " + std::to_string(options.max_frames));
    check_render_options(options.picture);
}

}  // namespace

std::string render_animation_png(const Animation& animation, const AnimationRenderOptions& options) {
    check(options);
    const int frames = animation.frame_count();
    const int step = options.max_frames > 0 ? std::max(1, (frames + options.max_frames - 1) / options.max_frames) : 1;
    double fps = options.fps;
    if (fps == 0.0) {
        const double dt = frames > 1 ? (animation.times.back() - animation.times.front()) / (frames - 1) : 1.0;
        fps = std::clamp(1.0 / dt, 1.0, 50.0);
    }
    std::vector<std::string> pictures;
    const RenderOptions picture = path_picture(animation, options);
    for (int f = 0; f < frames; f += step)
        pictures.push_back(render_png(frame_with_paths(animation, f, options.trail), picture));
    return render::assemble_apng(pictures, step / fps);
}

std::string render_trails_png(const Animation& animation, int frame, const AnimationRenderOptions& options) {
    check(options);
    const int frames = animation.frame_count();
    if (frame < 0) frame += frames;
    if (frame < 0 || frame >= frames)
        throw Error(ErrorKind::option, "frame must be within the animation's " + std::to_string(frames) + " frames");
    const int length = options.trail > 0 ? options.trail : frame + 1;
    return render_png(frame_with_paths(animation, frame, length), path_picture(animation, options));
}

}  // namespace tessera
