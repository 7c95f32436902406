// geometry/write_obj.cpp — the scene as Wavefront OBJ: one object per element (named
// type_id), grouped by type, world coordinates written so they read back exactly.
#include <cctype>

#include "geometry/geometry_internal.hpp"
#include "io/io_util.hpp"

namespace tessera::geometry {

namespace {

// OBJ names end at whitespace ("g a b" puts the faces in two groups).
std::string obj_name(std::string name) {
    for (char& c : name)
        if (std::isspace(static_cast<unsigned char>(c))) c = '_';
    return name;
}

}  // namespace

std::string to_obj(const Scene& scene) {
    using io_detail::format_number;
    std::string out = "# tessera scene: " + std::to_string(scene.instances.size()) + " elements, dimension " +
                      std::to_string(scene.dimension) + "\n";
    size_t base = 1;  // OBJ indices are 1-based and global
    for (int i = 0; i < static_cast<int>(scene.instances.size()); ++i) {
        const TriangleMesh mesh = scene.world_mesh(i);
        out += "o " + obj_name(instance_name(scene, i)) + "\n";
        out += "g " + obj_name(scene.type_names.at(static_cast<size_t>(scene.instances[i].type))) + "\n";
        for (const Vec3& v : mesh.vertices)
            out += "v " + format_number(v.x) + " " + format_number(v.y) + " " + format_number(v.z) + "\n";
        for (const auto& t : mesh.triangles)
            out += "f " + std::to_string(base + t[0]) + " " + std::to_string(base + t[1]) + " " +
                   std::to_string(base + t[2]) + "\n";
        base += mesh.vertices.size();
    }
    return out;
}

}  // namespace tessera::geometry
