// geometry/animated_scene.cpp — build_animated_scene (animated_scene.hpp): which element is
// drawn how, the poses of the instanced ones in every frame, the radii of the curves; and
// the small pieces both animated writers share (grid quads, USD time codes).
#include "geometry/animated_scene.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/geometry_internal.hpp"
#include "tessera/det.hpp"
#include "tessera/error.hpp"

namespace tessera::geometry {

namespace {

// A rigid type with a mesh keeps its mesh, whatever its topology: its elements are copies
// of one shape, so posing the mesh shows them as authored. Otherwise the topology decides.
AnimatedShape shape_of_type(const Exemplar& data, int type) {
    const ElementType& t = data.types[type];
    if (!t.mesh.empty() && t.rigid) return AnimatedShape::instance;
    switch (effective_topology(data, type)) {
        case ElementTopology::thread:
            return AnimatedShape::curve;
        case ElementTopology::sheet:
            return AnimatedShape::grid;
        default:
            return AnimatedShape::instance;
    }
}

// Frame f of just the given elements (types, attributes and domain kept, so that type
// indices, names and colours are those of the whole animation).
Exemplar frame_of(const Animation& a, const std::vector<int>& elements, int f) {
    const Exemplar& all = a.structure;
    Exemplar out;
    out.dimension = all.dimension;
    out.types = all.types;
    out.attribute_names = all.attribute_names;
    out.domain = all.domain;
    for (const int e : elements) {
        Element el = all.elements[e];
        el.first_sample = static_cast<int>(out.samples.size());
        el.position = {};
        for (int k = 0; k < el.sample_count; ++k) {
            Sample s = all.samples[all.elements[e].first_sample + k];
            s.p = a.at(f, all.elements[e].first_sample + k);
            s.time = a.times[f];
            s.element = static_cast<int>(out.elements.size());
            el.position += s.p / el.sample_count;
            out.samples.push_back(s);
        }
        out.elements.push_back(el);
    }
    return out;
}

// A rigid type's reference layout, when the file gives none, is derived from the type's
// first element in the data: in frame f that would be frame f's samples, and the element
// would never turn. Frame 0's layout, fixed, makes the later frames turn against it.
void fix_references(Exemplar& frame0, const GeometryOptions& options) {
    const std::vector<TypeGeometry> geometry = type_geometry(frame0, options);
    for (size_t t = 0; t < frame0.types.size(); ++t)
        if (geometry[t].has_mesh && frame0.types[t].reference.empty()) frame0.types[t].reference = geometry[t].reference;
}

void check_instanced(const Scene& scene, const Exemplar& data) {
    for (const SceneInstance& inst : scene.instances)
        if (!inst.instanced)
            throw Error(ErrorKind::input, "type '" + data.types.at(static_cast<size_t>(inst.type)).name +
                                              "' is neither posed as a whole (a rigid mesh, one sample) nor a thread "
                                              "or a sheet, so its frames have no scene form; write them as .json or .csv");
}

// q and -q are the same rotation; interpolating from one to the other would spin the long way.
void make_orientations_continuous(std::vector<Scene>& frames) {
    for (size_t f = 1; f < frames.size(); ++f)
        for (size_t k = 0; k < frames[f].instances.size(); ++k) {
            const Quat& p = frames[f - 1].instances[k].orientation;
            Quat& q = frames[f].instances[k].orientation;
            if (p.w * q.w + p.x * q.x + p.y * q.y + p.z * q.z < 0.0) q = {-q.w, -q.x, -q.y, -q.z};
        }
}

std::vector<Scene> instance_frames(const Animation& a, const std::vector<int>& elements,
                                   const GeometryOptions& options) {
    Exemplar frame0 = frame_of(a, elements, 0);
    fix_references(frame0, options);
    std::vector<Scene> frames;
    for (int f = 0; f < a.frame_count(); ++f) {
        Exemplar frame = f == 0 ? frame0 : frame_of(a, elements, f);
        frame.types = frame0.types;
        frames.push_back(build_scene(frame, options));
        if (f == 0) check_instanced(frames[0], frame);
    }
    make_orientations_continuous(frames);
    return frames;
}

// The static scene's tube radius: the element's radius, else 0.2 x the spacing (the mean
// nearest-neighbour distance of the centroids at frame 0, else the mean distance between
// consecutive samples, else 1).
std::vector<double> curve_radii(const Animation& a, const std::vector<AnimatedShape>& shape) {
    const Exemplar& data = a.structure;
    std::vector<double> radius(data.elements.size(), 0.0);
    double spacing = -1.0;
    for (size_t e = 0; e < data.elements.size(); ++e) {
        if (shape[e] != AnimatedShape::curve) continue;
        radius[e] = data.elements[e].radius;
        if (radius[e] > 0.0) continue;
        if (spacing < 0.0) spacing = mean_nearest_neighbor_distance(a.frame(0));
        if (!(spacing > 0.0)) {
            double sum = 0.0;
            int gaps = 0;
            for (const Element& el : data.elements)
                for (int k = 0; k + 1 < el.sample_count; ++k, ++gaps)
                    sum += norm(a.at(0, el.first_sample + k + 1) - a.at(0, el.first_sample + k));
            spacing = sum > 0.0 ? sum / gaps : 1.0;
        }
        radius[e] = 0.2 * spacing;
    }
    return radius;
}

}  // namespace

int AnimatedScene::sheet_columns(int element) const {
    const Exemplar& data = animation->structure;
    return data.types.at(static_cast<size_t>(data.elements.at(static_cast<size_t>(element)).type)).sheet_columns;
}

AnimatedScene build_animated_scene(const Animation& animation, const GeometryOptions& options) {
    const Exemplar& data = animation.structure;
    AnimatedScene out;
    out.animation = &animation;
    std::vector<AnimatedShape> by_type;
    for (int t = 0; t < static_cast<int>(data.types.size()); ++t) by_type.push_back(shape_of_type(data, t));
    for (int e = 0; e < static_cast<int>(data.elements.size()); ++e) {
        out.shape.push_back(by_type.at(static_cast<size_t>(data.elements[e].type)));
        if (out.shape.back() == AnimatedShape::instance) out.instanced.push_back(e);
    }
    out.curve_radius = curve_radii(animation, out.shape);
    if (!out.instanced.empty()) out.frames = instance_frames(animation, out.instanced, options);
    return out;
}

std::vector<std::array<int, 4>> grid_quads(int rows, int columns) {
    std::vector<std::array<int, 4>> quads;
    for (int r = 0; r + 1 < rows; ++r)
        for (int c = 0; c + 1 < columns; ++c) {
            const int a = r * columns + c;
            quads.push_back({a, a + 1, a + columns + 1, a + columns});
        }
    return quads;
}

TimeCodes usd_time_codes(const std::vector<double>& times) {
    TimeCodes out;
    const size_t n = times.size();
    if (n > 1) out.per_second = static_cast<double>(n - 1) / (times.back() - times.front());
    for (const double t : times) {
        const double code = (t - times.front()) * out.per_second;
        out.codes.push_back(std::abs(code - std::round(code)) <= 1e-9 * std::max(1.0, code) ? std::round(code) : code);
    }
    return out;
}

}  // namespace tessera::geometry
