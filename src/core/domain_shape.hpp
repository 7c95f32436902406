// core/domain_shape.hpp — the private interface behind every non-box Domain kind
// (polygon, mask, mesh, shell), and the voxel-grid shape shared by masks, meshes
// and shells. Shapes are immutable once built; the one lazily built table (the set
// covariance for translated_overlap) is guarded by std::call_once, so a shape may
// be queried from many threads.
#pragma once

#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include "tessera/domain.hpp"

namespace tessera {

class DomainShape {
public:
    virtual ~DomainShape() = default;
    // All in the shape's own (unscaled) coordinates; Domain applies scaled().
    virtual bool inside(const Vec3& p) const = 0;
    virtual double occupancy(const Vec3& p) const = 0;
    virtual double measure() const = 0;
    virtual Vec3 closest_inside(const Vec3& p) const = 0;
    virtual double distance_to_boundary(const Vec3& p) const = 0;
    virtual std::string describe() const = 0;
    // |W ∩ (W + d)|, interpolated in a table of the set covariance of a rasterization
    // of the shape (domain_overlap.cpp), built on first use.
    double translated_overlap(const Vec3& d) const;
    // Builds that table now with `threads` workers, unless it is built already.
    void prepare_overlap(int threads) const;

    int dimension = 2;
    Box bounds;
    std::string notes;
    DomainSource source;

private:
    struct OverlapTable {
        double cell = 0.0;   // raster cell size
        int stride = 1;      // table step, in cells
        int half[3] = {0, 0, 0};  // table index m in [-half, half] per axis
        std::vector<double> values;  // measure |W ∩ (W + m * stride * cell)|
    };
    void build_overlap_table(int threads) const;
    mutable std::once_flag overlap_once_;
    mutable OverlapTable overlap_;
};

// A regular grid of cells over a box, with a value per cell centre; inside where the
// (bi/tri)linear interpolation of the values reaches `threshold`. 2D grids have nz = 1.
class VoxelShape : public DomainShape {
public:
    int n[3] = {1, 1, 1};
    Vec3 spacing;      // cell size per axis
    Vec3 first;        // centre of cell (0, 0, 0)
    double threshold = 0.5;
    std::vector<float> values;

    int64_t cell_count() const { return int64_t(n[0]) * n[1] * n[2]; }
    int64_t index(int i, int j, int k) const { return i + int64_t(n[0]) * (j + int64_t(n[1]) * k); }
    Vec3 centre(int64_t v) const;

    bool inside(const Vec3& p) const override;
    double occupancy(const Vec3& p) const override;
    double measure() const override;
    Vec3 closest_inside(const Vec3& p) const override;
    double distance_to_boundary(const Vec3& p) const override;

    // Call once values are set: counts inside cells and builds the distance transforms
    // closest_inside and distance_to_boundary use. Returns the number of inside cells.
    int64_t finish(int threads);

protected:
    bool in_box(const Vec3& p) const;
    double interpolate(const Vec3& p) const;
    int64_t nearest_cell(const Vec3& p) const;

private:
    int64_t inside_cells_ = 0;
    std::vector<int32_t> nearest_inside_;  // per cell: the nearest cell whose value >= threshold
    std::vector<float> outside_distance_;  // per cell: distance to the nearest cell below threshold
};

// Exact separable Euclidean distance transform with feature (Felzenszwalb-Huttenlocher
// lower envelope per axis, carrying the argmin): for every cell the squared distance to
// the nearest target cell and that cell's index (-1 / infinity when there is none).
void distance_transform(const std::vector<uint8_t>& target, const int n[3], const Vec3& spacing, int threads,
                        std::vector<double>& squared_distance, std::vector<int32_t>* feature);

}  // namespace tessera
