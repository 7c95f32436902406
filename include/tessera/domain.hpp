// tessera/domain.hpp — where elements live: the region an exemplar was observed
// in, and the region an output must fill. Methods see a domain only through
// inside(p), occupancy c(p) in [0, 1] (Eq. 6 of the Discrete Element Textures
// paper), its bounding box and its measure, so shapes plug in without touching
// the methods: boxes, 2D polygons with holes, 2D grayscale image masks, 3D closed
// triangle meshes and 3D shells under a mesh surface (section 5, "Domain shape").
//
// Domain is a small value type. Boxes are answered inline (inside/occupancy sit in
// the search's inner loop); every other kind holds an immutable shape behind a
// shared_ptr<const>, so copies are cheap and concurrent queries are safe.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tessera/mesh.hpp"
#include "tessera/vec.hpp"

namespace tessera {

struct Box {
    Vec3 lo, hi;
    Vec3 size() const { return hi - lo; }
    Vec3 center() const { return (lo + hi) * 0.5; }
};

// A grayscale image, row 0 at the top, values in [0, 1] (0 = black, 1 = white).
struct GrayImage {
    int width = 0, height = 0;
    std::vector<float> values;  // width * height, row-major
};

// How a shaped domain was made, so writers (JSON) and previews can reproduce it.
// Coordinates are those of the unscaled shape; `scale` (about `origin`, the lower
// corner of the unscaled bounds) is applied on top (Domain::scaled).
struct DomainSource {
    std::vector<Vec3> outer;               // polygon
    std::vector<std::vector<Vec3>> holes;  // polygon
    std::string file;                      // mask image / mesh file ("" for in-memory data)
    Box box;                               // mask: the box the image is mapped onto
    double threshold = 0.5;                // mask
    int resolution = 0;                    // mesh, shell: voxels along the longest axis
    double thickness = 0.0;                // shell
    double scale = 1.0;
    Vec3 origin;
};

class DomainShape;  // private to the library (src/core/domain_shape.hpp)

class Domain {
public:
    enum class Kind { box, polygon, mask, mesh, shell };

    // An axis-aligned box. dimension 2 ignores z (lo.z = hi.z = 0 is allowed).
    // Throws Error(domain) if any extent used by `dimension` is not > 0 or not finite.
    static Domain box(const Vec3& lo, const Vec3& hi, int dimension);

    // A 2D polygon (z ignored) with optional holes; inside = even-odd rule over all
    // rings, so a point in a hole is outside. Throws Error(domain) for a ring with
    // fewer than 3 vertices or zero area, non-finite coordinates, a self-intersecting
    // ring, or a hole that crosses the outer ring or another hole or lies outside it.
    static Domain polygon(const std::vector<Vec3>& outer, const std::vector<std::vector<Vec3>>& holes = {});

    // A 2D grayscale image mapped onto the box [lo, hi] (x right, y up: the image's top
    // row is at hi.y). c(p) = bilinear gray level (white = 1 = inside), inside = c >= threshold.
    // Throws Error(io) naming the file if it cannot be read as an image, Error(domain)
    // naming it if no pixel reaches the threshold (an empty mask) or the box is empty.
    static Domain mask(const std::string& png_path, const Vec3& lo, const Vec3& hi, double threshold = 0.5);
    static Domain mask(const GrayImage& image, const Vec3& lo, const Vec3& hi, double threshold = 0.5,
                       const std::string& name = "image");

    // The volume enclosed by a triangle mesh (OBJ or ASCII PLY), on a voxel grid with
    // `resolution` voxels along its longest axis (16..1024). Inside is decided by the
    // generalized winding number (>= 1/2 in magnitude), so small cracks, open or
    // non-manifold meshes still work (see notes()); inside(p) is exact at any point, not
    // the voxels' (the voxels serve occupancy and the distance queries). Throws Error(domain) if the mesh
    // encloses no volume, Error(io)/Error(input) for unreadable / malformed files.
    static Domain mesh(const std::string& path, int resolution = 128);
    static Domain mesh(const TriangleMesh& mesh, int resolution = 128, const std::string& name = "mesh");

    // The band of the mesh's volume within `thickness` of its surface (for surface
    // synthesis); inside(p) is exact (the mesh's inside and the exact distance to its
    // triangles). Throws as mesh(), and Error(domain) if thickness is not > 0.
    static Domain shell(const std::string& path, double thickness, int resolution = 128);
    static Domain shell(const TriangleMesh& mesh, double thickness, int resolution = 128,
                        const std::string& name = "mesh");

    // The part of `within` where keep(p) holds, on a grid of cells of size `cell` (a mask in
    // 2D, a voxel volume in 3D; inside where the interpolated cell values reach 1/2). For
    // regions computed by a method (the band a brush stroke sweeps). Error(domain) when no
    // cell is kept or the grid would exceed 2^24 cells.
    static Domain region(const Domain& within, const std::function<bool(const Vec3&)>& keep, double cell,
                         const std::string& name = "region");

    Kind kind() const { return kind_; }
    int dimension() const { return dimension_; }
    const Box& bounds() const { return bounds_; }

    // Inline for boxes: Eq. 6 asks it for every neighbour of every candidate of the search.
    bool inside(const Vec3& p) const {
        if (kind_ == Kind::box)
            return p.x >= bounds_.lo.x && p.x <= bounds_.hi.x && p.y >= bounds_.lo.y && p.y <= bounds_.hi.y &&
                   (dimension_ == 2 || (p.z >= bounds_.lo.z && p.z <= bounds_.hi.z));
        return shaped_inside(p);
    }
    // Occupancy c(p) of Eq. 6 in [0, 1]: boxes and polygons are sharp (1 inside, 0
    // outside); masks give the bilinear gray level, meshes and shells the trilinear
    // interpolation of their voxel occupancy.
    double occupancy(const Vec3& p) const {
        if (kind_ == Kind::box) return inside(p) ? 1.0 : 0.0;
        return shaped_occupancy(p);
    }
    // Area (2D) or volume (3D): exact for boxes and polygons, pixel / voxel counts otherwise.
    double measure() const;
    // |W ∩ (W + d)|: the measure of the domain intersected with its translate by d,
    // used by the translation edge correction of pair correlation estimates. Exact for
    // boxes; other kinds interpolate a table computed once (on first use) from a
    // rasterization (256 cells along the longest side in 2D, 48 in 3D).
    double translated_overlap(const Vec3& d) const;
    // Computes that table now with `threads` workers (0 = all) if it is not there yet; a
    // method calls this with its own thread count before its first translated_overlap.
    void prepare_overlap(int threads) const;
    // A point of the domain nearest to p (p itself when inside); inside(result) holds.
    // Exact for boxes and polygons; voxel kinds return a point on the segment to the
    // nearest inside voxel centre, within about a cell of the boundary (meshes and
    // shells: just inside their exact boundary, by bisection with the exact inside).
    Vec3 closest_inside(const Vec3& p) const;
    // Distance from p to the domain boundary, positive inside. For p inside it never
    // exceeds the true distance (voxel kinds subtract a cell diagonal), so callers may
    // skip boundary work when it is >= their radius. <= 0 outside.
    double distance_to_boundary(const Vec3& p) const;
    // The same shape scaled by `factor` about the lower corner of its bounds.
    Domain scaled(double factor) const;
    // Human-readable description, e.g. "box [0,10]x[0,10]".
    std::string describe() const;
    // Repairs and remarks worth telling a user (e.g. "mesh bowl.obj has 12 boundary
    // edges; inside decided by generalized winding number"); empty when there are none.
    std::string notes() const;
    // How a non-box domain was made (empty for boxes).
    DomainSource source() const;

private:
    bool shaped_inside(const Vec3& p) const;
    double shaped_occupancy(const Vec3& p) const;
    // Maps a world point into the unscaled shape's coordinates and back.
    Vec3 to_shape(const Vec3& p) const { return origin_ + (p - origin_) * (1.0 / scale_); }
    Vec3 to_world(const Vec3& q) const { return origin_ + (q - origin_) * scale_; }
    static Domain from_shape(std::shared_ptr<const DomainShape> shape, Kind kind);

    Kind kind_ = Kind::box;
    int dimension_ = 2;
    Box bounds_;
    std::shared_ptr<const DomainShape> shape_;
    double scale_ = 1.0;
    Vec3 origin_;
};

}  // namespace tessera
