// geometry/write_mesh_ply.cpp — the scene as one ASCII PLY mesh whose faces carry the
// element index and the class (type index), for tools that colour or split by them
// (MeshLab, Houdini, Blender). Named .mesh.ply: a plain .ply is save()'s point output.
#include "geometry/geometry_internal.hpp"
#include "io/io_util.hpp"

namespace tessera::geometry {

std::string to_mesh_ply(const Scene& scene) {
    using io_detail::format_number;
    std::vector<int> triangle_instance;
    const TriangleMesh all = scene.merged(&triangle_instance);
    std::string out = "ply\nformat ascii 1.0\ncomment tessera scene, dimension " + std::to_string(scene.dimension) + "\n";
    for (size_t t = 0; t < scene.type_names.size(); ++t) {
        std::string name = scene.type_names[t];
        for (char& c : name)
            if (c == '\n' || c == '\r') c = ' ';  // a header line per class
        out += "comment class " + std::to_string(t) + " " + name + "\n";
    }
    out += "element vertex " + std::to_string(all.vertices.size()) + "\n";
    out += "property double x\nproperty double y\nproperty double z\n";
    out += "element face " + std::to_string(all.triangles.size()) + "\n";
    out += "property list uchar int vertex_indices\nproperty int element\nproperty int class\nend_header\n";
    for (const Vec3& v : all.vertices)
        out += format_number(v.x) + " " + format_number(v.y) + " " + format_number(v.z) + "\n";
    for (size_t f = 0; f < all.triangles.size(); ++f) {
        const auto& t = all.triangles[f];
        const SceneInstance& inst = scene.instances[triangle_instance[f]];
        out += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + " " +
               std::to_string(inst.element) + " " + std::to_string(inst.type) + "\n";
    }
    return out;
}

}  // namespace tessera::geometry
