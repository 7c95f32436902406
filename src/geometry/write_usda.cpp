// geometry/write_usda.cpp — the scene as a USD text layer (.usda), for USD tools (usdview,
// Houdini Solaris, Omniverse, Blender). USD's own conventions are followed where it has
// them (docs/format.md, "USD"):
// - the stage says upAxis "Z" and metersPerUnit 1 rather than converting coordinates;
// - every instanced element (a rigid type's mesh, a default sphere) is one entry of a
//   UsdGeomPointInstancer, /World/Elements, with positions, orientations (quath, written
//   (w, x, y, z) as USD's text form of a quaternion is real part first; also quatf
//   orientationsf, which newer readers prefer for its precision), scales, protoIndices,
//   ids (the element ids) and per-instance primvars (class index, id, free attributes);
// - the prototypes, one Mesh per shared mesh named after its type, sit under the
//   instancer in an `over "Prototypes"`, the arrangement UsdGeomPointInstancer's
//   documentation recommends: renderers draw them only through the instancer, and
//   generic traversals skip them;
// - elements that cannot be instanced (deformed meshes, tubes) are Mesh prims of their
//   own in world coordinates under /World/Meshes, named type_id.
// An animation's layer (write_usda_animated.cpp) reuses the instancer with time samples.
#include <algorithm>

#include "geometry/geometry_internal.hpp"
#include "geometry/usda_text.hpp"
#include "io/io_util.hpp"
#include "render/palette.hpp"
#include "tessera/error.hpp"
#include "tessera/version.hpp"

namespace tessera::geometry {

namespace {

using usda::list;
using usda::pad;
using usda::quoted;
using usda::real;
using usda::tuple;

// One prototype: a shared scene mesh, the type it belongs to and its prim name.
struct Prototype {
    int mesh = 0;
    int type = 0;
    std::string name;
};

// A Mesh prim: triangles, smooth vertex normals, the type's preview colour, no
// subdivision (USD's default scheme would round the triangles off), and the class name.
std::string mesh_prim(const TriangleMesh& mesh, const std::string& name, int type,
                      const std::string& class_name, const std::string& extra, int depth) {
    const std::string in = pad(depth + 1);
    Vec3 lo = mesh.vertices.empty() ? Vec3{} : mesh.vertices[0], hi = lo;
    std::vector<std::string> points, normals, counts, indices;
    for (const Vec3& v : mesh.vertices) {
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
        points.push_back(tuple(v));
    }
    for (const Vec3& n : vertex_normals(mesh)) normals.push_back(tuple(n));
    for (const auto& t : mesh.triangles) {
        counts.push_back("3");
        for (int k = 0; k < 3; ++k) indices.push_back(std::to_string(t[k]));
    }
    const render::Rgb c = render::class_color(type);
    std::string out = pad(depth) + "def Mesh " + quoted(name) + "\n" + pad(depth) + "{\n";
    out += in + "uniform bool doubleSided = 1\n";
    out += in + "float3[] extent = [" + tuple(lo) + ", " + tuple(hi) + "]\n";
    out += in + "int[] faceVertexCounts = " + list(counts) + "\n";
    out += in + "int[] faceVertexIndices = " + list(indices) + "\n";
    out += in + "normal3f[] normals = " + list(normals) + " (interpolation = \"vertex\")\n";
    out += in + "point3f[] points = " + list(points) + "\n";
    out += in + "color3f[] primvars:displayColor = [(" + real(c.r) + ", " + real(c.g) + ", " + real(c.b) +
           ")] (interpolation = \"constant\")\n";
    out += in + "uniform token subdivisionScheme = \"none\"\n";
    out += in + "custom string tessera:className = " + quoted(class_name) + "\n";
    out += extra;
    return out + pad(depth) + "}\n";
}

// The shared meshes in order of first use, each named after its type.
std::vector<Prototype> prototypes_of(const Scene& scene) {
    std::vector<Prototype> out;
    std::vector<int> seen(scene.meshes.size(), 0);
    usda::NameTable names;
    for (const SceneInstance& inst : scene.instances)
        if (inst.instanced && !seen.at(static_cast<size_t>(inst.mesh))) {
            seen[inst.mesh] = 1;
            out.push_back({inst.mesh, inst.type, names.unique(scene.type_names.at(inst.type))});
        }
    return out;
}

// The instances' poses of one scene as USD array texts: positions, orientations (quath and
// quatf share the text).
struct InstancePoses {
    std::vector<std::string> positions, orientations;
};

InstancePoses poses_of(const Scene& scene) {
    InstancePoses p;
    for (const SceneInstance& inst : scene.instances) {
        if (!inst.instanced) continue;
        const Quat& q = inst.orientation;
        p.orientations.push_back("(" + real(q.w) + ", " + real(q.x) + ", " + real(q.y) + ", " + real(q.z) + ")");
        p.positions.push_back(tuple(inst.position));
    }
    return p;
}

std::string point_instancer(const Scene& scene, const std::vector<Prototype>& prototypes,
                            const std::vector<Scene>& frames, const std::vector<double>& codes) {
    std::vector<int> proto_index(scene.meshes.size(), -1);
    for (size_t p = 0; p < prototypes.size(); ++p) proto_index[prototypes[p].mesh] = static_cast<int>(p);
    std::vector<std::string> ids, quath, positions, classes, protos, scales;
    std::vector<std::vector<std::string>> attributes(scene.attribute_names.size());
    for (const SceneInstance& inst : scene.instances) {
        if (!inst.instanced) continue;
        const Quat& q = inst.orientation;
        const std::string wxyz =
            "(" + real(q.w) + ", " + real(q.x) + ", " + real(q.y) + ", " + real(q.z) + ")";
        ids.push_back(usda::int64_id(inst.id));
        quath.push_back(wxyz);
        positions.push_back(tuple(inst.position));
        classes.push_back(std::to_string(inst.type));
        protos.push_back(std::to_string(proto_index.at(static_cast<size_t>(inst.mesh))));
        scales.push_back(tuple({inst.scale, inst.scale, inst.scale}));
        for (size_t a = 0; a < attributes.size(); ++a)
            attributes[a].push_back(io_detail::format_number(inst.attributes.at(a)));
    }
    std::vector<std::string> class_names, targets;
    for (const std::string& name : scene.type_names) class_names.push_back(quoted(name));
    for (const Prototype& p : prototypes) targets.push_back("</World/Elements/Prototypes/" + p.name + ">");

    // An animation's poses: one set per frame (the first scene's when there are no frames).
    std::vector<std::string> frame_positions{list(positions)}, frame_orientations{list(quath)};
    if (frames.size() > 1) {
        frame_positions.clear(), frame_orientations.clear();
        for (const Scene& frame : frames) {
            const InstancePoses p = poses_of(frame);
            frame_positions.push_back(list(p.positions));
            frame_orientations.push_back(list(p.orientations));
        }
    }
    const std::string in = pad(2), per_instance = " (interpolation = \"vertex\")\n";
    std::string out = pad(1) + "def PointInstancer \"Elements\"\n" + pad(1) + "{\n";
    out += in + "int64[] ids = " + list(ids) + "\n";
    out += usda::sampled("quath[] orientations", frame_orientations, codes, 2);
    out += usda::sampled("quatf[] orientationsf", frame_orientations, codes, 2);
    out += usda::sampled("point3f[] positions", frame_positions, codes, 2);
    out += in + "int[] primvars:tessera:class = " + list(classes) + per_instance;
    out += in + "string[] primvars:tessera:classNames = " + list(class_names) +
           " (interpolation = \"constant\")\n";
    out += in + "int64[] primvars:tessera:id = " + list(ids) + per_instance;
    usda::NameTable names({"class", "classNames", "id"});
    for (size_t a = 0; a < attributes.size(); ++a)
        out += in + "double[] primvars:tessera:" + names.unique(scene.attribute_names[a]) + " = " +
               list(attributes[a]) + per_instance;
    out += in + "int[] protoIndices = " + list(protos) + "\n";
    out += in + "rel prototypes = " + list(targets) + "\n";
    out += in + "float3[] scales = " + list(scales) + "\n";
    out += "\n" + in + "over \"Prototypes\"\n" + in + "{\n";
    for (const Prototype& p : prototypes)
        out += mesh_prim(scene.meshes[p.mesh], p.name, p.type, scene.type_names[p.type], "", 3);
    return out + in + "}\n" + pad(1) + "}\n";
}

// The elements that are not instanced, each a Mesh in world coordinates.
std::string own_meshes(const Scene& scene) {
    usda::NameTable names;
    std::string out = pad(1) + "def Xform \"Meshes\"\n" + pad(1) + "{\n";
    for (int i = 0; i < static_cast<int>(scene.instances.size()); ++i) {
        const SceneInstance& inst = scene.instances[i];
        if (inst.instanced) continue;
        const std::string id = pad(3) + "custom int64 tessera:id = " + usda::int64_id(inst.id) + "\n";
        out += mesh_prim(scene.world_mesh(i), names.unique(instance_name(scene, i)), inst.type,
                         scene.type_names.at(inst.type), id, 2);
    }
    return out + pad(1) + "}\n";
}

}  // namespace

std::string to_usda(const Scene& scene) {
    size_t instanced = 0;
    for (const SceneInstance& inst : scene.instances) instanced += inst.instanced ? 1 : 0;
    std::string out = usda::layer_header(std::string("tessera ") + version + ": " +
                                             std::to_string(scene.instances.size()) + " elements, dimension " +
                                             std::to_string(scene.dimension),
                                         {}, 0.0);
    out += "def Xform \"World\"\n{\n";
    if (instanced > 0) out += point_instancer(scene, prototypes_of(scene), {}, {});
    if (instanced < scene.instances.size()) out += (instanced > 0 ? "\n" : "") + own_meshes(scene);
    return out + "}\n";
}

std::string usda_point_instancer(const std::vector<Scene>& frames, const std::vector<double>& codes) {
    return point_instancer(frames.at(0), prototypes_of(frames[0]), frames, codes);
}

}  // namespace tessera::geometry
