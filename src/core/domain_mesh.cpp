// core/domain_mesh.cpp — 3D domains from triangle meshes: Domain::mesh (the enclosed
// volume) and Domain::shell (the band of that volume within a thickness of the
// surface, for surface synthesis). Both become a VoxelShape: cubic cells, `resolution`
// along the longest axis with two cells of empty margin, value 1 inside / 0 outside,
// so c(p) of Eq. 6 is the trilinear interpolation of the voxel occupancy.
// inside(p) is exact, not the voxels' (a sample a fraction of a cell outside the surface
// is outside): the cell centre nearest p is classified exactly by the winding number,
// and the triangles the segment from that centre to p crosses flip it (ray parity, only
// in cells a triangle passes near); a shell adds the exact distance to the surface
// where its voxel value cannot decide.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <sstream>

#include "core/domain_shape.hpp"
#include "core/triangle_tree.hpp"
#include "core/winding_number.hpp"
#include "tessera/error.hpp"

namespace tessera {
namespace {

class MeshShape final : public VoxelShape {
public:
    std::string text;
    std::string describe() const override { return text; }

    std::unique_ptr<core::TriangleTree> tree;
    std::vector<uint8_t> enclosed;   // per cell: its centre is inside the mesh (exact)
    std::vector<uint8_t> near;       // per cell: a triangle's box meets the cell
    std::vector<float> to_surface;   // shells: per cell, the centre's distance to the surface
    double thickness = 0.0;          // shells: the band's width; 0 for a solid mesh
    double half_diagonal = 0.0;      // of a cell

    bool inside(const Vec3& p) const override {
        if (!in_box(p)) return false;
        const int64_t v = nearest_cell(p);
        bool in = enclosed[v];
        if (near[v]) in ^= (tree->segment_crossings(centre(v), p) & 1) != 0;
        if (!in || thickness == 0.0) return in;
        // The distance to the surface is 1-Lipschitz: the centre's decides unless p is
        // within a half diagonal of the band's edge.
        const double d = to_surface[v];
        if (d + half_diagonal <= thickness) return true;
        if (d - half_diagonal > thickness) return false;
        return tree->any_within(p, thickness);
    }
};

// Cells whose box meets a triangle's bounding box: only there can the segment from a
// cell's centre to a point of the cell cross the surface.
std::vector<uint8_t> near_surface_cells(const TriangleMesh& mesh, const core::CubeGrid& grid) {
    std::vector<uint8_t> near(static_cast<size_t>(grid.count()), 0);
    constexpr double pad = 1e-3;  // of a cell: ties at cell borders count on both sides
    for (const auto& t : mesh.triangles) {
        int i0[3], i1[3];
        for (int k = 0; k < 3; ++k) {
            double lo = INFINITY, hi = -INFINITY;
            for (int v : t) lo = std::min(lo, mesh.vertices[v][k]), hi = std::max(hi, mesh.vertices[v][k]);
            i0[k] = std::clamp(static_cast<int>(std::floor((lo - grid.first[k]) / grid.cell + 0.5 - pad)), 0, grid.n[k] - 1);
            i1[k] = std::clamp(static_cast<int>(std::floor((hi - grid.first[k]) / grid.cell + 0.5 + pad)), 0, grid.n[k] - 1);
        }
        for (int z = i0[2]; z <= i1[2]; ++z)
            for (int y = i0[1]; y <= i1[1]; ++y)
                for (int x = i0[0]; x <= i1[0]; ++x)
                    near[x + int64_t(grid.n[0]) * (y + int64_t(grid.n[1]) * z)] = 1;
    }
    return near;
}

std::string base_name(const std::string& name) { return std::filesystem::path(name).filename().string(); }

void check_mesh(const TriangleMesh& mesh, const std::string& name, int resolution) {
    if (resolution < 16 || resolution > 1024)
        throw Error(ErrorKind::domain, "mesh " + name + ": resolution must be 16 to 1024, got " + std::to_string(resolution));
    if (mesh.triangles.empty()) throw Error(ErrorKind::domain, "mesh " + name + " has no triangles");
    for (const Vec3& v : mesh.vertices)
        if (!is_finite(v)) throw Error(ErrorKind::domain, "mesh " + name + " has a non-finite vertex");
    for (const auto& t : mesh.triangles)
        for (int v : t)
            if (v < 0 || v >= int(mesh.vertices.size()))
                throw Error(ErrorKind::domain, "mesh " + name + " has a triangle with a vertex index out of range");
}

// Boundary edges (used by one triangle) and non-manifold edges (by more than two).
std::pair<long, long> edge_defects(const TriangleMesh& mesh) {
    std::vector<std::pair<int, int>> edges;
    edges.reserve(mesh.triangles.size() * 3);
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) edges.push_back(std::minmax(t[k], t[(k + 1) % 3]));
    std::sort(edges.begin(), edges.end());
    long boundary = 0, non_manifold = 0;
    for (size_t i = 0; i < edges.size();) {
        size_t j = i;
        while (j < edges.size() && edges[j] == edges[i]) ++j;
        if (j - i == 1) ++boundary;
        if (j - i > 2) ++non_manifold;
        i = j;
    }
    return {boundary, non_manifold};
}

std::string repair_notes(const std::string& name, long boundary, long non_manifold, int64_t exact_cells,
                         int64_t overlap_cells) {
    std::ostringstream s;
    if (boundary > 0 || non_manifold > 0) {
        s << "mesh " << base_name(name) << " has " << boundary << " boundary edges";
        if (non_manifold) s << " and " << non_manifold << " non-manifold edges";
        s << "; inside decided by generalized winding number (" << exact_cells << " cells evaluated exactly)";
    }
    if (overlap_cells > 0) {
        if (s.tellp() > 0) s << "; ";
        s << "mesh " << base_name(name) << " overlaps itself (winding number 2 or more in " << overlap_cells
          << " voxels: self-intersecting or nested parts); the domain is their union";
    }
    return s.str();
}

std::shared_ptr<MeshShape> voxelize(const TriangleMesh& mesh, int resolution, const std::string& name, double thickness) {
    check_mesh(mesh, name, resolution);
    Vec3 lo{INFINITY, INFINITY, INFINITY}, hi = -lo;
    for (const Vec3& v : mesh.vertices)
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
    const Vec3 size = hi - lo;
    const double longest = std::max({size.x, size.y, size.z});
    if (!(longest > 0.0)) throw Error(ErrorKind::domain, "mesh " + name + " encloses no volume (all vertices coincide)");
    constexpr int margin = 2;  // empty cells around the mesh: the grid's border is outside
    core::CubeGrid grid;
    grid.cell = longest / (resolution - 2 * margin);
    auto shape = std::make_shared<MeshShape>();
    for (int k = 0; k < 3; ++k) {
        grid.n[k] = std::min(resolution, static_cast<int>(std::ceil(size[k] / grid.cell - 1e-9)) + 2 * margin);
        const double extent = grid.n[k] * grid.cell;
        shape->bounds.lo[k] = lo[k] - 0.5 * (extent - size[k]);
        shape->bounds.hi[k] = shape->bounds.lo[k] + extent;
        grid.first[k] = shape->bounds.lo[k] + 0.5 * grid.cell;
    }
    const int threads = 0;
    int64_t exact_cells = 0;
    const std::vector<float> w = core::winding_numbers(mesh, grid, threads, &exact_cells);
    shape->dimension = 3;
    for (int k = 0; k < 3; ++k) shape->n[k] = grid.n[k];
    shape->spacing = {grid.cell, grid.cell, grid.cell};
    shape->first = grid.first;
    shape->threshold = 0.5;
    shape->values.resize(w.size());
    // |w| so that a mesh with inward-facing triangles still encloses its volume.
    // |w| >= 1.5 marks volume enclosed twice: a self-intersecting mesh or overlapping parts.
    // Taking the union is the natural repair; it is reported in the notes.
    int64_t overlap_cells = 0;
    for (size_t v = 0; v < w.size(); ++v) {
        shape->values[v] = std::abs(w[v]) >= 0.5f ? 1.0f : 0.0f;
        overlap_cells += std::abs(w[v]) >= 1.5f;
    }
    const auto [boundary, non_manifold] = edge_defects(mesh);
    if (boundary > 0 || non_manifold > 0) {
        // Where all three ray counts agree the exact winding number was not evaluated;
        // for an open mesh (a sheet, say) they can agree on a wrong answer. Check a
        // spread sample of the inside cells with the exact generalized winding number:
        // if most are below 1/2 the mesh does not enclose a volume.
        std::vector<int64_t> in;
        for (size_t v = 0; v < w.size(); ++v)
            if (shape->values[v] > 0.5f) in.push_back(static_cast<int64_t>(v));
        const size_t samples = std::min<size_t>(in.size(), 512);
        size_t agree = 0;
        for (size_t s = 0; s < samples; ++s) {
            const int64_t v = in[s * in.size() / samples];
            const Vec3 p = grid.first + Vec3(double(v % grid.n[0]), double(v / grid.n[0] % grid.n[1]),
                                             double(v / (int64_t(grid.n[0]) * grid.n[1]))) * grid.cell;
            agree += std::abs(core::generalized_winding_number(mesh, p)) >= 0.5;
        }
        if (2 * agree < samples) std::fill(shape->values.begin(), shape->values.end(), 0.0f);
    }
    shape->enclosed.resize(w.size());
    for (size_t v = 0; v < w.size(); ++v) shape->enclosed[v] = shape->values[v] > 0.5f;
    if (thickness > 0.0) {
        shape->to_surface = core::surface_distance(mesh, grid, thickness + 2.0 * grid.cell, threads);
        for (size_t v = 0; v < w.size(); ++v)
            if (!(shape->to_surface[v] <= thickness)) shape->values[v] = 0.0f;
    }
    shape->tree = std::make_unique<core::TriangleTree>(mesh);
    shape->near = near_surface_cells(mesh, grid);
    shape->thickness = thickness;
    shape->half_diagonal = 0.5 * std::sqrt(3.0) * grid.cell;
    if (shape->finish(threads) == 0) {
        if (thickness > 0.0)
            throw Error(ErrorKind::domain, "shell of mesh " + name + " is empty: thickness " + std::to_string(thickness) +
                                               " is thinner than the voxel size or the mesh encloses no volume");
        throw Error(ErrorKind::domain, "mesh " + name +
                                           " encloses no volume (generalized winding number below 1/2 everywhere); "
                                           "it must be a closed or nearly closed surface");
    }
    shape->notes = repair_notes(name, boundary, non_manifold, exact_cells, overlap_cells);
    shape->source.file = name;
    shape->source.resolution = resolution;
    shape->source.thickness = thickness;
    std::ostringstream s;
    s << (thickness > 0.0 ? "shell of mesh " : "mesh ") << base_name(name);
    if (thickness > 0.0) s << " (thickness " << thickness << ")";
    s << " on a " << grid.n[0] << "x" << grid.n[1] << "x" << grid.n[2] << " voxel grid";
    shape->text = s.str();
    return shape;
}

}  // namespace

Domain Domain::mesh(const TriangleMesh& mesh, int resolution, const std::string& name) {
    return from_shape(voxelize(mesh, resolution, name, 0.0), Kind::mesh);
}

Domain Domain::mesh(const std::string& path, int resolution) { return mesh(read_triangle_mesh(path), resolution, path); }

Domain Domain::shell(const TriangleMesh& mesh, double thickness, int resolution, const std::string& name) {
    if (!std::isfinite(thickness) || !(thickness > 0.0))
        throw Error(ErrorKind::domain, "shell of mesh " + name + ": thickness must be a number > 0, got " + std::to_string(thickness));
    return from_shape(voxelize(mesh, resolution, name, thickness), Kind::shell);
}

Domain Domain::shell(const std::string& path, double thickness, int resolution) {
    return shell(read_triangle_mesh(path), thickness, resolution, path);
}

}  // namespace tessera
