// geometry/scene.cpp — build_scene: every element of an arrangement rebuilt as a
// triangle mesh (geometry.hpp): rigid types instance their mesh with the fitted pose,
// deformable types get a deformed copy each, types without a mesh a default shape
// (single-sample elements instance one unit sphere per type, scaled by the radius).
#include <algorithm>
#include <cmath>

#include "geometry/geometry_internal.hpp"
#include "tessera/det.hpp"
#include "tessera/error.hpp"

namespace tessera {

namespace {

void check_options(const GeometryOptions& o) {
    const auto fail = [](const std::string& what) { throw Error(ErrorKind::option, "GeometryOptions::" + what); };
    if (o.sphere_subdivisions < 0 || o.sphere_subdivisions > 5)
        fail("sphere_subdivisions must be 0 to 5, got " + std::to_string(o.sphere_subdivisions));
    if (o.tube_sides < 3 || o.tube_sides > 64)
        fail("tube_sides must be 3 to 64, got " + std::to_string(o.tube_sides));
    if (!std::isfinite(o.deform_falloff) || !(o.deform_falloff > 0.0))
        fail("deform_falloff must be a number > 0, got " + std::to_string(o.deform_falloff));
}

// The spacing that sizes default shapes of elements without a radius: the mean
// nearest-neighbour distance of the element centroids; for a lone element the mean
// distance between its consecutive samples, else a tenth of the domain's smallest side.
double default_spacing(const Exemplar& data) {
    const double nn = mean_nearest_neighbor_distance(data);
    if (nn > 0.0) return nn;
    double sum = 0.0;
    int count = 0;
    for (const Element& e : data.elements)
        for (int s = 0; s + 1 < e.sample_count; ++s, ++count)
            sum += norm(data.samples[e.first_sample + s + 1].p - data.samples[e.first_sample + s].p);
    if (sum > 0.0) return sum / count;
    const Vec3 size = data.domain.bounds().size();
    double side = size.x;
    for (int k = 1; k < data.dimension; ++k) side = std::min(side, size[k]);
    return side > 0.0 ? 0.1 * side : 1.0;
}

}  // namespace

Scene build_scene(const Exemplar& data, const GeometryOptions& options) {
    check_options(options);
    data.validate("build_scene");
    Scene scene;
    scene.dimension = data.dimension;
    scene.attribute_names = data.attribute_names;
    for (const ElementType& t : data.types) scene.type_names.push_back(t.name);
    std::vector<geometry::TypeGeometry> types = geometry::type_geometry(data, options);

    // Rigid types share one mesh, placed by each element's pose.
    std::vector<int> shared(types.size(), -1);
    for (size_t t = 0; t < types.size(); ++t)
        if (types[t].has_mesh && data.types[t].rigid) {
            shared[t] = static_cast<int>(scene.meshes.size());
            scene.meshes.push_back(types[t].mesh);
        }

    // Default spheres: one unit icosphere per type, made on first need.
    std::vector<int> sphere(types.size(), -1);
    double spacing = -1.0;  // computed on first need
    const auto default_radius = [&](const Element& el) {
        if (el.radius > 0.0) return el.radius;
        if (spacing < 0.0) spacing = default_spacing(data);
        return (el.sample_count == 1 ? 0.5 : 0.2) * spacing;
    };
    scene.instances.reserve(data.elements.size());
    for (size_t e = 0; e < data.elements.size(); ++e) {
        const Element& el = data.elements[e];
        std::vector<Vec3> points;
        for (int s = 0; s < el.sample_count; ++s) points.push_back(data.samples[el.first_sample + s].p);
        SceneInstance inst;
        inst.element = static_cast<int>(e);
        inst.id = el.id;
        inst.type = el.type;
        inst.scale = el.scale;
        inst.orientation = el.orientation;
        inst.attributes = el.attributes;
        for (const Vec3& p : points) inst.position += p / el.sample_count;
        const geometry::TypeGeometry& g = types[el.type];
        if (g.has_mesh && data.types[el.type].rigid) {
            const geometry::Pose pose = geometry::fit_rigid_pose(g.reference, points.data(), el, data.dimension);
            inst.instanced = true;
            inst.mesh = shared[el.type];
            inst.position = pose.position;
            inst.orientation = pose.orientation;
            inst.fit_error = pose.fit_error;
        } else if (!g.has_mesh && el.sample_count == 1) {
            if (sphere[el.type] < 0) {
                sphere[el.type] = static_cast<int>(scene.meshes.size());
                scene.meshes.push_back(geometry::icosphere({0, 0, 0}, 1.0, options.sphere_subdivisions));
            }
            inst.instanced = true;
            inst.mesh = sphere[el.type];
            inst.scale = default_radius(el);  // the radius alone, as the previews draw it
        } else {
            inst.mesh = static_cast<int>(scene.meshes.size());
            if (g.has_mesh)
                scene.meshes.push_back(geometry::deform_mesh(g.mesh, g.reference, points.data(), el.scale,
                                                             options.deform_falloff, data.dimension, el.orientation));
            else
                scene.meshes.push_back(geometry::tube(points, default_radius(el), options.tube_sides));
        }
        scene.instances.push_back(inst);
    }
    return scene;
}

TriangleMesh Scene::world_mesh(int instance) const {
    if (instance < 0 || instance >= static_cast<int>(instances.size()))
        throw Error(ErrorKind::option, "Scene::world_mesh: instance " + std::to_string(instance) +
                                           " does not exist (the scene has " + std::to_string(instances.size()) + ")");
    const SceneInstance& inst = instances[instance];
    TriangleMesh mesh = meshes.at(static_cast<size_t>(inst.mesh));
    if (inst.instanced)
        for (Vec3& v : mesh.vertices) v = inst.position + inst.orientation.rotate(v * inst.scale);
    return mesh;
}

TriangleMesh Scene::merged(std::vector<int>* triangle_instance) const {
    TriangleMesh all;
    if (triangle_instance) triangle_instance->clear();
    for (int i = 0; i < static_cast<int>(instances.size()); ++i) {
        const TriangleMesh mesh = world_mesh(i);
        const int offset = static_cast<int>(all.vertices.size());
        all.vertices.insert(all.vertices.end(), mesh.vertices.begin(), mesh.vertices.end());
        for (const auto& t : mesh.triangles) {
            all.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
            if (triangle_instance) triangle_instance->push_back(i);
        }
    }
    return all;
}

}  // namespace tessera
