// geometry/type_geometry.cpp — what each element type brings to the scene: its mesh
// (read once, however many elements use it) and its reference layout, the samples'
// places in the mesh's frame. Problems are reported per type, by name, before any
// element is built.
#include <filesystem>

#include "geometry/geometry_internal.hpp"
#include "tessera/error.hpp"

namespace tessera::geometry {

namespace {

std::string resolve(const std::string& path, const std::string& base) {
    const std::filesystem::path p(path);
    if (base.empty() || p.is_absolute()) return path;
    return (std::filesystem::path(base) / p).lexically_normal().string();
}

// The layout of `element`'s samples in its own frame: the inverse of its pose.
std::vector<Vec3> derived_reference(const Exemplar& data, const Element& element) {
    Vec3 centroid;
    for (int s = 0; s < element.sample_count; ++s) centroid += data.samples[element.first_sample + s].p;
    centroid = centroid / element.sample_count;
    const Quat inverse = element.orientation.conjugate();
    std::vector<Vec3> reference;
    for (int s = 0; s < element.sample_count; ++s)
        reference.push_back(inverse.rotate(data.samples[element.first_sample + s].p - centroid) / element.scale);
    return reference;
}

}  // namespace

std::vector<TypeGeometry> type_geometry(const Exemplar& data, const GeometryOptions& options) {
    std::vector<TypeGeometry> types(data.types.size());
    std::vector<int> first(data.types.size(), -1);  // first element of each type
    for (size_t e = 0; e < data.elements.size(); ++e)
        if (first[data.elements[e].type] < 0) first[data.elements[e].type] = static_cast<int>(e);
    for (size_t t = 0; t < data.types.size(); ++t) {
        const ElementType& type = data.types[t];
        if (type.mesh.empty() || first[t] < 0) continue;  // default shapes; or no element to build
        const std::string name = "element type '" + type.name + "'";
        const Element& example = data.elements[first[t]];
        const std::string file = resolve(type.mesh, options.base_directory);
        TypeGeometry& g = types[t];
        g.has_mesh = true;
        try {
            g.mesh = read_triangle_mesh(file);
        } catch (const Error& e) {
            throw Error(e.kind(), name + ": " + e.what());
        }
        if (g.mesh.triangles.empty())
            throw Error(ErrorKind::input, name + ": mesh " + file + " has no triangles");
        if (!type.reference.empty()) {
            if (static_cast<int>(type.reference.size()) != example.sample_count)
                throw Error(ErrorKind::input, name + ": the reference layout has " +
                                                  std::to_string(type.reference.size()) +
                                                  " samples but its elements have " +
                                                  std::to_string(example.sample_count));
            for (const Vec3& r : type.reference)
                if (!is_finite(r)) throw Error(ErrorKind::input, name + ": the reference layout is not finite");
            g.reference = type.reference;
        } else if (!type.rigid) {
            // Every element of a deformable type may be bent: none shows the rest shape.
            throw Error(ErrorKind::input, name + " is deformable and has a mesh, so it needs a \"reference\" "
                                                 "layout (the samples' places in the mesh's frame)");
        } else {
            g.reference = derived_reference(data, example);
        }
    }
    return types;
}

}  // namespace tessera::geometry
