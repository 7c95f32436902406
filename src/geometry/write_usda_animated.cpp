// geometry/write_usda_animated.cpp — an animation as one USD text layer (docs/format.md,
// "Animations (frames)"). Each kind of element under a prim of its own below /World:
// - /World/Elements, the PointInstancer of the instanced elements (write_usda.cpp), whose
//   positions and orientations are time samples;
// - /World/Threads/<type>, a BasisCurves per thread type: type "linear" (the samples are
//   the curve, no smoothing that would leave them), one curve per element, widths the
//   diameter of the still scene's tube;
// - /World/Sheets/<type>, a Mesh per sheet type: the quads of every element's sample grid.
// Curves and meshes carry their points (and extent, so that culling follows the motion) as
// time samples, one per frame; the per-curve / per-face primvar tessera:id names the element.
#include <algorithm>
#include <string>
#include <vector>

#include "geometry/animated_scene.hpp"
#include "geometry/geometry_internal.hpp"
#include "geometry/usda_text.hpp"
#include "render/palette.hpp"
#include "tessera/version.hpp"

namespace tessera::geometry {

namespace {

using usda::list;
using usda::pad;
using usda::quoted;
using usda::real;
using usda::tuple;

// The elements of `type` drawn as `shape`, in element order.
std::vector<int> elements_of(const AnimatedScene& scene, int type, AnimatedShape shape) {
    std::vector<int> out;
    const std::vector<Element>& elements = scene.animation->structure.elements;
    for (int e = 0; e < static_cast<int>(elements.size()); ++e)
        if (elements[e].type == type && scene.shape[e] == shape) out.push_back(e);
    return out;
}

// Per frame: the points of `elements` (element after element, samples in sample-id order)
// and their extent grown by `margin` (a curve's half width), as USD array texts.
struct SampledPoints {
    std::vector<std::string> points, extents;
};

SampledPoints sampled_points(const Animation& a, const std::vector<int>& elements, const std::vector<double>& margin) {
    SampledPoints out;
    for (int f = 0; f < a.frame_count(); ++f) {
        std::vector<std::string> points;
        Vec3 lo = a.at(f, a.structure.elements[elements[0]].first_sample), hi = lo;
        for (size_t i = 0; i < elements.size(); ++i) {
            const Element& el = a.structure.elements[elements[i]];
            for (int k = 0; k < el.sample_count; ++k) {
                const Vec3& p = a.at(f, el.first_sample + k);
                for (int c = 0; c < 3; ++c)
                    lo[c] = std::min(lo[c], p[c] - margin[i]), hi[c] = std::max(hi[c], p[c] + margin[i]);
                points.push_back(tuple(p));
            }
        }
        out.points.push_back(list(points));
        out.extents.push_back("[" + tuple(lo) + ", " + tuple(hi) + "]");
    }
    return out;
}

// The lines every curve and grid prim ends with: colour, element ids, class name.
std::string common_lines(const Exemplar& data, int type, const std::vector<std::string>& ids, int depth) {
    const render::Rgb c = render::class_color(type);
    std::string out = pad(depth) + "color3f[] primvars:displayColor = [(" + real(c.r) + ", " + real(c.g) + ", " +
                      real(c.b) + ")] (interpolation = \"constant\")\n";
    out += pad(depth) + "int64[] primvars:tessera:id = " + list(ids) + " (interpolation = \"uniform\")\n";
    return out + pad(depth) + "custom string tessera:className = " + quoted(data.types[type].name) + "\n";
}

std::string curves_prim(const AnimatedScene& scene, int type, const std::string& name,
                        const std::vector<double>& codes) {
    const Animation& a = *scene.animation;
    const std::vector<int> elements = elements_of(scene, type, AnimatedShape::curve);
    std::vector<std::string> counts, widths, ids;
    std::vector<double> half_width;
    for (const int e : elements) {
        const Element& el = a.structure.elements[e];
        counts.push_back(std::to_string(el.sample_count));
        widths.insert(widths.end(), static_cast<size_t>(el.sample_count), real(2.0 * scene.curve_radius[e]));
        half_width.push_back(scene.curve_radius[e]);
        ids.push_back(usda::int64_id(el.id));
    }
    const SampledPoints p = sampled_points(a, elements, half_width);
    const std::string in = pad(3);
    std::string out = pad(2) + "def BasisCurves " + quoted(name) + "\n" + pad(2) + "{\n";
    out += in + "int[] curveVertexCounts = " + list(counts) + "\n";
    out += usda::sampled("float3[] extent", p.extents, codes, 3);
    out += usda::sampled("point3f[] points", p.points, codes, 3);
    out += in + "uniform token type = \"linear\"\n";
    out += in + "float[] widths = " + list(widths) + " (interpolation = \"vertex\")\n";
    out += in + "uniform token wrap = \"nonperiodic\"\n";
    return out + common_lines(a.structure, type, ids, 3) + pad(2) + "}\n";
}

std::string grid_prim(const AnimatedScene& scene, int type, const std::string& name,
                      const std::vector<double>& codes) {
    const Animation& a = *scene.animation;
    const std::vector<int> elements = elements_of(scene, type, AnimatedShape::grid);
    std::vector<std::string> counts, indices, ids;
    int offset = 0;
    for (const int e : elements) {
        const Element& el = a.structure.elements[e];
        const int columns = scene.sheet_columns(e);
        for (const auto& quad : grid_quads(el.sample_count / columns, columns)) {
            counts.push_back("4");
            for (const int v : quad) indices.push_back(std::to_string(offset + v));
            ids.push_back(usda::int64_id(el.id));
        }
        offset += el.sample_count;
    }
    const SampledPoints p = sampled_points(a, elements, std::vector<double>(elements.size(), 0.0));
    const std::string in = pad(3);
    std::string out = pad(2) + "def Mesh " + quoted(name) + "\n" + pad(2) + "{\n";
    out += in + "uniform bool doubleSided = 1\n";
    out += usda::sampled("float3[] extent", p.extents, codes, 3);
    out += in + "int[] faceVertexCounts = " + list(counts) + "\n";
    out += in + "int[] faceVertexIndices = " + list(indices) + "\n";
    out += usda::sampled("point3f[] points", p.points, codes, 3);
    out += in + "uniform token subdivisionScheme = \"none\"\n";
    return out + common_lines(a.structure, type, ids, 3) + pad(2) + "}\n";
}

// An Xform `group` holding one prim per type drawn as `shape`; "" when there is none.
std::string shape_group(const AnimatedScene& scene, AnimatedShape shape, const std::string& group,
                        const std::vector<double>& codes) {
    const Exemplar& data = scene.animation->structure;
    usda::NameTable names;
    std::string prims;
    for (int t = 0; t < static_cast<int>(data.types.size()); ++t) {
        if (elements_of(scene, t, shape).empty()) continue;
        const std::string name = names.unique(data.types[t].name);
        prims += shape == AnimatedShape::curve ? curves_prim(scene, t, name, codes) : grid_prim(scene, t, name, codes);
    }
    if (prims.empty()) return "";
    return pad(1) + "def Xform " + quoted(group) + "\n" + pad(1) + "{\n" + prims + pad(1) + "}\n";
}

}  // namespace

std::string to_usda_animated(const AnimatedScene& scene) {
    const Animation& a = *scene.animation;
    const TimeCodes timing = usd_time_codes(a.times);
    std::string out = usda::layer_header(std::string("tessera ") + version + ": " +
                                             std::to_string(a.structure.elements.size()) + " elements, dimension " +
                                             std::to_string(a.structure.dimension) + ", " +
                                             std::to_string(a.frame_count()) + " frames",
                                         timing.codes, timing.per_second);
    std::vector<std::string> parts;
    if (!scene.instanced.empty()) parts.push_back(usda_point_instancer(scene.frames, timing.codes));
    parts.push_back(shape_group(scene, AnimatedShape::curve, "Threads", timing.codes));
    parts.push_back(shape_group(scene, AnimatedShape::grid, "Sheets", timing.codes));
    std::string body;
    for (const std::string& part : parts)
        if (!part.empty()) body += (body.empty() ? "" : "\n") + part;
    return out + "def Xform \"World\"\n{\n" + body + "}\n";
}

}  // namespace tessera::geometry
