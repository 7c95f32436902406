// Element meshes of a Scene (tessera/geometry.hpp) placed in the world and handed to
// the triangle rasterizer. The renderer keeps its own copy of the pose transform
// (world = position + scale * orientation.rotate(v) for instanced meshes, as given
// otherwise) so that it depends on the Scene's data only.
#pragma once

#include "render/mesh_raster.hpp"
#include "tessera/domain.hpp"
#include "tessera/geometry.hpp"

namespace tessera::render {

// An orthographic camera as a map from world to picture space (x right and y down,
// in raster pixels): x = (p . right - x0) * scale, y = (y1 - p . up) * scale, and
// depth = p . toward (larger = nearer). The axes are orthonormal, `toward` pointing
// at the viewer.
struct ScreenMap {
    Vec3 right{1, 0, 0}, up{0, 1, 0}, toward{0, 0, 1};
    double x0 = 0.0, y1 = 0.0;  // picture left and top, data units
    double scale = 1.0;         // raster pixels per data unit
};

// Throws Error(input) when an instance names a mesh the scene does not have, or when
// the scene's dimension differs from `dimension`.
void check_scene(const Scene& scene, int dimension);

// Bounds of every finite world-space vertex of the instances; lo > hi when there is none.
Box scene_bounds(const Scene& scene);

// Draws every triangle of every instance, tagged with the instance index. Normals are
// the meshes' corner normals (mesh_normals.hpp: smooth across gentle bends, split at
// sharp edges) in view coordinates (x right, y up, z toward the viewer), turned per
// triangle to the side of the face that the viewer sees: both sides of a surface are
// lit, so the winding does not matter.
void rasterize_scene(const Scene& scene, const ScreenMap& map, MeshRaster& raster);

}  // namespace tessera::render
